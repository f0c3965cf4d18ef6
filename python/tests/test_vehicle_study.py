"""The truck lane change from Python against `flexmb run truck.yaml`, and a
parameter study in processes."""

import json
import os
import subprocess

import pytest

import flexmb


@pytest.fixture
def truck(source_dir):
    return os.path.join(source_dir, "examples", "truck_lane_change", "truck.yaml")


def test_lane_change_matches_cli(cli, truck, tmp_path):
    r = flexmb.lane_change(truck, speed_kmh=45, frame="rigid", out_dir=tmp_path / "py")
    subprocess.run([cli, "run", truck, "-o", str(tmp_path / "cli"), "--speed", "45", "--frame", "rigid", "-q"],
                   check=True, capture_output=True)
    assert (tmp_path / "py" / "results.csv").read_bytes() == (tmp_path / "cli" / "results.csv").read_bytes()
    ref = json.loads((tmp_path / "cli" / "summary.json").read_text())
    assert r.completed and r.passed == ref["passed"]
    for key in ("max_lateral_acceleration", "max_roll_deg", "min_corridor_margin", "steps"):
        assert r.metrics[key] == ref[key]
    assert r.max_roll_deg == ref["max_roll_deg"]  # metrics as attributes
    assert r.results["time"][-1] == pytest.approx(r.metrics["t_end"])
    # load-transfer ratios: from the tire loads of the same rows (6 digits)
    c = r.results
    for axle, left, right in (("front", "fz_fl_kN", "fz_fr_kN"), ("rear", "fz_rl_kN", "fz_rr_kN")):
        ltr = (c[left] - c[right]) / (c[left] + c[right])
        assert abs(c["ltr_" + axle] - ltr).max() < 1e-5
        monitored = c["x"] >= 0.0
        assert r.metrics["max_ltr_" + axle] == pytest.approx(abs(c["ltr_" + axle][monitored]).max(), abs=2e-2)
    assert r.metrics["rollover_margin"] == pytest.approx(1 - max(r.metrics["max_ltr_front"], r.metrics["max_ltr_rear"]))


def short_lane_change(variant):
    r = flexmb.lane_change(variant["file"], speed_kmh=variant["speed_kmh"], frame="rigid", stop_distance=30.0)
    return {"completed": r.completed, "max_lateral_acceleration": r.max_lateral_acceleration}


def test_study_in_processes_equals_serial(truck):
    variants = [{"file": truck, "speed_kmh": v} for v in (35.0, 50.0)]
    parallel = flexmb.run_study(short_lane_change, variants, max_workers=2)
    serial = flexmb.run_study(short_lane_change, variants, executor="serial")
    assert parallel == serial
    assert parallel.column("completed") == [True, True]
    a = parallel.column("max_lateral_acceleration")
    assert 0 < a[0] < a[1]  # same course, faster: more lateral acceleration
    bad = flexmb.run_study(short_lane_change, [{"file": "nope.yaml", "speed_kmh": 40.0}], executor="serial")
    assert "nope.yaml" in bad[0]["error"]
