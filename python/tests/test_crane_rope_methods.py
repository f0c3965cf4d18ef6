"""examples/crane/rope_methods.py end to end: the crane's hoisting rope as
the massless `rope` force and as an `ancf_hoist_rope` whose free length the
winch changes, on the same slew with hoisting (docs/validation.md,
"Hoisting rope of changing length").

Reference: the two models of the same rope. The rope weighs 1.6 kg/m (18 kg
hanging) against the 5 t load, so the largest swing, the largest hook force
and the hook's height must agree to the rope's weight and its waves:
measured 0.14 % (swing), < 0.01 % (force), 1.6 mm (height; the ANCF span's
own weight and sag); allowed 1 %, 1 % and 5 mm. The hoisting really moves
the hook: 1.05 m of rope hauled in."""

import json
import os
import subprocess
import sys

import pytest
from conftest import build_crane_boom


@pytest.fixture(scope="module")
def ropes(cli_module, source_dir_module, tmp_path_factory):
    work = tmp_path_factory.mktemp("crane_ropes")
    crane = build_crane_boom(cli_module, work)
    subprocess.run([sys.executable, os.path.join(crane, "rope_methods.py"), "--flexmb", cli_module,
                    "--body", str(work / "boom.h5"), "--out", str(work / "ropes")], check=True, capture_output=True)
    with open(work / "ropes" / "rope_methods.json") as f:
        return json.load(f)


def test_massless_and_ancf_rope_agree(ropes):
    m, a = ropes["methods"]["massless"], ropes["methods"]["ancf"]
    assert a["largest_swing_deg"] == pytest.approx(m["largest_swing_deg"], rel=0.01)
    assert a["largest_hook_force_N"] == pytest.approx(m["largest_hook_force_N"], rel=0.01)
    assert abs(a["hook_z_end_m"] - m["hook_z_end_m"]) < 5e-3
    assert m["largest_swing_deg"] > 5.0  # the slew swings the load


def test_the_winch_hoisted_the_load(ropes):
    # the hook starts at the block's lifted place (1.39 m above its centre at 2.38 m) and
    # rises by the 1.05 m hauled in, less the stretch of the heavier hoist (mm)
    for r in ropes["methods"].values():
        assert r["hook_z_end_m"] == pytest.approx(0.38475 + 2.0 + 1.39 + 1.05, abs=0.05)
