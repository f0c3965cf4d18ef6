"""Study files (docs/studies.md) without Dask: the errors of a study file,
the serial runs of the pendulum study against the closed-form period, a
failing run as a row, and the resumption of an interrupted study."""

import json
import math
import os
import re
import signal
import subprocess
import sys
import time

import pytest

import flexmb


def pendulum_study(tmp_path, source_dir, body, name="study.yaml"):
    """A study file in tmp_path on examples/studies/pendulum.yaml."""
    model = os.path.join(source_dir, "examples", "studies", "pendulum.yaml")
    path = tmp_path / name
    path.write_text(f"model: {model}\n" + body)
    return path


LENGTHS = """parameters:
  length: {path: "bodies[name=bob].center_of_mass[1]", scale: -1, values: [0.5, 1.0]}
outputs: {period: period(angle.value)}
"""


@pytest.mark.parametrize("body, key, text", [
    ("parameters: {l: {path: bodies[name=bob].mass, values: [1]}}\noutputs: {s: summary.steps}\nspeed: 3\n",
     "speed", "unknown key"),
    ("parameters: {l: {path: bodies[name=bob].lenght, values: [1]}}\noutputs: {s: summary.steps}\n",
     "parameters.l.path", "has no key 'lenght'"),
    ("parameters: {l: {path: bodies[name=rod].mass, values: [1]}}\noutputs: {s: summary.steps}\n",
     "parameters.l.path", "0 entries of bodies have name = rod"),
    ("parameters: {l: {path: bodies[name=bob].center_of_mass[3], values: [1]}}\noutputs: {s: summary.steps}\n",
     "parameters.l.path", "has no element [3]"),
    ("parameters: {l: {path: bodies[name=bob].mass, range: {start: 2, stop: 1, step: 0.5}}}\n"
     "outputs: {s: summary.steps}\n", "parameters.l.range", "the range is empty"),
    ("parameters: {l: {path: bodies[name=bob].mass, values: []}}\noutputs: {s: summary.steps}\n",
     "parameters.l.values", "non-empty list"),
    ("parameters: {l: {path: bodies[name=bob].mass, values: [1], unit: kg}}\noutputs: {s: summary.steps}\n",
     "parameters.l.unit", "unknown key"),
    ("parameters: {l: {path: bodies[name=bob].mass, values: [1]}}\noutputs: {s: median(angle.value)}\n",
     "outputs.s", "unknown reduction 'median'"),
    ("parameters: {l: {path: bodies[name=bob].mass}}\ntable: [{l: 1}, {m: 2}]\noutputs: {s: summary.steps}\n",
     "table[1]", "a row gives every parameter"),
])
def test_study_file_errors_name_the_file_and_key(tmp_path, source_dir, body, key, text):
    path = pendulum_study(tmp_path, source_dir, re.sub(r'path: ([^,"}]+)', r'path: "\1"', body))
    with pytest.raises(flexmb.InputError) as e:
        flexmb.load_study(path)
    assert str(e.value).startswith(f"{path}: {key}"), str(e.value)
    assert text in str(e.value)


def test_study_file_expands_ranges_and_tables(tmp_path, source_dir):
    spec = flexmb.load_study(pendulum_study(tmp_path, source_dir, """parameters:
  length: {path: "bodies[name=bob].center_of_mass[1]", scale: -1, range: {start: 0.5, stop: 1.0, step: 0.25}}
  dt: {option: dt, range: {start: 1.0e-3, stop: 2.0e-3, count: 3}}
outputs: {period: period(angle.value)}
"""))
    assert [r["length"] for r in spec.rows] == [0.5] * 3 + [0.75] * 3 + [1.0] * 3  # full factorial, stop included
    assert [r["dt"] for r in spec.rows[:3]] == [1.0e-3, 1.5e-3, 2.0e-3]
    tasks = spec.runs("flexmb")
    assert tasks[3]["options"] == {"dt": 1.0e-3}
    assert "center_of_mass: [0, -0.75, 0]" in tasks[3]["model_text"]
    table = flexmb.load_study(pendulum_study(tmp_path, source_dir, """parameters:
  length: {path: "bodies[name=bob].center_of_mass[1]"}
  mass: {path: "bodies[name=bob].mass"}
table: [{length: -1, mass: 2}, {length: -2, mass: 1}]
outputs: {steps: summary.steps}
""", "t.yaml"))
    assert table.rows == [{"length": -1.0, "mass": 2.0}, {"length": -2.0, "mass": 1.0}]


def closed_form_period(length, theta0=0.1, g=9.81, mass=1.0, inertia=1.0e-6):
    """Period of the pendulum of examples/studies/pendulum.yaml released at
    theta0: T = 4 sqrt(J/(m g L)) K(sin(theta0/2)), J = I + m L^2 (the
    compound pendulum), K by the arithmetic-geometric mean."""
    k = math.sin(theta0 / 2)
    a, b = 1.0, math.sqrt(1 - k * k)
    for _ in range(30):
        a, b = (a + b) / 2, math.sqrt(a * b)
    big_k = math.pi / (2 * a)
    return 4 * math.sqrt((inertia + mass * length ** 2) / (mass * g * length)) * big_k


def test_pendulum_period_study_matches_closed_form(cli, source_dir, tmp_path):
    study = os.path.join(source_dir, "examples", "studies", "pendulum_period.yaml")
    table = flexmb.study(study, tmp_path / "out", workers=0, cli=cli)
    assert table.column("status") == ["ok"] * 4
    for length, period in zip(table.column("length"), table.column("period")):
        assert period == pytest.approx(closed_form_period(length), rel=2e-5), length
    assert table.column("steps") == [6000] * 4
    text = (tmp_path / "out" / "study.csv").read_text().splitlines()
    assert text[0] == "run,length,status,message,period,max_angle,steps,wall_time_s"
    assert [float(line.split(",")[4]) for line in text[1:]] == table.column("period")  # round trip


def test_a_failing_run_is_a_row_and_the_others_go_on(cli, source_dir, tmp_path):
    path = pendulum_study(tmp_path, source_dir, """parameters:
  mass: {path: "bodies[name=bob].mass", values: [1.0, -1.0, 2.0]}
outputs: {period: period(angle.value), x: max(no_such_column)}
""")
    table = flexmb.study(path, tmp_path / "out", workers=0, cli=cli, keep_runs=True)
    assert table.column("status") == ["failed"] * 3  # the missing column fails every run that ran
    assert "no column 'no_such_column'" in table[0]["message"]
    msg = table[1]["message"]  # flexmb's own error, the scratch folder named by the run
    assert msg.startswith("run_0001/model/pendulum.yaml:") and "'mass' must be positive, got -1" in msg, msg
    assert (tmp_path / "out" / "runs" / "run_0001" / "out" / "summary.json").exists()
    path.write_text(path.read_text().replace(", x: max(no_such_column)", ""))
    table = flexmb.study(path, tmp_path / "out2", workers=0, cli=cli)
    assert table.column("status") == ["ok", "failed", "ok"]
    for row in table[0], table[2]:  # the mass changes the period only through the bob's small inertia
        assert row["period"] == pytest.approx(closed_form_period(1.0, mass=row["mass"]), rel=2e-5)
    with pytest.raises(flexmb.InputError, match="journal of another study"):
        flexmb.study(path, tmp_path / "out", workers=0, cli=cli)


def test_an_interrupted_study_resumes_without_redoing_runs(cli, source_dir, tmp_path):
    path = pendulum_study(tmp_path, source_dir, LENGTHS.replace("[0.5, 1.0]", "[0.3, 0.4, 0.5, 0.6, 0.7, 0.8]"))
    out = tmp_path / "out"
    journal = out / "journal.jsonl"
    env = dict(os.environ, FLEXMB_CLI=cli)
    proc = subprocess.Popen([sys.executable, "-m", "flexmb.study_cli", str(path), "--out", str(out), "--workers", "0",
                             "-q"], env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline and proc.poll() is None:
        if journal.exists() and len(journal.read_text().splitlines()) >= 3:  # fingerprint + 2 rows
            break
        time.sleep(0.02)
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=10)
    lines = journal.read_text().splitlines()
    assert 3 <= len(lines) < 7, "the study was not interrupted in the middle"
    with open(journal, "a") as fh:
        fh.write('{"run": 5, "length": 0.8, "sta')  # a row cut by the kill
    ran = []
    table = flexmb.study(path, out, workers=0, cli=cli, on_row=ran.append)
    assert sorted(r["run"] for r in ran) == [i for i in range(6) if i >= len(lines) - 1]
    assert table.column("status") == ["ok"] * 6
    assert journal.read_text().splitlines()[:len(lines)] == lines  # finished rows kept as they were
    assert all(json.loads(line) for line in journal.read_text().splitlines())
    assert len((out / "study.csv").read_text().splitlines()) == 7


def test_flexmb_study_command_equals_the_python_call(cli, source_dir, tmp_path):
    study = os.path.join(source_dir, "examples", "studies", "pendulum_period.yaml")
    proc = subprocess.run([cli, "study", study, "--out", str(tmp_path / "cli"), "--workers", "0"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert "4 runs, 0 failed" in proc.stdout and "run 4/4: ok" in proc.stdout
    table = flexmb.study(study, tmp_path / "py", workers=0, cli=cli)
    rows = [line.rsplit(",", 1)[0] for line in (tmp_path / "cli" / "study.csv").read_text().splitlines()]
    assert rows == [line.rsplit(",", 1)[0] for line in (tmp_path / "py" / "study.csv").read_text().splitlines()]
    assert len(table) == 4
    bad = pendulum_study(tmp_path, source_dir, LENGTHS.replace("values: [0.5, 1.0]", "values: []"))
    proc = subprocess.run([cli, "study", str(bad), "--out", str(tmp_path / "bad")], capture_output=True, text=True,
                          timeout=60)
    assert proc.returncode == 2
    assert proc.stderr.startswith(f"error: {bad}: parameters.length.values: a non-empty list is needed")


def test_example_studies_are_valid(source_dir):
    folder = os.path.join(source_dir, "examples", "studies")
    counts = {"pendulum_period.yaml": 4, "truck_speed_friction.yaml": 9, "truck_max_speed.yaml": 3}
    for name, count in counts.items():
        spec = flexmb.load_study(os.path.join(folder, name))
        assert len(spec.rows) == count, name
    grid = flexmb.load_study(os.path.join(folder, "truck_speed_friction.yaml")).runs("flexmb")
    assert grid[5]["options"] == {"frame": "rigid", "speed": 50.0}
    assert "road_mu: 0.8" in grid[5]["model_text"] and "road_mu: 0.8" not in grid[4]["model_text"]


def test_study_table_in_hdf5_equals_the_csv(cli, source_dir, tmp_path):
    pd = pytest.importorskip("pandas", reason="study.h5 is written only with pandas (python3-pandas)")
    pytest.importorskip("tables", reason="study.h5 is written only with PyTables (python3-tables)")
    path = pendulum_study(tmp_path, source_dir, LENGTHS)
    table = flexmb.study(path, tmp_path / "out", workers=0, cli=cli)
    frame = pd.read_hdf(tmp_path / "out" / "study.h5", "study")
    assert list(frame.columns) == ["run", "length", "status", "message", "period", "wall_time_s"]
    assert list(frame["period"]) == table.column("period") and list(frame["status"]) == ["ok", "ok"]


def test_truck_run_with_side_files_equals_the_plain_run(cli, source_dir, tmp_path):
    truck = os.path.join(source_dir, "examples", "truck_lane_change", "truck.yaml")
    body = f"""model: {truck}
options: {{frame: rigid}}
parameters:
  speed_kmh: {{option: speed, values: [40]}}
  road_mu: {{path: lane_change_test.road_mu, values: [0.8]}}
outputs: {{passed: summary.passed, margin: summary.min_corridor_margin, roll: max(roll_deg)}}
"""
    (tmp_path / "shared.yaml").write_text(body)
    (tmp_path / "sent.yaml").write_text(body + "files: [tire_11r22_5.yaml, tire_11r22_5_twin.yaml]\n")
    shared = flexmb.study(tmp_path / "shared.yaml", tmp_path / "shared", workers=0, cli=cli)
    sent = flexmb.study(tmp_path / "sent.yaml", tmp_path / "sent", workers=0, cli=cli, keep_runs=True)
    assert shared[0]["status"] == "ok", shared[0]["message"]
    assert {k: v for k, v in sent[0].items() if k != "wall_time_s"} == \
        {k: v for k, v in shared[0].items() if k != "wall_time_s"}
    model_dir = tmp_path / "sent" / "runs" / "run_0000" / "model"
    assert sorted(p.name for p in model_dir.iterdir()) == ["tire_11r22_5.yaml", "tire_11r22_5_twin.yaml", "truck.yaml"]
    assert not any(p.is_symlink() for p in model_dir.iterdir())  # copies that travelled with the task
    subprocess.run([cli, "run", truck, "-o", str(tmp_path / "plain"), "--speed", "40", "--frame", "rigid", "-q"],
                   check=True, capture_output=True, timeout=120)
    plain = json.loads((tmp_path / "plain" / "summary.json").read_text())
    assert shared[0]["passed"] == plain["passed"]
    assert shared[0]["margin"] == plain["min_corridor_margin"]  # the rewritten file runs the same truck, bit for bit


def test_a_newton_failure_is_a_row(cli, source_dir, tmp_path):
    text = open(os.path.join(source_dir, "examples", "studies", "pendulum.yaml")).read()
    solver = "solver: {t_end: 4.0, dt: 1.0e-3, rho_inf: 0.9}"
    assert solver in text
    model = tmp_path / "pendulum.yaml"  # no step cutting (dt_min = dt): one Newton iteration cannot converge
    model.write_text(text.replace(solver, "solver: {t_end: 0.5, dt: 1.0e-3, dt_min: 1.0e-3, rho_inf: 0.9, "
                                          "newton_tol: 1.0e-12, max_newton: 12}"))
    path = tmp_path / "newton.yaml"
    path.write_text(f"""model: {model}
parameters:
  max_newton: {{path: solver.max_newton}}
table: [{{max_newton: 12}}, {{max_newton: 1}}]
outputs: {{angle: final(angle.value)}}
""")
    table = flexmb.study(path, tmp_path / "out", workers=0, cli=cli)
    assert table.column("status") == ["ok", "failed"]
    assert "step size fell below dt_min" in table[1]["message"] and table[1].get("angle") is None
    assert table[0]["angle"] < 0.1  # released at 0.1 rad, swinging down


def test_one_study_at_a_time_per_folder(cli, source_dir, tmp_path):
    import fcntl
    path = pendulum_study(tmp_path, source_dir, LENGTHS)
    (tmp_path / "out").mkdir()
    with open(tmp_path / "out" / "journal.jsonl", "a") as fh:  # as a study running into the folder holds it
        fcntl.flock(fh, fcntl.LOCK_EX)
        with pytest.raises(flexmb.InputError, match="is in use by another study"):
            flexmb.study(path, tmp_path / "out", workers=0, cli=cli)
    assert len(flexmb.study(path, tmp_path / "out", workers=0, cli=cli)) == 2
