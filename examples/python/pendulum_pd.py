#!/usr/bin/python3
"""An inverted pendulum built in Python (dicts with the keys of the model
file) and held upright by a PD controller written in Python that sets the
motor torque between steps (a closed loop at 100 Hz).

Usage: PYTHONPATH=build/release/python /usr/bin/python3 examples/python/pendulum_pd.py [OUT_DIR]
Writes OUT_DIR/pendulum_pd.png (angle and torque over time, with and
without the controller)."""
import math
import os
import sys

import flexmb
import flexmb.plot

out_dir = sys.argv[1] if len(sys.argv) > 1 else "out/python"
os.makedirs(out_dir, exist_ok=True)

tilt = 0.1  # initial angle from upright [rad]
model = {
    "name": "inverted_pendulum",
    "gravity": [0, -9.81, 0],
    "ground": {"markers": [{"name": "pivot"}]},
    "bodies": [{
        "name": "rod", "mass": 1.0, "inertia": [0.0834, 0.001, 0.0834],  # 1 m rod along its y axis
        "position": [-0.5 * math.sin(tilt), 0.5 * math.cos(tilt), 0],
        "orientation": {"rotation_vector": [0, 0, tilt]},
        "markers": [{"name": "pin", "position": [0, -0.5, 0]}],
    }],
    "joints": [{"name": "pin", "type": "revolute", "i": "ground.pivot", "j": "rod.pin"}],
    # the motor torque [N m] is an input set from Python
    "forces": [{"name": "motor", "type": "joint_motor", "joint": "pin", "function": {"input": "torque"}}],
    "sensors": [{"name": "angle", "type": "joint_coordinate", "joint": "pin"}],
    "solver": {"t_end": 3.0, "dt": 1.0e-3},
    "output": {"interval": 0.01},
}

runs = []
for label, kp, kd in [("PD controller", 60.0, 8.0), ("no controller", 0.0, 0.0)]:
    sim = flexmb.from_dict(model)
    print(label, sim.check())
    torque = sim.input("torque")
    log = {"time": [], "torque": []}
    while sim.t < 3.0 - 1e-9:
        angle = sim.joint_coordinates("pin")[0]   # [rad], 0 = upright
        rate = sim.body_v("rod")[5]               # [rad/s], w_z
        torque.value = -kp * angle - kd * rate    # [N m]
        log["time"].append(sim.t)
        log["torque"].append(torque.value)
        sim.step(0.01)
        if abs(angle) > 1.5:
            break
    res = sim.results()
    print(f"{label}: angle at t = {sim.t:.2f} s: {res['angle.value'][-1]:.2e} rad")
    runs.append((label, {"time": res.time, "angle.value": res["angle.value"], "torque_time": log["time"],
                         "torque": log["torque"]}))

plt = flexmb.plot._plt()
fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
flexmb.plot.time_history(ax1, runs, ["angle.value"])
ax1.set_ylabel("angle from upright [rad]")
ax1.legend(fontsize=7)
ax2.plot(runs[0][1]["torque_time"], runs[0][1]["torque"], label="PD controller")
ax2.set_ylabel("motor torque [N m]")
ax2.set_xlabel("time [s]")
ax2.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(out_dir, "pendulum_pd.png"), dpi=110)
print("plot:", os.path.join(out_dir, "pendulum_pd.png"))
