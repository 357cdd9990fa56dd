#!/usr/bin/python3
"""Why MacNeal's massless-boundary model of a free bar rings against a rigid wall (its force
does not keep within +-5 % of the plateau), from the held system's modes, in 1D.

While the bar presses on the wall its boundary is held, and the reduced model is a linear
system in the free-interface coordinates (the rigid translation, carried by the floating
frame, and N elastic modes): K_h = Omega^2 + dK_bb phi_b phi_b^T, mass I. From the uniform
velocity v0 at the touch, each held mode k moves as a_k sin(w_k t) / w_k, and the wall's force
is a sum of these sines. The continuum's force is the plateau rho c A v0, whose clamped-mode
series is the square wave's Fourier series 4 / (pi (2k - 1)) sin(...).

The script builds a uniform linear FE bar (the steel bar of bench/bar_drop, 0.1 m, 1e-4 m^2,
2 000 elements, so the retained modes are those of the continuum to 1e-5), reduces it by
MacNeal's method with inertia relief for N modes, and prints for each N: the held system's
top frequency against the retained band, the force over the middle 70 % of 2L/c relative to
the plateau (as bench/bar_drop measures it), the share of the top held mode in the force and in
the energy, and the force without that mode. For contrast, the held body of the massless
Craig-Bampton variant is the bar's N lowest clamped modes exactly: its force is the square
wave's partial sum. Writes RESULTS.md's 'bar_held_modes' section.

Usage: bench/reference/macneal_bar_held_modes.py [N ...]   (default 10 30 60 120)"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from bench_common import machine, update_section  # noqa: E402

E, RHO, AREA, LENGTH, V0 = 210e9, 7850.0, 1e-4, 0.1, 1.0
C = np.sqrt(E / RHO)
ELEMENTS = 2000
PLATEAU = RHO * C * AREA * V0
WINDOW = (0.15, 0.85)  # of the contact's 2L/c, as bench/bar_drop


def fe_bar():
    """Free-free linear FE bar: its modes M-normalized (rigid first) and squared frequencies."""
    h = LENGTH / ELEMENTS
    n = ELEMENTS + 1
    K = np.zeros((n, n))
    M = np.zeros((n, n))
    ke = E * AREA / h * np.array([[1.0, -1.0], [-1.0, 1.0]])
    me = RHO * AREA * h / 6 * np.array([[2.0, 1.0], [1.0, 2.0]])
    for e in range(ELEMENTS):
        K[e:e + 2, e:e + 2] += ke
        M[e:e + 2, e:e + 2] += me
    L = np.linalg.cholesky(M)
    Linv = np.linalg.inv(L)
    w2, V = np.linalg.eigh(Linv @ K @ Linv.T)
    return np.maximum(w2, 0.0), Linv.T @ V


def window_stats(force, t, T):
    inside = (t > WINDOW[0] * T) & (t < WINDOW[1] * T)
    r = force[inside] / PLATEAU
    return r.mean(), r.min(), r.max()


def macneal_held(w2, Phi, n):
    """Held system of MacNeal's model with n elastic modes: frequencies, the force's amplitude
    per mode (relative to the plateau) and the modes' energy shares, from the touch at v0."""
    phi_b = Phi[0, :n + 1]  # boundary row: rigid mode, then n elastic modes
    # residual flexibility of the boundary: the dropped elastic modes' share (all of the FE's)
    dF_bb = np.sum(Phi[0, n + 1:] ** 2 / w2[n + 1:])
    dK = 1.0 / dF_bb
    Kh = np.diag(w2[:n + 1]) + dK * np.outer(phi_b, phi_b)
    Kh[0, 0] = dK * phi_b[0] ** 2  # the rigid mode's frequency is 0 (round-off of the FE's)
    wh2, U = np.linalg.eigh(Kh)
    wh = np.sqrt(wh2)
    # the frame moves at -v0 toward the wall: the rigid coordinate's velocity -v0 / phi_rigid,b
    deta = np.zeros(n + 1)
    deta[0] = -V0 / phi_b[0]
    a = U.T @ deta
    amplitude = dK * (phi_b @ U) * a / wh / PLATEAU  # force = -dK phi_b . eta
    energy = 0.5 * a ** 2 / (0.5 * RHO * AREA * LENGTH * V0 ** 2)
    return wh, amplitude, energy


def main():
    counts = [int(a) for a in sys.argv[1:]] or [10, 30, 60, 120]
    w2, Phi = fe_bar()
    T = 2 * LENGTH / C
    t = np.linspace(0.0, T, 8001)
    rows = []
    for n in counts:
        wh, amp, energy = macneal_held(w2, Phi, n)
        sines = np.sin(np.outer(t, wh))
        force = -sines @ amp * PLATEAU
        without_top = -sines[:, :-1] @ amp[:-1] * PLATEAU
        k = np.arange(1, n + 1)
        clamped = PLATEAU * np.sin(np.outer(t, (2 * k - 1) * np.pi * C / (2 * LENGTH))) @ (4 / (np.pi * (2 * k - 1)))
        band = np.sqrt(w2[n]) / (2 * np.pi)
        rows.append((n, band / 1e3, wh[-1] / (2 * np.pi) / 1e3, abs(amp[-1]), energy[-1],
                     window_stats(force, t, T), window_stats(without_top, t, T), window_stats(clamped, t, T)))
        print(f"N {n}: top held {wh[-1] / 2 / np.pi / 1e3:.0f} kHz (band {band / 1e3:.0f} kHz), top mode force "
              f"{abs(amp[-1]):.3f}, energy {energy[-1]:.2e}; force {rows[-1][5]}, without it {rows[-1][6]}, clamped {rows[-1][7]}")

    m = machine()
    fmt = lambda s: f"{s[0]:.3f} / {s[1]:.3f} / {s[2]:.3f}"  # noqa: E731
    lines = [f"## Why MacNeal's bar rings: the held system's top mode",
             f"{m['date']}, commit {m['commit']}; `bench/reference/macneal_bar_held_modes.py` (numpy, no isosid code). "
             f"The steel bar of bench/bar_drop in 1D ({ELEMENTS} linear elements), reduced by MacNeal's method with inertia "
             "relief to N free-interface modes; with the boundary held at the wall, the force from the touch at v0 "
             "resolved into the held system's modes. Force over the middle 70 % of 2L/c relative to the plateau rho c A v0: "
             "mean / min / max.", "",
             "| N | retained band [kHz] | top held mode [kHz] | its force amplitude | its energy share | force | force without the top held mode | N clamped modes (massless Craig-Bampton, held body) |",
             "|---|---|---|---|---|---|---|---|"]
    for n, band, top, amp, energy, full, without, clamped in rows:
        lines.append(f"| {n} | {band:.0f} | {top:.0f} | {amp:.3f} | {energy:.2e} | {fmt(full)} | {fmt(without)} | {fmt(clamped)} |")
    lines += ["", "Reading: every held mode but the top one is a clamped mode of the bar (the lowest to 1e-5 in "
              "frequency, the highest within 1.3 %) with its share of the force (1.273, 0.424, 0.255, ... = "
              "4 / (pi (2k - 1))). The top held mode lies above the retained band, where "
              "the residual stiffness ties the boundary to the modes, and it carries the whole dropped tail of the series: "
              "a force amplitude of 0.80 of the plateau whatever N, and about the energy share 2 / (pi^2 N) that the N modes do "
              "not hold. More modes raise its frequency, not lower its amplitude. Without it the force is the partial sum "
              "of N clamped modes and flat to the Gibbs ripple of the window's edges. The ringing of bench/bar_drop "
              "(min 0.16, max 1.84 at N = 30, plane stress) is this mode; the plateau within +-5 % asked for is out of "
              "reach of MacNeal's model of a free body as long as its static boundary flexibility is exact (the issue's "
              "first acceptance item). The top mode sits only 1.2 times above the band, too close for an integrator's "
              "numerical damping to remove it without the upper real modes. The massless Craig-Bampton variant has no "
              "such mode, but needs a held body (its constraint modes of a free bar are its rigid motion)."]
    update_section("bar_held_modes", "\n".join(lines))


if __name__ == "__main__":
    main()
