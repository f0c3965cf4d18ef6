"""A truck inside an ordinary model file (issue 18: "a vehicle can be used
inside a normal model file, e.g. a crane on a truck"): the truck of
examples/truck_lane_change/truck.yaml as a `type: truck` body entry, parked
(brake torque), a mast of 800 kg on its frame on a driven slewing joint.
References: the weight (the tire loads carry the truck's, measured without
the mast, plus the mast's), the lever rule for the mast's share of the axle
loads, the side the truck leans to. docs/validation.md, "A truck in a model
file"."""

import csv
import subprocess

import pytest

G = 9.81

MODEL = """name: crane_on_truck
bodies:
  - name: truck
    type: truck
    file: truck.yaml
    brake_torque: 20000
    markers:
      - {{body: frame, name: slew_ring, position: [-1.5, 0, 1.07]}}
{mast}
sensors:
  - {{name: fl, type: force_element, force: wheel_fl_tire}}
  - {{name: fr, type: force_element, force: wheel_fr_tire}}
  - {{name: rl, type: force_element, force: wheel_rl_tire}}
  - {{name: rr, type: force_element, force: wheel_rr_tire}}
  - {{name: ring, type: marker_orientation, marker: frame.slew_ring}}
solver:
  analysis: {analysis}
  t_end: 2.0
  dt: 0.004
  statics_hold: always         # a vehicle at rest: held by its tires' slip damping
  statics_residual_tol: 1.0e-6 # the contact patches' weight on the tilted wheels leaves 0.01 N
"""

MAST = """  - name: mast
    type: rigid
    mass: 800
    inertia: [400, 400, 50]
    position: [-1.5, 0, 1.07]
    center_of_mass: [0, 1.5, 1.0]
    markers:
      - {name: ring, position: [0, 0, 0]}
joints:
  - {name: slew, type: revolute, i: frame.slew_ring, j: mast.ring}
drivers:
  - {name: slew_drive, type: coordinate, joint: slew, function: {expression: "0.3*t"}}"""


@pytest.fixture
def work(truck_copy):
    return truck_copy


def run(cli, work, name, mast=True, analysis="statics", extra=()):
    path = work / f"{name}.yaml"
    path.write_text(MODEL.format(mast=MAST if mast else "", analysis=analysis))
    r = subprocess.run([cli, "run", str(path), "--out", str(work / name), *extra], capture_output=True, text=True)
    rows = []
    if r.returncode == 0:
        with open(work / name / "results.csv") as f:
            rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    return r, rows


def test_crane_on_a_parked_truck_statics(cli, work):
    r, rows = run(cli, work, "with_mast")
    assert r.returncode == 0, r.stderr
    r0, rows0 = run(cli, work, "truck_only", mast=False)
    assert r0.returncode == 0, r0.stderr
    fz = {k: rows[-1][k + ".fz"] for k in ("fl", "fr", "rl", "rr")}
    fz0 = {k: rows0[-1][k + ".fz"] for k in ("fl", "fr", "rl", "rr")}
    mast = 800 * G
    # the tires carry the truck and the mast
    assert sum(fz.values()) == pytest.approx(sum(fz0.values()) + mast, rel=1e-6)
    # the mast's share by the lever rule (its centre of mass at x = -1.5 m of
    # the 4.2 m wheelbase); the roll and pitch shift the centres of mass by
    # their heights times the angles (1 deg at 2 m: 35 mm), 3 % of the mast
    front = fz["fl"] + fz["fr"] - fz0["fl"] - fz0["fr"]
    assert front == pytest.approx(mast * (4.2 - 1.5) / 4.2, abs=0.03 * mast)
    # the mast stands out to the left (+y): the left tires carry more, the truck leans left
    assert fz["fl"] > fz["fr"] and fz["rl"] > fz["rr"]
    assert rows[-1]["ring.roll"] < -0.005 and rows0[-1]["ring.roll"] == pytest.approx(0.0, abs=1e-3)


def test_slewing_on_the_parked_truck(cli, work):
    r, rows = run(cli, work, "slewing", analysis="statics_then_dynamics")
    assert r.returncode == 0, r.stderr
    assert rows[-1]["time"] == pytest.approx(2.0)
    # 0.6 rad of slewing from the left (+y) towards the rear: the left lean eases
    assert abs(rows[-1]["ring.roll"]) < abs(rows[0]["ring.roll"])
    assert rows[0]["ring.roll"] < -0.005


def test_bad_truck_entries_are_named(cli, work):
    path = work / "bad.yaml"
    text = MODEL.format(mast="", analysis="statics")
    path.write_text(text.replace("    file: truck.yaml\n", "    file: truck.yaml\n    frame: elastic\n"))
    r = subprocess.run([cli, "check", str(path)], capture_output=True, text=True)
    assert r.returncode != 0 and "bad.yaml:" in r.stderr and "rigid frame" in r.stderr, r.stderr
    (work / "not_a_truck.yaml").write_text("vehicle: {}\n")
    path.write_text(text.replace("file: truck.yaml", "file: not_a_truck.yaml"))
    r = subprocess.run([cli, "check", str(path)], capture_output=True, text=True)
    assert r.returncode != 0 and "not_a_truck.yaml" in r.stderr and "'truck' map" in r.stderr, r.stderr
    path.write_text(text.replace("{body: frame, name: slew_ring", "{body: chassis, name: slew_ring"))
    r = subprocess.run([cli, "check", str(path)], capture_output=True, text=True)
    assert r.returncode != 0 and "no body named 'chassis'" in r.stderr, r.stderr
