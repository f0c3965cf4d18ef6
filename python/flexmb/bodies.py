"""Flexible body files (.h5, written by `flexmb reduce`) as numpy arrays."""

import os

import numpy as np

from . import _core


class Body:
    """A body file: frequencies [Hz], reduced mass/stiffness/damping (n x n),
    mode shapes (6 rows per node: ux uy uz [m] rx ry rz [rad] per unit modal
    coordinate), mesh nodes [m], elements, interface nodes, inertia
    invariants and stress modes (tables shell, beam, solid)."""

    def __init__(self, path):
        self.path = os.fspath(path)
        d = _core.read_body(self.path)
        self.frequencies_hz = d["frequencies_hz"]
        self.mass = d["mass"]
        self.stiffness = d["stiffness"]
        self.damping = d["damping"]
        self.modes = d["modes"]
        self.nodes = d["nodes"]
        self.node_ids = d["node_ids"]
        self.elements = d["elements"]
        self.interface_nodes = np.asarray(d["interface_nodes"], dtype=np.int64)
        self.invariants = d["invariants"]
        self.stress = d["stress"]
        self.units = d["units"]
        self.provenance = dict(d["provenance"])
        self.static_modes = d["static_modes"]
        self.normal_modes = d["normal_modes"]
        self.rigid_modes_removed = d["rigid_modes_removed"]

    @property
    def mode_count(self):
        """Number of modal coordinates n."""
        return self.modes.shape[1]

    @property
    def total_mass(self):
        """Mass [kg] (trace of the translational invariant / 3)."""
        return float(np.trace(self.invariants["mvv"]) / 3.0)

    @property
    def center_of_mass(self):
        """Centre of mass in the body frame [m] (from mvo0 = -m skew(c))."""
        m = self.total_mass
        s = -self.invariants["mvo0"] / m if m > 0 else np.zeros((3, 3))
        return np.array([s[2, 1], s[0, 2], s[1, 0]])

    def mode_shape(self, k):
        """Translations of mode k at every node, N x 3 [m per unit coordinate]."""
        return self.modes[:, k].reshape(-1, 6)[:, :3]

    def stress_modes(self, family):
        """The stress table of 'shell', 'beam', 'solid', 'beam_fibre' (beams
        at their sections' stress points) or 'solid_node' (solids at their
        corner nodes, when reduced with solid_corner_stress) (dict:
        components, locations, elements, axes, modes rows x n)."""
        return self.stress[family]

    def __repr__(self):
        return f"Body({self.path!r}, {len(self.nodes)} nodes, {self.mode_count} modes)"


def read_body(path):
    """Opens a body file; returns a Body."""
    return Body(path)
