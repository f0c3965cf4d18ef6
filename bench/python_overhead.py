#!/usr/bin/python3
"""Overhead of the Python module (docs/PERFORMANCE.md, "Python module").

1. A model run through Python without callbacks against `flexmb run`: the
   integration wall time (initialization and time integration, as
   summary.json's integration_time_s) of the same model in the same
   process environment, alternating CLI and Python, best of REPEAT.
2. A Python callback every step (read the state, set one input) against
   the same run without callback: the extra wall time per step.

Usage: PYTHONPATH=BUILD/python /usr/bin/python3 bench/python_overhead.py BUILD/bin/flexmb [REPEAT]
"""
import json
import os
import subprocess
import sys
import tempfile
import time

import flexmb

HERE = os.path.dirname(os.path.abspath(__file__))
cli = sys.argv[1] if len(sys.argv) > 1 else "build/release/bin/flexmb"
repeat = int(sys.argv[2]) if len(sys.argv) > 2 else 5
model = os.path.join(HERE, "..", "examples", "bricard", "model.yaml")

tmp = tempfile.mkdtemp()
cli_times, py_times = [], []
for k in range(repeat):
    out = os.path.join(tmp, "cli%d" % k)
    subprocess.run([cli, "run", model, "-o", out, "-q"], check=True, stderr=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        cli_times.append(json.load(f)["integration_time_s"])
    sim = flexmb.load(model)
    sim.run(out_dir=os.path.join(tmp, "py%d" % k))
    py_times.append(sim.stats["integration_time_s"])
steps = sim.stats["steps"]
cli_best, py_best = min(cli_times), min(py_times)
pairs = sorted(p / c for p, c in zip(py_times, cli_times))
print(f"bricard, {steps} steps: CLI integration {cli_best * 1e3:.1f} ms, Python {py_best * 1e3:.1f} ms "
      f"(best of {repeat}), ratio Python/CLI of the bests {py_best / cli_best:.4f}, "
      f"median of the {repeat} pairs {pairs[len(pairs) // 2]:.4f}")

pendulum = {
    "name": "inverted_pendulum", "gravity": [0, -9.81, 0],
    "ground": {"markers": [{"name": "pivot"}]},
    "bodies": [{"name": "rod", "mass": 1.0, "inertia": [0.0834, 0.001, 0.0834], "position": [0, 0.5, 0],
                "markers": [{"name": "pin", "position": [0, -0.5, 0]}]}],
    "joints": [{"name": "pin", "type": "revolute", "i": "ground.pivot", "j": "rod.pin"}],
    "forces": [{"name": "motor", "type": "joint_motor", "joint": "pin", "function": {"input": "torque"}}],
    "sensors": [{"name": "angle", "type": "joint_coordinate", "joint": "pin"}],
    "solver": {"t_end": 10.0, "dt": 1.0e-3}, "output": {"interval": 0.01},
}


def timed(kind):
    sim = flexmb.from_dict(pendulum)
    sim.initialize()
    u = sim.input("torque")

    def control(s):
        u.value = -120.0 * s.q[6] - 8.0 * s.v[5]  # q[6] = sin(angle / 2), v[5] = w_z

    def control_by_name(s):
        s.set_input("torque", -120.0 * s.q[6] - 8.0 * s.v[5])

    callback = {"none": None, "empty": lambda s: None, "control": control, "by_name": control_by_name}[kind]
    t0 = time.perf_counter()
    sim.run(callback=callback, interval=0.0)
    return time.perf_counter() - t0, sim.stats["steps"]


times = {"none": [], "empty": [], "control": [], "by_name": []}
for _ in range(repeat):
    for kind in times:
        t, n = timed(kind)
        times[kind].append(t)
base = min(times["none"])
extra = {k: (min(v) - base) / n * 1e6 for k, v in times.items()}
print(f"inverted pendulum, {n} steps: no callback {base / n * 1e6:.2f} us/step; callback every step: "
      f"empty +{extra['empty']:.2f} us/step, read q and v and set one input (handle) +{extra['control']:.2f} "
      f"us/step, the same with set_input(name) +{extra['by_name']:.2f} us/step (best of {repeat})")
