"""The truck with its frame from a body file, the seed's workflow: the
generated ladder frame written as a Nastran deck (`flexmb truck frame-deck`),
reduced by `flexmb reduce` as a user's deck is, and named in the truck file
(`frame: {body, mounts}`; examples/truck_lane_change/own_frame.py). The lane
change with that frame reproduces the run that reduces the frame inline,
and bad mounts are errors that name the file, line and mount
(docs/validation.md, "Truck frame from a body file")."""

import csv
import os
import re
import shutil
import subprocess
import sys

import pytest

# both files run with full Newton at a tight tolerance: the comparison then
# shows the frame, not the iteration error (1e-6 by default)
TIGHT = [(r"^    newton_tol: .*$", "    newton_tol: 1.0e-10"), (r"^    jacobian_reuse: true.*$", "    jacobian_reuse: false")]


def tighten(path):
    text = open(path).read()
    for pattern, repl in TIGHT:
        text, n = re.subn(pattern, repl, text, flags=re.M)
        assert n == 1, pattern
    open(path, "w").write(text)


@pytest.fixture(scope="module")
def files(cli_module, source_dir_module, tmp_path_factory):
    """(generated, own): truck.yaml and its own-frame copy, both tightened."""
    work = tmp_path_factory.mktemp("own_frame")
    example = os.path.join(source_dir_module, "examples", "truck_lane_change")
    subprocess.run([sys.executable, os.path.join(example, "own_frame.py"), "--out", str(work), "--flexmb", cli_module],
                   check=True, capture_output=True)
    generated = work / "generated.yaml"
    shutil.copy(os.path.join(example, "truck.yaml"), generated)
    own = work / "truck_own_frame.yaml"
    tighten(generated)
    tighten(own)
    return generated, own


def run(cli, model, frame, out):
    subprocess.run([cli, "run", str(model), "--frame", frame, "--out", str(out), "-q"], check=True,
                   capture_output=True)
    with open(out / "results.csv") as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def largest_difference(a, b):
    """Largest difference of a column, relative to the column's largest value."""
    (ha, ra), (hb, rb) = a, b
    assert ha == hb and len(ra) == len(rb)
    worst = 0.0
    for j in range(len(ha)):
        scale = max(abs(r[j]) for r in ra) or 1.0
        worst = max(worst, max(abs(x[j] - y[j]) for x, y in zip(ra, rb)) / scale)
    return worst


def test_elastic_frame_from_the_deck_reproduces_the_inline_reduction(cli, files, tmp_path):
    generated, own = files
    a = run(cli, generated, "elastic", tmp_path / "generated")
    b = run(cli, own, "elastic", tmp_path / "own")
    assert "frame_max_stress_MPa" in a[0]
    # measured 3.7e-8 (lateral acceleration): the same body to round-off
    assert largest_difference(a, b) < 1e-6


def test_rigid_frame_takes_the_body_files_mass_properties(cli, files, tmp_path):
    generated, own = files
    a = run(cli, generated, "rigid", tmp_path / "generated")
    b = run(cli, own, "rigid", tmp_path / "own")
    # the body's inertia holds the plates' rotary inertia (t^2 / 12 against
    # the rails' spacing squared: 2e-5 of the roll inertia) that the
    # generated frame's surface integral leaves out; measured 7.5e-6
    assert largest_difference(a, b) < 5e-5


def check_error(cli, path, edits, *expected):
    text = open(path).read()
    for old, new in edits:
        assert old in text, old
        text = text.replace(old, new, 1)
    bad = path.parent / "bad.yaml"
    bad.write_text(text)
    r = subprocess.run([cli, "check", str(bad), "--frame", "elastic"], capture_output=True, text=True)
    assert r.returncode != 0
    for part in expected:
        assert re.search(part, r.stderr), (part, r.stderr)


def test_bad_mounts_are_errors_naming_file_line_and_mount(cli, files):
    _, own = files
    text = open(own).read()
    tow = re.search(r"^      tow_hitch: \d+\n", text, re.M).group(0)
    pivot = re.search(r"^      arm_pivot_front: (\d+)\n", text, re.M)
    line = text[:pivot.start()].count("\n") + 1
    check_error(cli, own, [(tow, "")], r"bad\.yaml:\d+: .*mount 'tow_hitch' .* has no node")
    check_error(cli, own, [(tow, tow.replace("tow_hitch", "tow_hook"))], r"unknown mount 'tow_hook'; .*tow_hitch")
    check_error(cli, own, [(pivot.group(0), "      arm_pivot_front: 999999\n")],
                rf"bad\.yaml:{line}: frame mount 'arm_pivot_front': node 999999 does not exist in body file")
    check_error(cli, own, [(pivot.group(0), "      arm_pivot_front: 12.5\n")],
                rf"bad\.yaml:{line}: .*node id of mount 'arm_pivot_front' must be a positive integer")
    check_error(cli, own, [(pivot.group(0), "      arm_pivot_front: 1\n")],
                rf"bad\.yaml:{line}: .*node 1 of .* is not an interface node")
    check_error(cli, own, [("mount_tolerance: 0.35", "mount_tolerance: 0.1")],
                rf"bad\.yaml:{line}: frame mount 'arm_pivot_front': node {pivot.group(1)} .* is 0\.295 m from the mount point")
    check_error(cli, own, [("    body: frame.h5", "    thickness: 0.007\n    body: frame.h5")],
                r"bad\.yaml:\d+: .*'thickness' shapes the generated ladder frame")
    check_error(cli, own, [("  road_mu:", "  frame_modes: 12\n  road_mu:")],
                r"bad\.yaml:\d+: .*'frame_modes' applies to the generated frame")
    check_error(cli, own, [("  road_mu:", "  frame_acceleration_modes: true\n  road_mu:")],
                r"bad\.yaml:\d+: .*'frame_acceleration_modes' applies to the generated frame.*--acceleration-modes")
    check_error(cli, own, [("    body: frame.h5", "    body: missing.h5")], r"bad\.yaml:\d+: .*cannot use body file")


def test_frame_deck_refuses_a_truck_whose_frame_is_a_body_file(cli, files, tmp_path):
    _, own = files
    r = subprocess.run([cli, "truck", "frame-deck", str(own), "-o", str(tmp_path / "x.bdf")], capture_output=True,
                       text=True)
    assert r.returncode != 0 and "already a body file" in r.stderr


@pytest.fixture(scope="module")
def files_6x4(cli_module, source_dir_module, tmp_path_factory):
    """(generated, own) of the 6x4, whose frame carries the platform, both tightened."""
    work = tmp_path_factory.mktemp("own_frame_6x4")
    truck = os.path.join(source_dir_module, "examples", "truck_6x4", "truck.yaml")
    subprocess.run([sys.executable, os.path.join(source_dir_module, "examples", "truck_lane_change", "own_frame.py"),
                    "--truck", truck, "--out", str(work), "--flexmb", cli_module], check=True, capture_output=True)
    generated = work / "generated.yaml"
    text = open(truck).read().replace("../truck_lane_change/", "")  # the tire files were copied beside it
    generated.write_text(text)
    own = work / "truck_own_frame.yaml"
    tighten(generated)
    tighten(own)
    return generated, own


def test_frame_with_platform_from_the_deck_reproduces_the_inline_reduction(cli, files_6x4, tmp_path):
    """The platform's sills, bearers, side rails and brackets pass through the
    Nastran deck (PSHELL with NSM per section) unchanged, and its `spacer` and
    `sill_height` place the cargo mounts on the platform's top as the
    generated frame does."""
    generated, own = files_6x4
    text = open(own).read()
    assert re.search(r"^    platform: \{spacer: 0\.02, sill_height: 0\.12\}", text, re.M), text
    a = run(cli, generated, "elastic", tmp_path / "generated")
    b = run(cli, own, "elastic", tmp_path / "own")
    assert largest_difference(a, b) < 1e-6


def test_platform_keys_beside_a_body_file_only_place_the_cargo(cli, files_6x4):
    _, own = files_6x4
    check_error(cli, own, [("{spacer: 0.02,", "{width: 2.5, spacer: 0.02,")],
                r"bad\.yaml:\d+: .*platform.*unknown key 'width'")


def test_a_platform_at_its_default_placement_keeps_its_cargo_on_top(cli, source_dir_module, tmp_path):
    """A platform whose `spacer` and `sill_height` are left at their defaults:
    the deck carries them (a comment) and own_frame.py writes them beside the
    body file, so the cargo mounts stay on the platform's top (found by a
    user test: they fell to the rails' top, hidden by the mount tolerance)."""
    truck = os.path.join(source_dir_module, "examples", "truck_6x4", "truck.yaml")
    text = open(truck).read().replace("../truck_lane_change/", os.path.join(source_dir_module, "examples",
                                                                             "truck_lane_change") + "/")
    text, n = re.subn(r"^      (spacer|sill_height): .*\n", "", text, flags=re.M)
    assert n == 2
    path = tmp_path / "defaults.yaml"
    path.write_text(text)
    deck = tmp_path / "frame.bdf"
    printed = subprocess.run([cli, "truck", "frame-deck", str(path), "-o", str(deck)], check=True,
                             capture_output=True, text=True).stdout
    assert "platform: {spacer: 0.02, sill_height: 0.12}" in printed
    sys.path.insert(0, os.path.join(source_dir_module, "examples", "truck_lane_change"))
    try:
        import own_frame
    finally:
        sys.path.pop(0)
    placement = re.search(r"^\$ platform: spacer (\S+) sill_height (\S+) ", deck.read_text(), re.M).groups()
    assert placement == ("0.02", "0.12")
    assert "    platform: {spacer: 0.02, sill_height: 0.12}" in own_frame.own_frame_file(text, [], placement)
