"""Shared set-up of the Python tests: the flexmb CLI and the source tree
(environment of the ctest entry, python/CMakeLists.txt)."""

import os
import shutil
import subprocess
import sys

import pytest

SOURCE_DIR = os.environ.get("FLEXMB_SOURCE_DIR",
                            os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))


@pytest.fixture
def cli():
    """Path of the flexmb executable."""
    path = os.environ.get("FLEXMB_CLI") or shutil.which("flexmb")
    if not path:
        pytest.skip("flexmb CLI not found (FLEXMB_CLI)")
    return path


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="module")
def cli_module():
    """The flexmb executable for module-scoped fixtures."""
    path = os.environ.get("FLEXMB_CLI") or shutil.which("flexmb")
    if not path:
        pytest.skip("flexmb CLI not found (FLEXMB_CLI)")
    return path


@pytest.fixture(scope="module")
def source_dir_module():
    return SOURCE_DIR


def build_crane_boom(cli, work):
    """The example crane's boom as README.md builds it, in the folder `work`
    (a pathlib.Path): boom.bdf (make_boom.py) and boom.h5 (flexmb reduce,
    frame at the foot pin, 20 modes, deformation stiffening). Returns the
    crane example's folder."""
    crane = os.path.join(SOURCE_DIR, "examples", "crane")
    subprocess.run([sys.executable, os.path.join(crane, "make_boom.py"), "--out", str(work / "boom.bdf")],
                   check=True, capture_output=True)
    subprocess.run([cli, "reduce", str(work / "boom.bdf"), "--fix", "1", "--interface", "1,2,3", "--modes", "20",
                    "--deformation-stiffening", "-o", str(work / "boom.h5")], check=True, capture_output=True)
    return crane


@pytest.fixture
def truck_copy(tmp_path):
    """A folder with a copy of the example truck's lane-change file and its
    tire files, for tests that edit them."""
    example = os.path.join(SOURCE_DIR, "examples", "truck_lane_change")
    for name in ("truck.yaml", "tire_11r22_5.yaml", "tire_11r22_5_twin.yaml"):
        shutil.copy(os.path.join(example, name), tmp_path)
    return tmp_path
