"""Shared set-up of the Python tests: the flexmb CLI and the source tree
(environment of the ctest entry, python/CMakeLists.txt)."""

import os
import shutil

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
