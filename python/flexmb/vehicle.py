"""The truck lane change (`flexmb run truck.yaml`), the max-speed search
(`flexmb truck max-speed`) and the handling tests (`flexmb truck handling`)
from Python."""

import dataclasses
import json
import os

from . import _core
from .results import read_results


@dataclasses.dataclass
class LaneChangeResult:
    """Outcome and metrics of one lane change (keys of summary.json; speeds
    in km/h, times in s, lengths in m, angles in deg, accelerations in m/s^2,
    loads in N, stresses in Pa) and the results (Results, or None when no
    output directory was written)."""
    metrics: dict
    results: object = None

    @property
    def passed(self):
        """Completed without leaving the corridor or lifting a wheel."""
        return bool(self.metrics.get("passed"))

    @property
    def completed(self):
        return bool(self.metrics.get("completed"))

    def __getattr__(self, name):
        metrics = self.__dict__.get("metrics", {})
        if name in metrics:
            return metrics[name]
        raise AttributeError(name)


def lane_change(file, speed_kmh=None, frame=None, dt=None, out_dir=None, stop_on_failure=False,
                stop_distance=None, run_up_time=None, driver=None):
    """Runs the lane-change test of `file` at speed_kmh [km/h] with a 'rigid'
    or 'elastic' frame (None: as the file says). With out_dir, results.csv
    and summary.json are written there and read back into .results.
    `driver`: {key: value} of the file's driver section's numeric keys in
    its units (e.g. {"reaction_delay": 0.15}), set after the file is read."""
    text = _core.lane_change(os.fspath(file), speed_kmh, frame, dt, os.fspath(out_dir) if out_dir else "",
                             stop_on_failure, stop_distance, run_up_time, dict(driver or {}))
    metrics = json.loads(text)
    results = read_results(out_dir) if out_dir and os.path.exists(os.path.join(out_dir, "results.csv")) else None
    return LaneChangeResult(metrics, results)


def truck_handling(file, test="step-steer", speed_kmh=None, steer_deg=None, frame=None, dt=None, out_dir=None,
                   **options):
    """Runs the handling test `test` (step-steer, constant-steer, braking,
    brake-in-turn, sine-steer) of the truck of lane-change file `file`;
    `options` are the other settings of `flexmb truck handling` by their
    HandlingOptions names (target_ay, radius, rise_time, hold_time,
    frequency, periods, speed_rate_kmh_s, max_ay, max_speed_kmh,
    brake_torque, decel, brake_rise_time). Returns a
    LaneChangeResult-like result: .metrics (summary.json), .results (with
    out_dir), .completed."""
    text = _core.truck_handling(os.fspath(file), test, os.fspath(out_dir) if out_dir else "", speed_kmh, steer_deg,
                                frame, dt, options)
    metrics = json.loads(text)
    metrics["completed"] = metrics.get("status") == "ok"
    results = read_results(out_dir) if out_dir and os.path.exists(os.path.join(out_dir, "results.csv")) else None
    return LaneChangeResult(metrics, results)


def max_pass_speed(file, low, high, tol=0.5, frame=None, driver=None):
    """Highest entry speed [km/h] in [low, high] at which the test is passed
    (bisection to tol km/h). Returns None if even `low` fails. `driver` as
    in lane_change."""
    v, low_ok = _core.max_pass_speed(os.fspath(file), low, high, tol, frame, dict(driver or {}))
    return v if low_ok else None


def driver_sensitivity(file, vary, low=20.0, high=90.0, tol=1.0, frame=None, out_dir=None):
    """`flexmb truck driver-sensitivity`: the highest passing speed with the
    file's driver and with each setting of `vary` ({key: [values]}, the
    driver section's numeric keys in its units) changed one at a time.
    Returns summary.json as a dict (base_max_pass_speed_kmh, settings,
    driver_spread_kmh, ...); with out_dir also writes sensitivity.csv."""
    text = _core.driver_sensitivity(os.fspath(file), {k: [float(x) for x in v] for k, v in vary.items()}, low, high,
                                    tol, frame, os.fspath(out_dir) if out_dir else "")
    return json.loads(text)
