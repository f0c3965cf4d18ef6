"""The Python API against the command line and against closed-form facts:
bit-identical results, a closed loop through an input, errors, numpy views."""

import gc
import os
import subprocess

import numpy as np
import pytest

import flexmb


def pendulum(source_dir):
    return os.path.join(source_dir, "examples", "pendulum_a01", "model.yaml")


def test_results_csv_bit_identical_to_cli(cli, source_dir, tmp_path):
    # reference: `flexmb run` of the A01 pendulum to 20 s (rows every 0.5 s)
    model = pendulum(source_dir)
    subprocess.run([cli, "run", model, "-o", str(tmp_path / "cli"), "--t-end", "20", "-q"], check=True)
    sim = flexmb.load(model)
    sim.run(20.0, out_dir=str(tmp_path / "py"))
    cli_csv = (tmp_path / "cli" / "results.csv").read_bytes()
    assert (tmp_path / "py" / "results.csv").read_bytes() == cli_csv
    # the rows in memory print as the CSV's text
    res = sim.results()
    lines = cli_csv.decode().splitlines()
    assert lines[0].split(",") == list(res.keys())
    assert len(lines) - 1 == len(res.time) == 41
    for r, line in enumerate(lines[1:]):
        assert ",".join("%.15g" % res[k][r] for k in res.keys()) == line
    # run_file is `flexmb run`; read_results reads the same columns back
    back = flexmb.run_file(model, tmp_path / "rf", t_end=20.0)
    assert (tmp_path / "rf" / "results.csv").read_bytes() == cli_csv
    assert back.summary["status"] == "ok" and back.summary["rows"] == 41
    np.testing.assert_array_equal(back["angle.value"], np.array([float(l.split(",")[4]) for l in lines[1:]]))


def test_statics_then_dynamics_starts_as_the_cli(cli, source_dir, tmp_path):
    # a crane file with `analysis: statics_then_dynamics` (tests/data/crane):
    # `flexmb run` settles the static equilibrium before the first step, the
    # Python run must too (it started from the unsettled state before), so
    # both write the same results.csv
    model = os.path.join(source_dir, "tests", "data", "crane", "pedestal_crane.yaml")
    subprocess.run([cli, "run", model, "-o", str(tmp_path / "cli"), "--t-end", "1", "-q"], check=True)
    sim = flexmb.load(model)
    sim.run(1.0, out_dir=str(tmp_path / "py"))
    assert (tmp_path / "py" / "results.csv").read_bytes() == (tmp_path / "cli" / "results.csv").read_bytes()
    # the hook hangs at rest at t = 0: 2.4 m, where the template put it
    assert sim.results()["hook.z"][0] == pytest.approx(2.4, abs=1e-9)


def inverted_pendulum(torque):
    """A 1 kg rod of 1 m on a pin at its lower end (z axis), gravity -y,
    started 0.1 rad from upright; a joint motor applies `torque`."""
    return {
        "name": "inverted_pendulum",
        "gravity": [0, -9.81, 0],
        "ground": {"markers": [{"name": "pivot"}]},
        "bodies": [{
            "name": "rod", "mass": 1.0, "inertia": [0.0834, 0.001, 0.0834],
            "position": [-0.5 * np.sin(0.1), 0.5 * np.cos(0.1), 0],
            "orientation": {"rotation_vector": [0, 0, 0.1]},
            "markers": [{"name": "pin", "position": [0, -0.5, 0]}],
        }],
        "joints": [{"name": "pin", "type": "revolute", "i": "ground.pivot", "j": "rod.pin"}],
        "forces": [{"name": "motor", "type": "joint_motor", "joint": "pin", "function": torque}],
        "sensors": [{"name": "angle", "type": "joint_coordinate", "joint": "pin"}],
        "solver": {"t_end": 3.0, "dt": 1.0e-3},
        "output": {"interval": 0.01},
    }


def test_python_pd_controller_holds_inverted_pendulum():
    sim = flexmb.from_dict(inverted_pendulum({"input": "torque"}))
    assert sim.check()["dof"] == 1
    assert sim.input_names == ["torque"]
    u = sim.input("torque")
    assert sim.joint_coordinates("pin")[0] == pytest.approx(0.1, abs=1e-12)
    kp, kd = 60.0, 8.0  # m g l/2 = 4.9 N m/rad: kp well above, kd near critical
    for _ in range(300):
        angle = sim.joint_coordinates("pin")[0]
        rate = sim.body_v("rod")[5]  # w_z in body axes = joint rate (planar)
        u.value = -kp * angle - kd * rate
        sim.step(0.01)
    assert sim.t == pytest.approx(3.0)
    res = sim.results()
    assert abs(res["angle.value"][-1]) < 1e-3
    assert np.abs(res["angle.value"][-100:]).max() < 5e-3
    # without the controller it falls over (the loop is what holds it)
    free = flexmb.from_dict(inverted_pendulum({"input": "torque"}))
    free.step(0.01, n=100)
    assert abs(free.joint_coordinates("pin")[0]) > 1.0


def test_callback_closes_loop_in_run():
    sim = flexmb.from_dict(inverted_pendulum({"input": "torque", "initial": 0.0}))
    calls = []

    def control(s):
        calls.append(s.t)
        s.set_input("torque", -60.0 * s.joint_coordinates("pin")[0] - 8.0 * s.body_v("rod")[5])

    sim.run(2.0, callback=control, interval=0.01)
    assert len(calls) == 201
    assert abs(sim.joint_coordinates("pin")[0]) < 5e-3


def test_input_keeps_initial_value_in_cli(cli, tmp_path):
    # the CLI holds an input at `initial`: a constant torque -m g l/2 sin(0.1) balances the start
    import json
    model = inverted_pendulum({"input": "torque", "initial": -4.905 * np.sin(0.1)})
    path = tmp_path / "m.yaml"
    path.write_text(json.dumps(model))
    subprocess.run([cli, "run", str(path), "-o", str(tmp_path / "o"), "--t-end", "0.2", "-q"], check=True)
    res = flexmb.read_results(tmp_path / "o")
    assert res["angle.value"][-1] == pytest.approx(0.1, abs=1e-4)


BROKEN = """name: broken
bodies:
  - name: bob
    mass: 1.0
    inertia: [1, 1, 1]
    colour: red
"""


def test_broken_model_raises_cli_message(cli, tmp_path):
    path = tmp_path / "broken.yaml"
    path.write_text(BROKEN)
    proc = subprocess.run([cli, "check", str(path)], capture_output=True, text=True)
    assert proc.returncode == 2
    message = proc.stderr.strip()
    assert message.startswith("error: ")
    with pytest.raises(flexmb.InputError) as e:
        flexmb.load(path)
    assert "error: " + str(e.value) == message
    assert str(path) + ":6:" in str(e.value)
    assert isinstance(e.value, flexmb.Error) and isinstance(e.value, RuntimeError)
    # the same from text: the name given stands for the file
    with pytest.raises(flexmb.InputError) as e2:
        flexmb.from_yaml(BROKEN, name=str(path))
    assert str(e2.value) == str(e.value)
    # run_file raises the run command's message
    proc = subprocess.run([cli, "run", str(path), "-o", str(tmp_path / "o"), "-q"], capture_output=True, text=True)
    with pytest.raises(flexmb.InputError) as e3:
        flexmb.run_file(path, tmp_path / "o2")
    assert "error: " + str(e3.value) == proc.stderr.strip()


def test_numpy_views_shapes_no_copy_lifetime(source_dir):
    sim = flexmb.load(pendulum(source_dir))
    sim.initialize()
    q, v, lam = sim.q, sim.v, sim.lam
    assert q.shape == (7,) and v.shape == (6,) and q.dtype == np.float64 and v.dtype == np.float64
    assert lam.shape == (5,) and lam.dtype == np.float64
    assert not q.flags.owndata and q.flags.c_contiguous
    # views of the simulation's own vectors: no copy, and they follow the state
    assert np.shares_memory(q, sim.q)
    assert np.shares_memory(sim.body_q("bob"), q)
    assert np.shares_memory(sim.joint_lambda("pin"), lam)
    before = q.copy()
    sim.step(0.01)
    assert not np.array_equal(q, before)
    np.testing.assert_array_equal(q, sim.q)
    assert sim.modal_coordinates("bob").shape == (0,)
    p, R = sim.body_pose("bob")
    assert p.shape == (3,) and R.shape == (3, 3)
    np.testing.assert_allclose(R @ R.T, np.eye(3), atol=1e-12)
    # the views keep the simulation alive
    del sim
    gc.collect()
    assert np.isfinite(q).all() and np.linalg.norm(q[3:7]) == pytest.approx(1.0)
    with pytest.raises(KeyError):
        flexmb.load(pendulum(source_dir)).body_q("nobody")


def test_check_counts(source_dir):
    c = flexmb.load(os.path.join(source_dir, "examples", "four_bar_2", "model.yaml")).check()
    assert c["dof"] >= 1
    assert c["constraint_equations"] > c["redundant_constraints"] >= 0
    assert isinstance(c["warnings"], list)
    assert "degrees of freedom: %d" % c["dof"] in flexmb.check(os.path.join(source_dir, "examples", "four_bar_2",
                                                                              "model.yaml"))


def test_results_to_pandas_or_clear_error(source_dir):
    sim = flexmb.load(pendulum(source_dir))
    sim.run(1.0)
    res = sim.results()
    assert res.time.tolist() == [0.0, 0.5, 1.0]
    assert set(res.sensor("p1")) == {"x", "y", "z"}
    try:
        import pandas  # noqa: F401
    except ImportError:
        with pytest.raises(ImportError, match="pandas"):
            res.to_pandas()
    else:
        assert list(res.to_pandas().columns) == list(res.keys())[1:]


def test_gil_released_while_integrating(source_dir):
    # another Python thread runs while C++ integrates (it would stall if the GIL were held)
    import threading
    sim = flexmb.load(os.path.join(source_dir, "examples", "bricard", "model.yaml"))
    sim.initialize()
    worker = threading.Thread(target=sim.run, args=(2.0,))
    count = 0
    worker.start()
    while worker.is_alive():
        count += 1
    worker.join()
    assert sim.t == pytest.approx(2.0)
    assert count > 10000


def test_callback_exception_propagates():
    sim = flexmb.from_dict(inverted_pendulum({"input": "torque"}))

    def failing(s):
        if s.t > 0.05:
            raise ValueError("controller failed")

    with pytest.raises(ValueError, match="controller failed"):
        sim.run(1.0, callback=failing, interval=0.01)
    assert 0.05 < sim.t < 0.07
    sim.run(0.2)  # the simulation goes on from where it stopped
    assert sim.t == pytest.approx(0.2)


def test_inputs_drive_point_force_and_torque():
    # a free 2 kg body (inertia 0.5 kg m^2 about z), no gravity; force and torque inputs
    # set before the first step: v and w are a t exactly (constant acceleration)
    sim = flexmb.from_dict({
        "name": "free", "gravity": [0, 0, 0],
        "bodies": [{"name": "box", "mass": 2.0, "inertia": [0.5, 0.5, 0.5], "markers": [{"name": "c"}]}],
        "forces": [
            {"name": "push", "type": "point_force", "marker": "box.c", "force": [{"input": "fx"}, 0, 0]},
            {"name": "spin", "type": "point_torque", "marker": "box.c", "torque": [0, 0, {"input": "tz"}]},
        ],
        "solver": {"dt": 1.0e-3},
    })
    assert sorted(sim.input_names) == ["fx", "tz"]
    sim.set_input("fx", 4.0)
    sim.set_input("tz", 1.0)
    sim.step(0.5)
    v = sim.body_v("box")
    assert v[0] == pytest.approx(4.0 / 2.0 * 0.5, abs=1e-12)  # 1 m/s
    assert v[5] == pytest.approx(1.0 / 0.5 * 0.5, abs=1e-12)  # 1 rad/s
    # a step in the inputs: the integrator spreads the jump of the acceleration
    # over the next step (velocity error of order h |delta a|, h = 1 ms)
    sim.set_input("fx", -2.0)
    sim.set_input("tz", 0.0)
    sim.step(0.5)
    assert v[0] == pytest.approx(1.0 - 1.0 * 0.5, abs=1e-3 * 3.0)  # 0.5 m/s; delta a = 3 m/s^2
    assert v[5] == pytest.approx(1.0, abs=1e-3 * 2.0)  # delta alpha = 2 rad/s^2
    with pytest.raises(KeyError, match="no input named 'fy'"):
        sim.set_input("fy", 1.0)


def test_joint_reaction_of_hanging_rod():
    # a 1 kg rod hanging at rest from a pin: the pin carries its weight, m g upwards, no moment
    sim = flexmb.from_dict({
        "name": "hanging", "gravity": [0, -9.81, 0],
        "ground": {"markers": [{"name": "pivot"}]},
        "bodies": [{"name": "rod", "mass": 1.0, "inertia": [0.0834, 0.001, 0.0834], "position": [0, -0.5, 0],
                    "markers": [{"name": "pin", "position": [0, 0.5, 0]}]}],
        "joints": [{"name": "pin", "type": "revolute", "i": "ground.pivot", "j": "rod.pin"}],
        "solver": {"dt": 1.0e-3},
    })
    sim.step(0.1)
    np.testing.assert_allclose(sim.joint_reaction("pin", world=True), [0, 9.81, 0, 0, 0, 0], atol=1e-9)
    np.testing.assert_allclose(sim.joint_coordinates("pin"), [0.0], atol=1e-12)


def test_ctrl_c_interrupts_long_run(source_dir):
    import signal
    import threading
    sim = flexmb.load(pendulum(source_dir))  # 2000 s: minutes of integration
    timer = threading.Timer(0.3, lambda: signal.raise_signal(signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        sim.run()
    timer.join()
    assert 0 < sim.t < 2000


def test_manoeuvre_as_on_the_command_line(cli, source_dir, tmp_path):
    # a manoeuvre of the A01 pendulum that runs it 2 s instead of the file's
    # t_end: the CLI's --manoeuvre, flexmb.load and run_file agree
    text = open(pendulum(source_dir)).read() + "\nmanoeuvres:\n  short: {solver: {t_end: 2.0}}\n"
    model = tmp_path / "pendulum.yaml"
    model.write_text(text)
    subprocess.run([cli, "run", str(model), "-o", str(tmp_path / "cli"), "--manoeuvre", "short", "-q"], check=True)
    sim = flexmb.load(model, manoeuvre="short")
    assert sim.t_end == 2.0
    back = flexmb.run_file(model, tmp_path / "rf", manoeuvre="short")
    assert back.summary["manoeuvre"] == "short" and back.time[-1] == 2.0
    assert (tmp_path / "rf" / "results.csv").read_bytes() == (tmp_path / "cli" / "results.csv").read_bytes()
    with pytest.raises(flexmb.InputError, match="no manoeuvre named 'long'"):
        flexmb.load(model, manoeuvre="long")
