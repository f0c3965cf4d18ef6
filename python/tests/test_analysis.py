"""flexmb.statics, flexmb.modes and flexmb.linearize against closed forms and
against the files of the command line for the same model file (the same C++
functions: the numbers must be identical)."""

import json
import math
import subprocess

import numpy as np
import pytest

import flexmb

G = 9.81


def compound_pendulum(m=2.0, ic=0.05, d=0.6, yaw=0.2):
    """A body of mass m [kg], inertia ic [kg m^2] about its centre of mass,
    which is d [m] from a revolute pin (z axis), gravity -y, released yaw
    [rad] off the hanging position (the modes' static solve must find it).
    As in tests/validation/system_modes_cli_test.cc."""
    return {
        "name": "pendulum",
        "gravity": [0, -G, 0],
        "ground": {"markers": [{"name": "pin"}]},
        "bodies": [{
            "name": "arm", "mass": m, "inertia": [ic, ic, ic],
            "position": [d * math.sin(yaw), -d * math.cos(yaw), 0],
            "orientation": {"roll_pitch_yaw": [0, 0, yaw]},
            "markers": [{"name": "pin", "position": [0, d, 0]}],
        }],
        "joints": [{"name": "pin", "type": "revolute", "i": "ground.pin", "j": "arm.pin"}],
        "sensors": [{"name": "angle", "type": "joint_coordinate", "joint": "pin"}],
    }


# the quarter car of tests/validation/statespace_cli_test.cc: ms 400 kg, mu
# 40 kg on vertical guides, suspension 20 kN/m and 1.5 kN s/m, tire 200 kN/m,
# a vertical point force `push` on the body
QUARTER_CAR = """name: quarter_car
gravity: [0, 0, -9.81]
ground:
  markers:
    - {name: road}
bodies:
  - {name: body, mass: 400, inertia: [50, 50, 50], position: [0, 0, 1.0], markers: [{name: c}]}
  - {name: wheel, mass: 40, inertia: [1, 1, 1], position: [0, 0, 0.4], markers: [{name: c}]}
joints:
  - {name: body_guide, type: prismatic, i: ground.road, j: body.c}
  - {name: wheel_guide, type: prismatic, i: ground.road, j: wheel.c}
forces:
  - {name: suspension, type: spring_damper, i: wheel.c, j: body.c, stiffness: 20000, damping: 1500}
  - {name: tire, type: spring_damper, i: ground.road, j: wheel.c, stiffness: 200000}
  - {name: push, type: point_force, marker: body.c, force: [0, 0, 0]}
sensors:
  - {name: body, type: body_position, body: body}
  - {name: wheel, type: body_position, body: wheel}
"""


def hanging_mass(m=3.0, k=1500.0, free_length=0.5):
    """A mass m [kg] on a vertical guide hanging from a spring of rate k
    [N/m] and free length [m] anchored at the origin, gravity -z; starts with
    the spring at its free length."""
    return {
        "name": "hanging_mass",
        "gravity": [0, 0, -G],
        "ground": {"markers": [{"name": "anchor"}]},
        "bodies": [{"name": "mass", "mass": m, "inertia": [0.01, 0.01, 0.01],
                    "position": [0, 0, -free_length], "markers": [{"name": "c"}]}],
        "joints": [{"name": "guide", "type": "prismatic", "i": "ground.anchor", "j": "mass.c"}],
        "forces": [{"name": "spring", "type": "spring_damper", "i": "ground.anchor", "j": "mass.c",
                    "stiffness": k, "free_length": free_length}],
        "sensors": [{"name": "pos", "type": "body_position", "body": "mass"}],
    }


def write_model(tmp_path, model):
    """The model (dict or YAML text) as tmp_path/model.yaml (JSON is YAML)."""
    path = tmp_path / "model.yaml"
    path.write_text(model if isinstance(model, str) else json.dumps(model, indent=1))
    return str(path)


def test_pendulum_modes_closed_form():
    # reference: small oscillations of a compound pendulum, w^2 = g / L with
    # the equivalent length L = (I_c + m d^2) / (m d) (e.g. Meriam & Kraige,
    # Engineering Mechanics: Dynamics, compound pendulum), 1e-8 relative
    m, ic, d = 2.0, 0.05, 0.6
    res = flexmb.modes(compound_pendulum(m, ic, d))
    length = (ic + m * d * d) / (m * d)
    f = math.sqrt(G / length) / (2 * math.pi)
    assert res.dof == 1 and res.rigid_modes == 0 and len(res) == 1
    assert res.kinds == ["oscillatory"]
    assert res.frequencies_hz[0] / f - 1 == pytest.approx(0, abs=1e-8)
    assert res.damping_ratios[0] == pytest.approx(0, abs=1e-12)
    assert res.eigenvalues[0].imag == pytest.approx(2 * math.pi * f, rel=1e-8)
    # one shape column per mode over the body's six velocity coordinates:
    # the rotation about z (coordinate 5) with the centre moving along x
    assert res.shapes.shape == (6, 1) and len(res.coordinates) == 6
    assert res.coordinates[5] == "body 'arm' (velocity coordinate 5)"
    assert abs(res.shapes[5, 0]) == pytest.approx(1.0, abs=1e-12)
    assert abs(res.shapes[0, 0] / res.shapes[5, 0]) == pytest.approx(d, rel=1e-8)
    assert res.summary["status"] == "ok" and res.summary["analysis"] == "modes"


def test_modes_equal_cli_files(cli, tmp_path):
    # the same model file through `flexmb modes` and flexmb.modes: the
    # Python arrays are the numbers of modes.csv / modes.json, and the files
    # Python writes are byte for byte those of the CLI
    model = write_model(tmp_path, QUARTER_CAR)
    subprocess.run([cli, "modes", model, "--out", str(tmp_path / "cli"), "--quiet", "--count", "4"], check=True)
    res = flexmb.modes(model, count=4, out_dir=tmp_path / "py")
    for name in ("modes.csv", "modes.json"):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()
    assert (tmp_path / "py" / "mode_1" / "anim.pvd").exists()
    lines = (tmp_path / "cli" / "modes.csv").read_text().splitlines()
    assert len(lines) - 1 == len(res) == 2
    for k, line in enumerate(lines[1:]):
        cols = line.split(",")
        assert cols[1] == res.kinds[k]
        assert float(cols[2]) == float("%.15g" % res.frequencies_hz[k])
        assert float(cols[4]) == float("%.15g" % res.damping_ratios[k])
    js = json.loads((tmp_path / "cli" / "modes.json").read_text())
    assert js["coordinates"] == res.coordinates
    for k, mode in enumerate(js["modes"]):
        np.testing.assert_array_equal(np.array(mode["shape"]), res.shapes[:, k])
        np.testing.assert_array_equal(np.array(mode["shape_imag"]), res.shapes_imag[:, k])
    # no out_dir: nothing written, the same numbers
    again = flexmb.modes(model, count=4)
    np.testing.assert_array_equal(again.frequencies_hz, res.frequencies_hz)


def test_linearize_equal_cli_mtx(cli, tmp_path):
    model = write_model(tmp_path, QUARTER_CAR)
    subprocess.run([cli, "linearize", model, "--out", str(tmp_path / "cli"), "--inputs", "push,suspension",
                    "--outputs", "body", "--quiet"], check=True)
    ss = flexmb.linearize(model, inputs=["push", "suspension"], outputs=["body"], out_dir=tmp_path / "py")
    for name in "ABCD":
        np.testing.assert_array_equal(flexmb.read_mtx(tmp_path / "cli" / f"{name}.mtx"), getattr(ss, name))
        assert (tmp_path / "py" / f"{name}.mtx").read_bytes() == (tmp_path / "cli" / f"{name}.mtx").read_bytes()
    js = json.loads((tmp_path / "cli" / "statespace.json").read_text())
    assert js["states"] == ss.states and js["inputs"] == ss.inputs and js["outputs"] == ss.outputs
    np.testing.assert_array_equal(np.array(js["output_values"]), ss.output_values)
    # shapes: 2 free coordinates (two heights) -> 4 states; push gives 3
    # inputs, the spring 1; the body sensor 6 outputs
    assert ss.A.shape == (4, 4) and ss.B.shape == (4, 4) and ss.C.shape == (6, 4) and ss.D.shape == (6, 4)
    assert ss.inputs == ["push.fx", "push.fy", "push.fz", "suspension.tension"]
    # closed form: the body's vertical acceleration per newton of push.fz
    # is 1 / ms; the eigenvalues of A are those of the modes
    vz = ss.states.index("v body 'body' (velocity coordinate 2)")
    assert ss.B[vz, 2] == pytest.approx(1 / 400.0, rel=1e-12)
    ev = np.sort_complex(np.linalg.eigvals(ss.A))
    md = flexmb.modes(model)
    expected = np.sort_complex(np.concatenate([md.eigenvalues, np.conj(md.eigenvalues)]))
    np.testing.assert_allclose(ev, expected, rtol=1e-8)


def test_linearize_motor_input_static_gain():
    # a joint motor as input: its torque [N m] on the pendulum's pin. The
    # static gain from torque to angle, D - C A^-1 B, is the compliance of
    # the hanging pendulum, 1 / (m g d) (moment balance m g d sin(th) = tau
    # at th = 0); C is a central difference (step 1e-6), hence 1e-7
    m, ic, d = 2.0, 0.05, 0.6
    model = compound_pendulum(m, ic, d)
    model["forces"] = [{"name": "motor", "type": "joint_motor", "joint": "pin", "function": 0.0}]
    ss = flexmb.linearize(model, inputs=["motor"], outputs=["angle"])
    assert ss.inputs == ["motor.torque"] and ss.outputs == ["angle.value", "angle.rate"]
    gain = ss.D - ss.C @ np.linalg.solve(ss.A, ss.B)
    assert gain[0, 0] == pytest.approx(1.0 / (m * G * d), rel=1e-7)
    assert gain[1, 0] == pytest.approx(0.0, abs=1e-9)  # no rate at rest


def base_excited(m=10.0, k=4000.0, c=40.0):
    """A mass m [kg] on a guide linked by a spring-damper (k [N/m], c
    [N s/m]) to a base on a driven guide (driver `base_drive`, held at 0);
    no gravity. As in tests/validation/statespace_driver_test.cc."""
    return {
        "name": "base_excited",
        "gravity": [0, 0, 0],
        "ground": {"markers": [{"name": "o"}]},
        "bodies": [{"name": "base", "mass": 5, "inertia": [1, 1, 1], "position": [0, 0, 0], "markers": [{"name": "c"}]},
                   {"name": "mass", "mass": m, "inertia": [1, 1, 1], "position": [0, 0, 1], "markers": [{"name": "c"}]}],
        "joints": [{"name": "base_guide", "type": "prismatic", "i": "ground.o", "j": "base.c"},
                   {"name": "mass_guide", "type": "prismatic", "i": "ground.o", "j": "mass.c"}],
        "drivers": [{"name": "base_drive", "joint": "base_guide", "function": 0.0}],
        "forces": [{"name": "link", "type": "spring_damper", "i": "base.c", "j": "mass.c", "stiffness": k, "damping": c}],
        "sensors": [{"name": "mass", "type": "body_position", "body": "mass"}],
    }


def test_linearize_driver_input_closed_form():
    # a motion driver as input: its acceleration; its position and velocity
    # are appended to the state. Closed form: z'' = -k/m (z - b) - c/m (z' - b'),
    # b'' = u; and the static gain of a base displacement on the mass is 1
    m, k, c = 10.0, 4000.0, 40.0
    ss = flexmb.linearize(base_excited(m, k, c), inputs=["base_drive"], outputs=["mass"])
    assert ss.inputs == ["base_drive.acceleration"]
    assert ss.states[2:] == ["driver base_drive.position", "driver base_drive.velocity"]
    a_ref = np.array([[0, 1, 0, 0], [-k / m, -c / m, k / m, c / m], [0, 0, 0, 1], [0, 0, 0, 0]])
    assert np.allclose(ss.A, a_ref, rtol=0, atol=1e-9 * k / m)
    assert np.allclose(ss.B[:, 0], [0, 0, 0, 1], rtol=0, atol=1e-12)
    # with the base held at df: the mass follows, z = df (output mass.z)
    z = ss.outputs.index("mass.z")
    x = np.linalg.solve(ss.A[:2, :2], -ss.A[:2, 2])  # steady state at df = 1, df' = 0
    assert ss.C[z, :2] @ x + ss.C[z, 2] == pytest.approx(1.0, rel=1e-6)


def test_truck_modes_named_as_the_cli(cli, tmp_path):
    # the standing truck of a lane-change file, rigid frame: the names and
    # frequencies of flexmb.modes equal the CLI's modes.csv
    import os
    path = os.path.join(os.environ["FLEXMB_SOURCE_DIR"], "examples", "truck_lane_change", "truck.yaml")
    subprocess.run([cli, "modes", path, "--frame", "rigid", "--out", str(tmp_path), "--no-animation", "-n", "20",
                    "--quiet"], check=True)
    rows = (tmp_path / "modes.csv").read_text().splitlines()
    assert rows[0].endswith(",name,energy_share")
    r = flexmb.modes(path, frame="rigid", count=20, animation=False)
    assert len(r.names) == len(rows) - 1
    for k, row in enumerate(rows[1:]):
        cells = row.split(",")
        assert r.names[k] == cells[7]
        assert r.frequencies_hz[k] == pytest.approx(float(cells[2]), rel=1e-13)
    assert "bounce" in r.names and "front axle hop" in r.names
    assert flexmb.modes(compound_pendulum(), count=1).names == []


def test_linearize_at_time_equal_cli(cli, tmp_path):
    # --at time: the state after a dynamic run to 0.05 s (the quarter car
    # settles from its unloaded springs), the same through both
    model = write_model(tmp_path, QUARTER_CAR)
    subprocess.run([cli, "linearize", model, "--out", str(tmp_path / "cli"), "--inputs", "push", "--at", "time",
                    "--time", "0.05", "--quiet"], check=True)
    ss = flexmb.linearize(model, inputs="push", at="time", time=0.05)
    assert ss.time == pytest.approx(0.05, abs=1e-12)
    for name in "ABCD":
        np.testing.assert_array_equal(flexmb.read_mtx(tmp_path / "cli" / f"{name}.mtx"), getattr(ss, name))
    assert any("not an equilibrium" in w for w in ss.warnings)


def test_statics_hanging_mass_closed_form(cli, tmp_path):
    # reference: Hooke's law, the spring stretches by m g / k beyond its free
    # length
    m, k, free = 3.0, 1500.0, 0.5
    res = flexmb.statics(hanging_mass(m, k, free))
    z = -free - m * G / k
    assert res.body_q("mass")[2] == pytest.approx(z, abs=1e-10)
    assert res.sensors["pos.z"] == pytest.approx(z, abs=1e-10)
    assert res.load_factor == 1.0 and res.residual < 1e-6 and res.iterations >= 1
    assert res.table["load_factor"][-1] == 1.0 and len(res.table["load_factor"]) == res.load_steps
    assert res.summary["status"] == "ok"
    # through a model file, the CLI writes the same results.csv
    model = write_model(tmp_path, hanging_mass(m, k, free))
    subprocess.run([cli, "statics", model, "--out", str(tmp_path / "cli"), "--quiet"], check=True)
    res = flexmb.statics(model, out_dir=tmp_path / "py")
    assert (tmp_path / "py" / "results.csv").read_bytes() == (tmp_path / "cli" / "results.csv").read_bytes()
    lines = (tmp_path / "cli" / "results.csv").read_text().splitlines()
    assert lines[0].split(",") == res.columns
    assert float(lines[-1].split(",")[res.columns.index("pos.z")]) == float("%.15g" % res.sensors["pos.z"])


def test_statics_of_a_manoeuvre(cli, tmp_path):
    # reference: Hooke's law with the spring rate the manoeuvre sets; the
    # CLI's --manoeuvre and Python's manoeuvre= write the same results
    m, k, free = 3.0, 1500.0, 0.5
    model = hanging_mass(m, k, free)
    model["manoeuvres"] = {"stiff": {"forces": {"spring": {"stiffness": 2 * k}}}}
    path = write_model(tmp_path, model)
    plain = flexmb.statics(path)
    stiff = flexmb.statics(path, out_dir=tmp_path / "py", manoeuvre="stiff")
    assert plain.sensors["pos.z"] == pytest.approx(-free - m * G / k, abs=1e-10)
    assert stiff.sensors["pos.z"] == pytest.approx(-free - m * G / (2 * k), abs=1e-10)
    assert stiff.summary["manoeuvre"] == "stiff"
    subprocess.run([cli, "statics", path, "--out", str(tmp_path / "cli"), "--manoeuvre", "stiff", "--quiet"],
                   check=True)
    assert (tmp_path / "py" / "results.csv").read_bytes() == (tmp_path / "cli" / "results.csv").read_bytes()
    with pytest.raises(flexmb.InputError, match="no manoeuvre named 'soft'"):
        flexmb.statics(path, manoeuvre="soft")


def test_bad_inputs_raise_with_the_message(tmp_path):
    model = write_model(tmp_path, QUARTER_CAR)
    with pytest.raises(flexmb.InputError, match="no force element named 'nosuch'"):
        flexmb.linearize(model, inputs=["nosuch"])
    with pytest.raises(flexmb.InputError, match="no force element named 'body_guide'"):
        flexmb.linearize(model, inputs=["body_guide"])
    with pytest.raises(flexmb.InputError, match="no sensor named 'nosuch'"):
        flexmb.linearize(model, inputs=["push"], outputs=["nosuch"])
    with pytest.raises(flexmb.InputError, match="--at must be"):
        flexmb.modes(model, at="sometime")
    # a free body under gravity has no equilibrium: the body is named
    free = hanging_mass()
    free["forces"] = []
    with pytest.raises(flexmb.NumericalError, match="body 'mass'"):
        flexmb.statics(free)


def test_modes_and_linearize_of_a_simulation_at_its_current_state():
    # a Simulation as the model: linearized about its state now. The
    # pendulum released off the vertical, initialized: the same numbers as
    # at="initial" from its dict (the same consistent state); inverted and at
    # rest on its motor's input (zero torque), the upright is an unstable
    # equilibrium: A's eigenvalues +-sqrt(m g d / (I_c + m d^2)) (linearized
    # m g d sin(th) about th = 0), and the static gain from torque to angle,
    # D - C A^-1 B, of magnitude 1 / (m g d) (C by central differences: 1e-7)
    m, ic, d = 2.0, 0.05, 0.6
    model = compound_pendulum(m, ic, d)
    sim = flexmb.from_dict(model)
    sim.initialize()
    cur = flexmb.modes(sim)
    ref = flexmb.modes(model, at="initial")
    np.testing.assert_allclose(cur.frequencies_hz, ref.frequencies_hz, rtol=1e-12)
    assert any("not an equilibrium" in w for w in cur.warnings)

    up = compound_pendulum(m, ic, d, yaw=0.0)
    up["gravity"] = [0, G, 0]  # gravity away from the pin: inverted, joint angle 0 (no +-pi wrap)
    up["forces"] = [{"name": "motor", "type": "joint_motor", "joint": "pin", "function": {"input": "torque"}}]
    sim = flexmb.from_dict(up)
    sim.step(1e-3, 5)  # at rest on the upright: it stays there
    ss = flexmb.linearize(sim, inputs=["motor"], outputs=["angle"])
    assert ss.time == pytest.approx(5e-3, abs=1e-12)
    lam = np.sort(np.linalg.eigvals(ss.A).real)
    rate = math.sqrt(m * G * d / (ic + m * d * d))
    assert lam[0] == pytest.approx(-rate, rel=1e-7) and lam[-1] == pytest.approx(rate, rel=1e-7)
    gain = ss.D - ss.C @ np.linalg.solve(ss.A, ss.B)
    assert abs(gain[0, 0]) == pytest.approx(1.0 / (m * G * d), rel=1e-7)
    with pytest.raises(flexmb.InputError, match="current state"):
        flexmb.modes(sim, at="statics")
