#!/usr/bin/python3
# Reference for the ANCF soft pendulum (docs/validation.md, "ANCF axial
# strain measures"): Berzeri and Shabana's pendulum (L = 1.2 m, A = 0.0018
# m^2, I = 1.215e-8 m^4, rho = 5540 kg/m^3, E = 0.7 MPa, pinned at one end,
# released from rest horizontal, g = 9.81) as an independent discrete model:
# N + 1 point masses (rho A l, half at the ends) on N axial springs whose
# force is EA eps deps/dlambda (Green-Lagrange eps = (lambda^2 - 1)/2, or
# engineering eps = lambda - 1), with discrete bending springs at the inner
# nodes (energy EI phi^2 / (2 l), phi the turning angle between segments:
# the elastica's EI kappa^2 / 2 with kappa = phi / l per material length),
# integrated by velocity Verlet. Converges to the extensible elastica as
# N -> infinity; prints the tip (x, y) [m] at t = 0.1 ... 1.0 s per N.
import argparse

import numpy as np


def run(N, dt, t_out, green_lagrange=True, L=1.2, A=0.0018, I=1.215e-8, rho=5540.0, E=0.7e6, g=9.81):
    EA, EI, l = E * A, E * I, L / N
    m = np.full(N + 1, rho * A * l)
    m[0] *= 0.5
    m[-1] *= 0.5
    x = np.zeros((N + 1, 2))
    x[:, 0] = np.linspace(0.0, L, N + 1)
    v = np.zeros_like(x)

    def forces(x):
        f = np.zeros_like(x)
        f[:, 1] -= m * g
        d = x[1:] - x[:-1]
        ln = np.linalg.norm(d, axis=1)
        lam = ln / l
        T = EA * (0.5 * (lam**2 - 1.0) * lam if green_lagrange else (lam - 1.0))  # EA eps deps/dlambda
        u = d / ln[:, None]
        f[:-1] += T[:, None] * u
        f[1:] -= T[:, None] * u
        # bending at the inner nodes i = 1 .. N-1: phi = angle(b) - angle(a)
        a, b = d[:-1], d[1:]
        phi = np.arctan2(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0], (a * b).sum(axis=1))
        M = EI * phi / l
        ga = np.stack([-a[:, 1], a[:, 0]], axis=1) / (ln[:-1] ** 2)[:, None]  # d angle(a) / d a
        gb = np.stack([-b[:, 1], b[:, 0]], axis=1) / (ln[1:] ** 2)[:, None]
        f[2:] -= M[:, None] * gb
        f[1:-1] += M[:, None] * (ga + gb)
        f[:-2] -= M[:, None] * ga
        return f

    out, targets, k = {}, sorted(t_out), 0
    acc = forces(x) / m[:, None]
    acc[0] = 0.0  # the pin
    for s in range(1, int(round(max(targets) / dt)) + 1):
        v += 0.5 * dt * acc
        x += dt * v
        acc = forces(x) / m[:, None]
        acc[0] = 0.0
        v += 0.5 * dt * acc
        v[0] = 0.0
        x[0] = 0.0
        while k < len(targets) and abs(s * dt - targets[k]) < 0.5 * dt:
            out[targets[k]] = x[-1].copy()
            k += 1
    return out


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description="soft pendulum tip path of a discrete chain model")
    ap.add_argument("--n", type=int, nargs="+", default=[100, 200, 400], help="segments")
    ap.add_argument("--dt", type=float, default=2e-5, help="time step [s]")
    ap.add_argument("--engineering", action="store_true", help="engineering axial strain (default Green-Lagrange)")
    a = ap.parse_args()
    ts = [0.1 * k for k in range(1, 11)]
    for N in a.n:
        r = run(N, a.dt, ts, green_lagrange=not a.engineering)
        print(N, " ".join("(%.5f, %.5f)" % tuple(r[t]) for t in ts))
