"""FE models, reduction and body files from Python, on the free steel strip
of the command-line tests (tests/data/fe/nastran/cli_strip.bdf: 1 m x 50 mm
x 5 mm, E = 210 GPa, rho = 7850 kg/m^3, nu = 0)."""

import math
import os
import subprocess
import json

import numpy as np
import pytest

import flexmb

ENDS = "1,22,43,21,42,63"
E, RHO, L, B, T = 2.1e11, 7850.0, 1.0, 0.05, 0.005
MASS = RHO * L * B * T


@pytest.fixture
def strip(source_dir):
    return os.path.join(source_dir, "tests", "data", "fe", "nastran", "cli_strip.bdf")


def test_fe_modes_free_strip(strip):
    r = flexmb.fe_modes(strip, count=8)
    f = r["frequencies_hz"]
    assert len(f) == 8
    assert max(abs(x) for x in f[:6]) < 0.1  # six rigid-body modes
    # Euler-Bernoulli free-free beam, bending about the thickness: (4.7300)^2/(2 pi L^2) sqrt(EI/(rho A))
    f1 = 4.730040745 ** 2 / (2 * math.pi * L ** 2) * math.sqrt(E * T ** 2 / (12 * RHO))
    assert f[6] == pytest.approx(f1, rel=0.02)
    assert r["mass_kg"] == pytest.approx(MASS, rel=1e-12)
    assert flexmb.fe_info(strip)["nodes"] == 63


def test_reduce_stiffening_options(strip, tmp_path):
    rep = flexmb.reduce(strip, tmp_path / "s.h5", interface=ENDS, modes=4, deformation_stiffening=True,
                        geometric_stiffening=True)
    assert rep["timings_s"]["stiffening"] >= 0.0
    info = flexmb.body_info(tmp_path / "s.h5")
    assert info["deformation_stiffening"] and info["geometric_stiffening"]
    flexmb.reduce(strip, tmp_path / "p.h5", interface=ENDS, modes=4)
    info = flexmb.body_info(tmp_path / "p.h5")
    assert not info["deformation_stiffening"] and not info["geometric_stiffening"]


def test_reduce_acceleration_modes(strip, tmp_path):
    """`acceleration_modes=True` (`--acceleration-modes`): six more basis
    vectors, in the report and in `body_info`; the free strip's lowest
    frequencies do not rise (the basis only grows: Rayleigh-Ritz)."""
    plain = flexmb.reduce(strip, tmp_path / "p.h5", interface=ENDS, modes=4)
    acc = flexmb.reduce(strip, tmp_path / "a.h5", interface=ENDS, modes=4, acceleration_modes=True)
    assert (plain["acceleration_modes"], acc["acceleration_modes"]) == (0, 6)
    assert acc["flexible_modes"] == plain["flexible_modes"] + 6
    assert all(a <= p * (1 + 1e-9) for a, p in zip(acc["frequencies_hz"], plain["frequencies_hz"]))
    assert flexmb.body_info(tmp_path / "a.h5")["acceleration_modes"] == 6


def test_reduce_frame_option(strip, tmp_path):
    mean = flexmb.reduce(strip, tmp_path / "m.h5", interface=ENDS, modes=4, frame="buckens")
    assert mean["frame"].startswith("mean axes")
    assert mean["rigid_modes_removed"] == 6
    node = flexmb.reduce(strip, tmp_path / "n.h5", interface=ENDS, modes=4, frame=1)
    assert node["frame"] == "attached to the clamped nodes 1"
    assert node["rigid_modes_removed"] == 0
    assert node["frequencies_hz"] == flexmb.reduce(strip, tmp_path / "f.h5", interface=ENDS, modes=4,
                                                   fix="1")["frequencies_hz"]
    with pytest.raises(flexmb.InputError, match="--frame expects"):
        flexmb.reduce(strip, tmp_path / "x.h5", interface=ENDS, modes=4, frame="centre")


def test_reduce_and_body_file_match_cli(cli, strip, tmp_path):
    rep = flexmb.reduce(strip, tmp_path / "py.h5", interface=ENDS, modes=10)
    proc = subprocess.run([cli, "reduce", strip, "--interface", ENDS, "--modes", "10", "-o",
                           str(tmp_path / "cli.h5"), "--json"], capture_output=True, text=True, check=True)
    ref = json.loads(proc.stdout)
    assert rep["frequencies_hz"] == ref["frequencies_hz"]
    assert rep["flexible_modes"] == ref["flexible_modes"]
    body = flexmb.Body(tmp_path / "py.h5")
    n = body.mode_count
    assert n == rep["flexible_modes"]
    np.testing.assert_array_equal(body.frequencies_hz, np.array(rep["frequencies_hz"]))
    assert body.modes.shape == (6 * 63, n) and body.modes.dtype == np.float64
    assert body.nodes.shape == (63, 3)
    assert body.mass.shape == (n, n) and body.stiffness.shape == (n, n)
    # orthonormal modes: reduced mass identity, stiffness diag(omega^2)
    np.testing.assert_allclose(body.mass, np.eye(n), atol=1e-9)
    np.testing.assert_allclose(np.diag(body.stiffness), (2 * np.pi * body.frequencies_hz) ** 2, rtol=1e-9)
    # mass properties of the box from the inertia invariants
    assert body.total_mass == pytest.approx(MASS, rel=1e-9)
    np.testing.assert_allclose(body.center_of_mass, [0.5 * L, 0.5 * B, 0.0], atol=1e-9)
    assert body.stress_modes("shell")["modes"].shape[1] == n
    assert sorted(body.node_ids[body.interface_nodes].tolist()) == sorted(int(i) for i in ENDS.split(","))
    info = flexmb.body_info(tmp_path / "py.h5")
    assert info["mass_kg"] == pytest.approx(MASS, rel=1e-9)


def test_fe_error_names_file(tmp_path):
    with pytest.raises(flexmb.InputError, match="nope.bdf"):
        flexmb.fe_modes(tmp_path / "nope.bdf")


def test_flexible_body_modal_coordinates_are_views(strip, tmp_path):
    flexmb.reduce(strip, tmp_path / "strip.h5", interface=ENDS, modes=4)
    n = flexmb.Body(tmp_path / "strip.h5").mode_count
    w0 = [1e-3] + [0.0] * (n - 1)
    sim = flexmb.from_dict({
        "name": "free_strip", "gravity": [0, 0, 0],
        "bodies": [{"name": "strip", "type": "flexible", "file": str(tmp_path / "strip.h5"),
                    "modal_coordinates": w0}],
        "solver": {"t_end": 0.01, "dt": 1e-4},
    })
    sim.initialize()
    w = sim.modal_coordinates("strip")
    assert w.shape == (n,) and np.shares_memory(w, sim.q)
    np.testing.assert_array_equal(w, w0)
    assert sim.q.shape == (7 + n,) and sim.v.shape == (6 + n,)
    sim.run()
    # the first mode oscillates freely: w1(t) = w1(0) cos(omega1 t) (modes decoupled, no damping given)
    omega = 2 * math.pi * flexmb.Body(tmp_path / "strip.h5").frequencies_hz[0]
    # (generalized-alpha at omega h = 0.017: phase and amplitude errors of order (omega h)^2 = 3e-4)
    assert w[0] == pytest.approx(1e-3 * math.cos(omega * 0.01), abs=1e-6)
    assert np.abs(w[1:]).max() < 1e-12


def test_fe_mode_shapes_free_strip(strip):
    r = flexmb.fe_mode_shapes(strip, count=8)
    np.testing.assert_array_equal(r["frequencies_hz"], flexmb.fe_modes(strip, count=8)["frequencies_hz"])
    assert r["shapes"].shape == (6 * 63, 8) and r["nodes"].shape == (63, 3) and r["dofs"] == 378
    # first flexible mode: Euler-Bernoulli free-free beam, M-orthonormal: phi(x) / sqrt(m) with
    # phi = cosh bx + cos bx - s (sinh bx + sin bx), b L = 4.730041, s = 0.982502 (phi(0) = 2)
    bl, s = 4.730040745, 0.982502215

    def phi(x):
        b = bl * x / L
        return (np.cosh(b) + np.cos(b) - s * (np.sinh(b) + np.sin(b))) / math.sqrt(MASS)

    u = r["shapes"][:, 6].reshape(-1, 6)
    x = r["nodes"][:, 0]
    sign = np.sign(u[0, 2]) * np.sign(phi(x[0]))
    np.testing.assert_allclose(sign * u[:, 2], phi(x), rtol=0, atol=0.01 * phi(0.0))
    assert np.abs(u[:, :2]).max() < 1e-12  # bending out of plane only
