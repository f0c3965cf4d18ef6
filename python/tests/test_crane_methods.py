"""examples/crane/methods.py end to end: the crane's boom four ways against
the full FE model (docs/validation.md, "The crane boom four ways").

References: the full FE model's clamped frequencies (`flexmb fe modes`) and
linear static head deflection (`flexmb fe static`). The Craig-Bampton body's
static modes span the interface loads, so its linear deflection equals the
full model's (round-off and the self weight's distributed load: 1e-4); the
beam models (rigid finite elements, ANCF) are discretized beam theory of the
thin-walled box, within 1 % for the first two frequencies and the linear
deflections (measured 0.0 to 0.3 %). At the rated load the boom's growth
over linear, clamped and on the crane's pins (the P-delta of its axial
compression), must be that of the full FE model's second-order solution
(`fe static --second-order`, +2.02 and +2.15 %): the beam models by their
own geometry, the Craig-Bampton body (its frame attached to the foot,
`--fix 1`) by its deformation stiffening. Measured within 0.06 % of the
deflection; allowed 0.3 %. Every crane run must finish."""

import json
import os
import subprocess
import sys

import pytest
from conftest import build_crane_boom


@pytest.fixture(scope="module")
def methods(cli_module, source_dir_module, tmp_path_factory):
    work = tmp_path_factory.mktemp("crane_methods")
    crane = build_crane_boom(cli_module, work)
    subprocess.run([sys.executable, os.path.join(crane, "methods.py"), "--flexmb", cli_module,
                    "--out", str(work / "methods"), "--bdf", str(work / "boom.bdf"), "--body", str(work / "boom.h5")],
                   check=True, capture_output=True, cwd=work)
    with open(work / "methods" / "methods.json") as f:
        return json.load(f)


def test_the_reduced_boom_is_the_full_fe_model(methods):
    full, cb = methods["full_fe"], methods["methods"]["cb"]
    for f, ref in zip(cb["frequencies_hz"][:2], full["frequencies_hz"][:2]):
        assert f == pytest.approx(ref, rel=1e-3)
    for key in ("head_deflection", "pinned_deflection"):
        assert cb[key + "_linear_B_m"][2] == pytest.approx(full[key + "_B_m"][2], rel=1e-4)


@pytest.mark.parametrize("method", ["rfe", "ancf"])
def test_beam_models_match_the_full_fe_model(methods, method):
    full, r = methods["full_fe"], methods["methods"][method]
    for f, ref in zip(r["frequencies_hz"][:2], full["frequencies_hz"][:2]):
        assert f == pytest.approx(ref, rel=0.01)
    for key in ("head_deflection", "pinned_deflection"):
        assert r[key + "_linear_B_m"][2] == pytest.approx(full[key + "_B_m"][2], rel=0.01)
        # the axial compression's P-delta makes the rated load's deflection larger, by a few %
        growth = r[key + "_B_m"][2] / r[key + "_linear_B_m"][2] - 1.0
        assert 0.005 < growth < 0.05


@pytest.mark.parametrize("method", ["cb", "rfe", "ancf"])
def test_rated_load_p_delta_matches_the_full_fe_second_order(methods, method):
    full, r = methods["full_fe"], methods["methods"][method]
    for key in ("head_deflection", "pinned_deflection"):
        ref = full[key + "_second_order_B_m"][2] / full[key + "_B_m"][2]
        assert 1.01 < ref < 1.04
        growth = r[key + "_B_m"][2] / r[key + "_linear_B_m"][2]
        assert growth == pytest.approx(ref, abs=3e-3), key


def test_every_crane_run_finishes(methods):
    for name, r in methods["methods"].items():
        assert r["crane"]["status"] == "ok", name
        assert r["crane"]["t"][-1] == pytest.approx(24.0), name
    assert max(abs(y) for y in methods["methods"]["rigid"]["crane"]["head_y_m"]) < 1e-9
