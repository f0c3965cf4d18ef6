"""`flexmb truck driver-sensitivity`: the highest passing lane-change speed
with the file's driver and with one driver setting changed at a time. The
study's speeds are those of `flexmb truck max-speed` (the same bisection)
on the file, and on a copy of the file whose driver section sets the value
(the override equals the file key); bad settings are errors before any
run. docs/validation.md, "Driver sensitivity"."""

import json
import subprocess

import pytest

RANGE = ["--low", "40", "--high", "50", "--tol", "2"]


@pytest.fixture
def work(truck_copy):
    return truck_copy


def max_speed(cli, path):
    out = subprocess.run([cli, "truck", "max-speed", str(path), *RANGE], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)["max_pass_speed_kmh"]


def with_driver_key(work, key, value):
    """A copy of truck.yaml whose driver section sets key: value (the
    example's line of that key replaced)."""
    lines = (work / "truck.yaml").read_text().splitlines(keepends=True)
    at = [k for k, line in enumerate(lines) if line.startswith(f"    {key}:")]
    assert len(at) == 1
    lines[at[0]] = f"    {key}: {value}\n"
    path = work / f"truck_{key}.yaml"
    path.write_text("".join(lines))
    return path


def test_study_equals_max_speed_runs(cli, work):
    out = work / "sens"
    run = subprocess.run([cli, "truck", "driver-sensitivity", str(work / "truck.yaml"), "--vary",
                          "reaction_delay=0,0.2", *RANGE, "-o", str(out)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert "the driver settings move the highest passing speed" in run.stdout
    s = json.loads((out / "summary.json").read_text())
    base = max_speed(cli, work / "truck.yaml")
    assert s["base_max_pass_speed_kmh"] == pytest.approx(base, abs=1e-3)
    rows = {r["value"]: r for r in s["settings"]}
    assert set(rows) == {0, 0.2}
    assert rows[0]["file_value"] == 0 and rows[0.2]["file_value"] == 0
    # the file's value again: the file's speed
    assert rows[0]["max_pass_speed_kmh"] == pytest.approx(base, abs=1e-3)
    # the override: as if the file said so
    delayed = max_speed(cli, with_driver_key(work, "reaction_delay", 0.2))
    assert rows[0.2]["max_pass_speed_kmh"] == pytest.approx(delayed, abs=1e-3)
    assert s["driver_spread_kmh"] == pytest.approx(
        max(base, delayed) - min(base, delayed), abs=1e-3)
    lines = (out / "sensitivity.csv").read_text().splitlines()
    assert lines[0] == "key,value,file_value,max_pass_speed_kmh,low_passed,change_kmh"
    assert len(lines) == 3


def test_bad_settings_are_errors_before_any_run(cli, work):
    truck = str(work / "truck.yaml")
    r = subprocess.run([cli, "truck", "driver-sensitivity", truck, "--vary", "reaction_time=0.1"],
                       capture_output=True, text=True)
    assert r.returncode != 0
    assert "unknown driver setting 'reaction_time'" in r.stderr and "reaction_delay" in r.stderr
    r = subprocess.run([cli, "truck", "driver-sensitivity", truck, "--vary", "neuromuscular_lag=0.1,-0.1"],
                       capture_output=True, text=True)
    assert r.returncode != 0 and "neuromuscular_lag = -0.1" in r.stderr, r.stderr
    r = subprocess.run([cli, "truck", "driver-sensitivity", truck, "--vary", "preview_time=0.3,x"],
                       capture_output=True, text=True)
    assert r.returncode != 0 and "'x' is not a number" in r.stderr
    # in the file: named by file and line
    bad = with_driver_key(work, "reaction_delay", -0.2)
    r = subprocess.run([cli, "check", str(bad)], capture_output=True, text=True)
    assert r.returncode != 0
    assert "truck_reaction_delay.yaml:" in r.stderr and "reaction_delay must be >= 0" in r.stderr, r.stderr


def test_python_api_equals_cli(cli, work):
    import flexmb
    out = work / "cli"
    subprocess.run([cli, "truck", "driver-sensitivity", str(work / "truck.yaml"), "--vary", "neuromuscular_lag=0.15",
                    *RANGE, "-o", str(out), "-q"], check=True, capture_output=True)
    ref = json.loads((out / "summary.json").read_text())
    py = flexmb.driver_sensitivity(work / "truck.yaml", {"neuromuscular_lag": [0.15]}, low=40, high=50, tol=2)
    assert py["base_max_pass_speed_kmh"] == ref["base_max_pass_speed_kmh"]
    assert py["settings"] == ref["settings"]
    # one run with the driver changed from Python, and the same from the file
    a = flexmb.lane_change(work / "truck.yaml", speed_kmh=45, frame="rigid", stop_distance=30.0,
                           driver={"neuromuscular_lag": 0.15})
    b = flexmb.lane_change(with_driver_key(work, "neuromuscular_lag", 0.15), speed_kmh=45, frame="rigid",
                           stop_distance=30.0)
    for key in ("max_lateral_acceleration", "max_steering_wheel_deg", "min_corridor_margin", "steps"):
        assert a.metrics[key] == b.metrics[key]
    with pytest.raises(Exception, match="unknown driver setting"):
        flexmb.lane_change(work / "truck.yaml", speed_kmh=45, driver={"delay": 0.1})
