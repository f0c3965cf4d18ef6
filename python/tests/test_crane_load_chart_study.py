"""examples/crane/load_chart_crane.yaml: the example crane's load chart as a
study over the crane file's own keys (the luffing angle and the payload's
mass by path; the crane template places the boom, cylinder, load and rope
for each row), run by `flexmb study` (docs/crane-file.md, docs/studies.md).

References (statics, closed forms): the rope carries the hanging load on
two falls, T = m g / 2 (to 1e-6); the four pads carry the whole weight,
crane and load (the crane's 307.65 kN from the rigid parts' masses and the
boom's 2261 kg body file mass, plus m g; to 1e-6); the radius shrinks as the
boom luffs up."""

import csv
import json
import os
import shutil
import subprocess

import pytest
from conftest import build_crane_boom

G = 9.81
# carrier, superstructure, drum, barrel, rod (crane.yaml)
RIGID_KG = 16000 + 12000 + 600 + 350 + 150


def test_load_chart_study_over_the_crane_file(cli, tmp_path):
    crane = build_crane_boom(cli, tmp_path)
    for f in ("crane.yaml", "load_chart_crane.yaml"):
        shutil.copy(os.path.join(crane, f), tmp_path / f)
    r = subprocess.run([cli, "study", "load_chart_crane.yaml", "--out", "chart", "--workers", "1", "-q"],
                       cwd=tmp_path, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    rows = list(csv.DictReader(open(tmp_path / "chart" / "study.csv")))
    assert [int(row["luffing_deg"]) for row in rows] == [20, 30, 40, 50, 60, 70]
    info = subprocess.run([cli, "body", "info", str(tmp_path / "boom.h5"), "--json"], capture_output=True, text=True,
                          check=True).stdout
    boom_kg = json.loads(info)["mass_kg"]
    radius = []
    for row in rows:
        assert row["status"] == "ok", row["message"]
        m = float(row["rated_load_kg"])
        assert float(row["rope_tension_N"]) == pytest.approx(m * G / 2, rel=1e-6)
        pads = 2 * float(row["pad_fl_N"]) + 2 * float(row["pad_rl_N"])  # symmetric about x-z
        assert pads == pytest.approx((RIGID_KG + boom_kg + m) * G, rel=1e-6)
        radius.append(float(row["radius_m"]))
    assert radius == sorted(radius, reverse=True) and radius[0] > 17.5 and radius[-1] < 7.5
