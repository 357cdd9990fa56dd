#!/usr/bin/python3
"""Classical reference for the free-free case of sphere on a beam (F; [R3] in
docs/references.md: the steel sphere dropped centrically on the free-free steel beam at
1.1 m/s): Hertz contact on a Timoshenko beam by modal superposition, the sphere a rigid mass
(Goldsmith, Impact, 1960, ch. 4: the sphere on a beam by normal modes, Hertz's law for the
contact; Timoshenko's beam with shear and rotary inertia), plus 3D side calculations that bound
the classical model's own error.

Model (every input is read from the scene and its two model files; see --scene):
- Beam: bending in the impact plane (deflection w along the sphere's velocity), Timoshenko
  with the shear coefficient kappa = 10 (1 + nu) / (12 + 11 nu) (Cowper's rectangle) and
  rotary inertia. Finite elements of degree 5 (w and the section's rotation theta on the same
  Lagrange basis at Gauss-Lobatto nodes, shear strain w' - theta, consistent mass with rotary
  inertia, Gauss with 7 points: exact), a node at the impact point; dense generalized
  eigenproblem (scipy). Two-node interdependent-interpolation elements were tried first:
  their frequencies converge only as h^2 here (the shear strain is constant per element), too
  slowly for the 1e-5 asked. Free-free: the two rigid-body modes (translation, rotation) are
  put in exactly and mass-normalized; the elastic modes phi_k are mass-normalized and
  M-orthogonal to them (the mean-axis frame of the project's floating bodies). The first 12
  bending frequencies are shown converging with the mesh, against Euler-Bernoulli's free-free
  closed form (cos bL cosh bL = 1), a 3D CalculiX model and the project's values.
- Contact: Hertz, F = K delta^(3/2) for delta > 0, K = 4/3 E* sqrt(R), 1/E* = (1 - nu_s^2)/E_s +
  (1 - nu_b^2)/E_b, R the sphere's radius (the beam's face is flat); delta = u_s - w(x_c) the
  approach (u_s the sphere's displacement along its velocity, w the beam's deflection at the
  impact point along the same direction).
- Equations: m_s u_s'' = -F, q_k'' + omega_k^2 q_k = phi_k(x_c) F (the rigid translation with
  omega = 0), integrated by scipy's DOP853 (rtol 1e-11 by default, absolute tolerances scaled
  by the Hertz approach, v0 and the modal amplitudes), with events for the release (delta = 0)
  and the force maxima (delta' = 0); after the release the motion is free and is evaluated
  exactly (harmonic modes) to 500 us to check that the sphere does not touch the beam again.
- Modes retained: every mode below a cutoff frequency. The modes above it respond
  quasistatically to a pulse of ~37 us: their static flexibility at the impact point
  c_res = G(x_c, x_c) - sum_retained phi_k(x_c)^2 / omega_k^2 (G the free beam's
  inertia-relief flexibility from the same FE model) is put in series with the contact (the
  static correction, as in mode acceleration); the approach then solves
  u_s - sum phi_k q_k = delta + c_res F(delta). Plain truncation and the corrected
  superposition are both shown against the cutoff; they converge to the same values.
- Reported as isosid-run does (runtime/output/impact_modes.hpp): E_0 = 1/2 m_s v_0^2 (v_0 the
  sphere's velocity before the onset); E_k = 1/2 (q_k'^2 + omega_k^2 q_k^2) at the end of contact
  for the elastic modes (k-th bending mode = kF; the antisymmetric ones are not excited);
  r_k = -(v_s(t_E) - phi_k(x_c) q_k'(t_E)) / v_0, v_s the sphere's velocity along the impact
  direction. isosid-run takes t_E as the first step after the release (at most 0.1 us
  later); this script takes the release itself (E_k is constant after it; r_k moves by less
  than 1e-3 of v_0 in 0.1 us for 1F..9F).
- Checks: total energy (sphere, modes, contact potential 2/5 K delta_H^(5/2) + 1/2 C F^2) and
  momentum (sphere + beam's rigid translation) at the release, relative errors.

Limits: the 1D beam and Hertz's half-space. Left out, and estimated by the script (each a
rerun of the impact with one change; together they give a best estimate of the 3D problem
and a bracket around it):
- the sphere's finite size: its centre of mass approaches less than a half-space's surface
  would. A linear compliance C_s < 0 in series with Hertz, from the CalculiX force-approach
  law of a steel sphere on a rigid plane (bench/reference/finite_sphere_steel_r5_v1.csv, made
  by finite_sphere.py), scaled as 1/(E R) (same nu);
- the beam's local 3D field under the contact (Hertz's half-space reaches down to infinity,
  the beam is 10 mm deep and 15 mm wide): a static 3D CalculiX model of the quarter beam
  (C3D20, graded toward the contact) under the inertia-relief body force and (A) the Hertz
  pressure of the peak force, (B) the same force spread over a 10 mm slab of the section;
  A - B, less Timoshenko's A - B, Saint-Venant's anticlastic offsets and the half-space's
  pressure-weighted approach, is the local correction C_b F (a linear compliance, checked
  against five meshes, four slab widths and three forces while developing the script);
- the anticlastic offset of the loaded top face against the section's mean deflection,
  nu (2 h^2 + b^2) / 24 M / EI (Saint-Venant), with the bending moment under the sphere from the
  run itself (its least-squares ratio to the force over the pulse);
- the beam's dynamics in 3D: the symmetric bending frequencies of a 3D CalculiX model of the
  quarter beam replace the Timoshenko ones (same mode shapes), and kappa = 5/6 shows the
  sensitivity to the shear model.
The CalculiX parts need ccx (Debian calculix-ccx; about 2 minutes of CPU); with --no-ccx or
without ccx they are read back from the JSON written before.

Usage: timoshenko_hertz.py [--scene models/sphere_on_beam_free.scene.toml] [--no-ccx]
    [--json bench/reference/timoshenko_hertz_free.json] [--elements 40] [--cutoff 8e5] [--rtol 1e-11]
Prints a markdown section; writes the JSON with the converged values, the bracket, the side
calculations and the project's values it compares with."""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time
import tomllib

import numpy as np
from scipy import linalg, optimize
from scipy.integrate import solve_ivp

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TC_FACTOR = 0.8 * math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9)  # Hertz: t_c = TC_FACTOR delta_max / v0

# Comparison only, never used in the computation except the clearly marked sensitivity run
# "beam frequencies set to the project's": project values (timoshenko_hertz_project.json) as in
# bench/RESULTS.md section sphere_on_beam at commit 5f7f634 (free-free beam, centric impact at
# P4, 1.1 m/s).
with open(os.path.join(HERE, "timoshenko_hertz_project.json")) as f:
    PROJECT = json.load(f)
N_BENDING = 9      # modes reported (1F..9F), as bench/sphere_on_beam
N_FREQ = 12        # frequencies shown converging


# --------------------------------------------------------------------------------- inputs
def read_case(scene_path):
    """Beam, sphere and impact from the scene and its two model files (SI units)."""
    with open(scene_path, "rb") as f:
        scene = tomllib.load(f)
    folder = os.path.dirname(os.path.abspath(scene_path))
    bodies = {b["name"]: b for b in scene["flexible_body"]}
    contact = scene["contact"][0]
    slave, target = bodies[contact["body"]], bodies[contact["target"]]
    with open(os.path.join(folder, slave["model"]), "rb") as f:
        sphere = tomllib.load(f)
    with open(os.path.join(folder, target["model"]), "rb") as f:
        beam = tomllib.load(f)
    if sphere["geometry"]["primitive"] != "ball" or beam["geometry"]["primitive"] != "box":
        sys.exit("expected a ball on a box")
    velocity = np.array(slave["velocity"], float)
    axis = int(np.argmax(np.abs(velocity)))           # impact direction (the beam's height)
    if np.count_nonzero(velocity) != 1 or any(target.get("velocity", [0, 0, 0])):
        sys.exit("expected a sphere moving along one axis onto a beam at rest")
    size = np.array(beam["geometry"]["size"], float)
    long_axis = int(np.argmax(size))
    width_axis = 3 - axis - long_axis
    origin = np.array(target.get("position", [0, 0, 0]), float)
    radius = sphere["geometry"]["radius"]
    x_c = slave["position"][long_axis] - origin[long_axis]
    mat_s, mat_b = sphere["material"], beam["material"]
    return {
        "scene": os.path.relpath(os.path.abspath(scene_path), ROOT),
        "beam_model": os.path.relpath(os.path.join(folder, target["model"]), ROOT),
        "sphere_model": os.path.relpath(os.path.join(folder, slave["model"]), ROOT),
        "E_b": mat_b["youngs_modulus"], "nu_b": mat_b["poisson_ratio"], "rho_b": mat_b["density"],
        "L": size[long_axis], "h": size[axis], "b": size[width_axis],
        "E_s": mat_s["youngs_modulus"], "nu_s": mat_s["poisson_ratio"], "rho_s": mat_s["density"],
        "R": radius, "m_s": mat_s["density"] * 4.0 / 3.0 * math.pi * radius ** 3,
        "v0": abs(velocity[axis]), "x_c": x_c,
        "gap_m": abs(slave["position"][axis] - radius - (origin[axis] + size[axis])),
        "across_m": slave["position"][width_axis] - origin[width_axis],
    }


def hertz_half_space(case):
    e_star = 1.0 / ((1 - case["nu_s"] ** 2) / case["E_s"] + (1 - case["nu_b"] ** 2) / case["E_b"])
    K = 4.0 / 3.0 * e_star * math.sqrt(case["R"])
    dmax = (5.0 * case["m_s"] * case["v0"] ** 2 / (4.0 * K)) ** 0.4
    return {"E_star": e_star, "K": K, "delta_max_m": dmax, "peak_force_n": K * dmax ** 1.5,
            "duration_s": TC_FACTOR * dmax / case["v0"], "a_max_m": math.sqrt(case["R"] * dmax)}


def contact_radius_m(case, F):
    """Hertz's contact radius of the force F between the sphere and a half-space of the beam's
    material [m]."""
    return (3 * F * case["R"] / (4 * hertz_half_space(case)["E_star"])) ** (1 / 3)


# ------------------------------------------------------------------------ Timoshenko beam
def cowper_kappa(nu):
    return 10.0 * (1 + nu) / (12 + 11 * nu)


def gll_basis(p, points):
    """Lagrange basis of degree p on the Gauss-Lobatto-Legendre nodes of [-1, 1]: values and
    derivatives at `points` (rows: points, columns: nodes)."""
    inner = np.polynomial.legendre.Legendre.basis(p).deriv().roots() if p > 1 else np.array([])
    nodes = np.concatenate([[-1.0], np.sort(inner.real), [1.0]])
    V = np.zeros((len(points), p + 1))
    D = np.zeros((len(points), p + 1))
    for j in range(p + 1):
        others = np.delete(nodes, j)
        poly = np.polynomial.Polynomial.fromroots(others) / np.prod(nodes[j] - others)
        V[:, j], D[:, j] = poly(points), poly.deriv()(points)
    return nodes, V, D


def element(Le, p, E, G, kappa, rho, A, I):
    """Stiffness and consistent mass of a Timoshenko element of degree p (the same Lagrange
    basis on GLL nodes for the deflection w and the section's rotation theta; shear strain
    w' - theta), Gauss with p + 2 points (exact for both). Dofs (w_0, theta_0, ..., w_p, theta_p)."""
    gx, gw = np.polynomial.legendre.leggauss(p + 2)
    _, V, D = gll_basis(p, gx)
    J = Le / 2.0
    D = D / J
    n = 2 * (p + 1)
    Bw, Bt = np.zeros((len(gx), n)), np.zeros((len(gx), n))
    dBw, dBt = np.zeros((len(gx), n)), np.zeros((len(gx), n))
    Bw[:, 0::2], Bt[:, 1::2], dBw[:, 0::2], dBt[:, 1::2] = V, V, D, D
    gamma = dBw - Bt
    W = gw * J
    K = E * I * dBt.T @ (W[:, None] * dBt) + kappa * G * A * gamma.T @ (W[:, None] * gamma)
    M = rho * A * Bw.T @ (W[:, None] * Bw) + rho * I * Bt.T @ (W[:, None] * Bt)
    return K, M


class Beam:
    """FE model of the free-free beam: n_elem elements of degree p, a node at x_c."""

    def __init__(self, case, n_elem, p=5, kappa=None):
        E, nu, rho = case["E_b"], case["nu_b"], case["rho_b"]
        L, h, b = case["L"], case["h"], case["b"]
        self.kappa = cowper_kappa(nu) if kappa is None else kappa
        G = E / (2 * (1 + nu))
        A, I = b * h, b * h ** 3 / 12
        self.E, self.G, self.A, self.I, self.rho, self.L = E, G, A, I, rho, L
        self.mass = rho * A * L
        self.n_elem, self.p = n_elem, p
        n1 = max(1, int(round(n_elem * case["x_c"] / L)))
        ends = np.concatenate([np.linspace(0, case["x_c"], n1 + 1), np.linspace(case["x_c"], L, n_elem - n1 + 1)[1:]])
        gll, _, _ = gll_basis(p, np.zeros(1))
        x = [0.0]
        for e in range(n_elem):
            x.extend(ends[e] + (ends[e + 1] - ends[e]) * (gll[1:] + 1) / 2)
        x = np.array(x)
        self.x, self.ic = x, n1 * p                  # node n1 p is the impact point
        n = 2 * len(x)
        K, M = np.zeros((n, n)), np.zeros((n, n))
        cache = {}
        for e in range(n_elem):
            Le = ends[e + 1] - ends[e]
            key = round(Le, 15)
            if key not in cache:
                cache[key] = element(Le, p, E, G, self.kappa, rho, A, I)
            Ke, Me = cache[key]
            s = slice(2 * p * e, 2 * p * e + 2 * (p + 1))
            K[s, s] += Ke
            M[s, s] += Me
        self.K, self.M = K, M
        # exact rigid-body modes: translation and rotation about the centre of mass
        t = np.zeros(n)
        t[0::2] = 1
        r = np.zeros(n)
        r[0::2], r[1::2] = x - L / 2, 1
        rigid = np.column_stack([t, r])
        rigid /= np.sqrt(np.einsum("ij,jk,ki->i", rigid.T, M, rigid))
        assert abs(rigid[:, 0] @ M @ rigid[:, 1]) < 1e-12 and np.abs(K @ rigid).max() < 1e-6 * np.abs(K).max()
        assert abs(1 / rigid[0, 0] ** 2 - self.mass) < 1e-12 * self.mass
        self.rigid = rigid
        self.dof_c = 2 * self.ic
        assert abs(x[self.ic] - case["x_c"]) < 1e-15

    def modes(self, f_max_hz=None, count=None):
        """Elastic modes: (frequencies [Hz], mass-normalized shapes), ascending, the first
        `count` or those below f_max_hz."""
        if count is not None:
            vals, vecs = linalg.eigh(self.K, self.M, subset_by_index=[0, count + 1])
        else:
            vals, vecs = linalg.eigh(self.K, self.M, subset_by_value=[-np.inf, (2 * math.pi * f_max_hz) ** 2])
        vals, vecs = vals[2:], vecs[:, 2:]            # the two rigid-body modes (zero) are put in exactly
        vecs -= self.rigid @ (self.rigid.T @ (self.M @ vecs))
        vecs /= np.sqrt(np.einsum("ij,jk,ki->i", vecs.T, self.M, vecs))
        return np.sqrt(np.maximum(vals, 0)) / (2 * math.pi), vecs

    def contact_vector(self, anticlastic=0.0):
        """Observation (= load) vector of the contact point: w(x_c), plus `anticlastic` times
        the bending curvature theta'(x_c) (the mean of the two elements' values there)."""
        n = self.K.shape[0]
        g = np.zeros(n)
        g[self.dof_c] = 1.0
        if anticlastic:
            p = self.p
            _, _, D = gll_basis(p, np.array([-1.0, 1.0]))
            e_right = self.ic // p
            for e, row in ((e_right - 1, 1), (e_right, 0)):       # left element's end, right element's start
                Le = self.x[(e + 1) * p] - self.x[e * p]
                g[2 * p * e + 1:2 * p * e + 2 * (p + 1):2] += 0.5 * anticlastic * D[row] * 2.0 / Le
        return g

    def flexibility(self, g, observe=None):
        """Inertia-relief flexibility g^T K^+ g: the elastic response (no rigid content) to the
        load g balanced by the rigid-body inertia, observed by g (or by `observe`)."""
        n = self.K.shape[0]
        f = g - self.M @ (self.rigid @ (self.rigid.T @ g))      # self-equilibrated load
        keep = np.setdiff1d(np.arange(n), [0, n - 2])          # w held at both ends (statically determinate)
        u = np.zeros(n)
        u[keep] = linalg.solve(self.K[np.ix_(keep, keep)], f[keep], assume_a="sym")
        u -= self.rigid @ (self.rigid.T @ (self.M @ u))
        return (g if observe is None else observe) @ u


def euler_bernoulli(case, count):
    """Free-free Euler-Bernoulli frequencies, cos(bL) cosh(bL) = 1."""
    E, rho, L, h = case["E_b"], case["rho_b"], case["L"], case["h"]
    c = math.sqrt(E * h * h / 12 / rho)
    out = []
    for n in range(1, count + 1):
        z = (n + 0.5) * math.pi
        g = lambda bl: math.cos(bl) - 1.0 / math.cosh(bl)
        bl = optimize.brentq(g, z - 0.3, z + 0.3, xtol=1e-15)
        out.append(bl * bl / (2 * math.pi * L * L) * c)
    return np.array(out)


# --------------------------------------------------------------------------------- impact
class ContactLaw:
    """Approach s = u_s - w(x_c) = delta_H + C F, F = K delta_H^1.5: Hertz in series with a
    linear compliance C (the static correction of the truncated modes, plus any extra)."""

    def __init__(self, K, C):
        self.K, self.C = K, C

    def delta_h(self, s):
        if s <= 0:
            return 0.0
        if self.C == 0:
            return s
        K, C = self.K, self.C
        d = s if C > 0 else 0.0          # monotone Newton from the convex / concave side
        for _ in range(60):
            r = math.sqrt(d)
            g = d + C * K * d * r - s
            step = g / (1 + 1.5 * C * K * r)
            d -= step
            if abs(step) <= 1e-16 * s:
                break
        return d

    def force(self, s):
        d = self.delta_h(s)
        return self.K * d ** 1.5

    def energy(self, s):
        d = self.delta_h(s)
        F = self.K * d ** 1.5
        return 0.4 * self.K * d ** 2.5 + 0.5 * self.C * F * F


def simulate(case, beam, f_cut_hz, rtol=1e-10, static_correction=True, extra_compliance=0.0, anticlastic=0.0,
             end_time=500e-6, frequency_override=None, modes=None):
    """The impact with the elastic modes below f_cut_hz (plus the rigid translation).
    extra_compliance: a linear compliance in series with Hertz (m/N); anticlastic: the
    contact point moves by w + anticlastic theta' instead of w (m^2); frequency_override:
    {mode index (0 = 1F): f [Hz]} replaces those frequencies. The last three are the
    sensitivity runs of the bracket. Returns the results at the release."""
    hz = hertz_half_space(case)
    freqs, vecs = beam.modes(f_max_hz=f_cut_hz) if modes is None else modes
    g = beam.contact_vector(anticlastic)
    phi_all = g @ vecs
    excited = np.abs(vecs[beam.dof_c]) > 1e-9 * np.abs(vecs[beam.dof_c]).max()   # symmetric modes (central impact)
    omega_all = 2 * math.pi * freqs
    if frequency_override:
        omega_all = omega_all.copy()
        for k, f in frequency_override.items():
            omega_all[k] = 2 * math.pi * f
    c_res = 0.0
    if static_correction:
        c_res = beam.flexibility(g) - np.sum(phi_all[excited] ** 2 / (2 * math.pi * freqs[excited]) ** 2)
    law = ContactLaw(hz["K"], c_res + extra_compliance)
    phi_t = g @ beam.rigid[:, 0]                                    # rigid translation, omega 0
    phi = np.concatenate([[phi_t], phi_all[excited]])
    w2 = np.concatenate([[0.0], omega_all[excited] ** 2])
    n = len(phi)
    ms, v0 = case["m_s"], case["v0"]
    E0 = 0.5 * ms * v0 * v0

    def rhs(t, y):
        F = law.force(y[0] - phi @ y[2:2 + n])
        out = np.empty_like(y)
        out[0], out[1] = y[1], -F / ms
        out[2:2 + n] = y[2 + n:]
        out[2 + n:] = -w2 * y[2:2 + n] + phi * F
        return out

    def released(t, y):
        return y[0] - phi @ y[2:2 + n]
    released.terminal, released.direction = True, -1

    def turning(t, y):
        return y[1] - phi @ y[2 + n:]
    turning.direction = -1

    # scaled absolute tolerances: displacements ~ delta_max, velocities ~ v0
    tc = hz["duration_s"]
    amp_v = math.sqrt(2 * E0)
    amp_q = np.where(w2 > 0, amp_v / np.sqrt(np.maximum(w2, 1e-300)), amp_v * tc)
    atol = rtol * np.concatenate([[hz["delta_max_m"], v0], amp_q, np.full(n, amp_v)])
    y0 = np.zeros(2 + 2 * n)
    y0[1] = v0
    t0 = time.process_time()
    sol = solve_ivp(rhs, (0.0, 4 * tc), y0, method="DOP853", rtol=rtol, atol=atol, events=[released, turning],
                    dense_output=True)
    cpu = time.process_time() - t0
    if sol.status != 1:
        raise RuntimeError("no release within 4 Hertz contact times")
    t_end, y_end = sol.t_events[0][0], sol.y_events[0][0]
    peaks = [(t, law.force(y[0] - phi @ y[2:2 + n]), y) for t, y in zip(sol.t_events[1], sol.y_events[1])]
    t_peak, peak, y_peak = max(peaks, key=lambda p: p[1])
    # bending moment under the sphere at the peak: M = -EI theta'(x_c) (sagging positive), the
    # truncated modes' static part included
    curv = beam.contact_vector(1.0) - beam.contact_vector(0.0)
    curv_modes = (curv @ vecs)[excited]
    c_curv = beam.flexibility(g, curv) - np.sum(curv_modes * phi_all[excited] / (2 * math.pi * freqs[excited]) ** 2) \
        if static_correction else 0.0
    moment_peak = -beam.E * beam.I * (curv_modes @ y_peak[3:2 + n] + c_curv * peak)
    # over the pulse: the least-squares ratio M ~ r F (force-weighted)
    ts = np.linspace(0.0, t_end, 801)[1:-1]
    ys = sol.sol(ts)
    Fs = np.array([law.force(s_) for s_ in ys[0] - phi @ ys[2:2 + n]])
    Ms = -beam.E * beam.I * (curv_modes @ ys[3:2 + n] + c_curv * Fs)
    moment_ratio_ls = float(np.sum(Ms * Fs) / np.sum(Fs * Fs))
    # conservation at the release
    q, qd = y_end[2:2 + n], y_end[2 + n:]
    energy = 0.5 * ms * y_end[1] ** 2 + 0.5 * np.sum(qd ** 2 + w2 * q ** 2) + law.energy(y_end[0] - phi @ q)
    momentum = ms * y_end[1] + qd[0] / phi_t            # sqrt(m_beam) q0' = m_beam v_beam
    # free motion after the release: does the sphere touch again before end_time?
    tau = np.arange(0.0, end_time - t_end, 0.01e-6)
    us = y_end[0] + y_end[1] * tau
    w = phi[0] * (q[0] + qd[0] * tau)
    omega = np.sqrt(w2[1:])
    for k in range(1, n):
        w = w + phi[k] * (q[k] * np.cos(omega[k - 1] * tau) + qd[k] / omega[k - 1] * np.sin(omega[k - 1] * tau))
    gap = w - us                                          # > 0: apart
    recontact = tau[np.argmax(gap[1:] <= 0) + 1] + t_end if np.any(gap[1:] <= 0) else None
    # per-mode report
    v_sep = y_end[1]
    modes_out = []
    qd_all = np.zeros(len(freqs))
    q_all = np.zeros(len(freqs))
    qd_all[excited], q_all[excited] = qd[1:], q[1:]
    for k in range(len(freqs)):
        e_k = 0.5 * (qd_all[k] ** 2 + omega_all[k] ** 2 * q_all[k] ** 2)
        r_k = -(v_sep - phi_all[k] * qd_all[k]) / v0
        modes_out.append({"label": f"{k + 1}F", "frequency_hz": omega_all[k] / (2 * math.pi),
                          "energy_ratio": e_k / E0, "restitution": r_k})
    beam_rigid = 0.5 * qd[0] ** 2 / E0
    return {
        "peak_force_n": peak, "peak_time_s": t_peak, "force_maxima": len(peaks), "duration_s": t_end,
        "moment_at_peak_n_m": moment_peak, "moment_over_force_ls_m": moment_ratio_ls,
        "rebound_m_s": -v_sep, "modes": modes_out,
        "beam_mode_energy": sum(m["energy_ratio"] for m in modes_out), "beam_rigid_energy": beam_rigid,
        "beam_mode_energy_below_70khz": sum(m["energy_ratio"] for m in modes_out if m["frequency_hz"] < 70e3),
        "sphere_energy": 0.5 * ms * v_sep ** 2 / E0,
        "energy_error": abs(energy - E0) / E0, "momentum_error": abs(momentum - ms * v0) / (ms * v0),
        "impulse_n_s": ms * (v0 - v_sep), "recontact_s": recontact, "min_gap_after_m": float(gap[1:].min()),
        "max_gap_checked_s": end_time,
        "modes_integrated": n - 1, "modes_below_cut": len(freqs), "c_res_m_n": c_res, "extra_compliance_m_n": extra_compliance,
        "steps": len(sol.t) - 1, "rhs": sol.nfev, "cpu_s": cpu, "f_cut_hz": f_cut_hz, "rtol": rtol,
        "static_correction": static_correction,
    }


KEYS = ["peak_force_n", "duration_s", "rebound_m_s"]
ODD = ["1F", "3F", "5F", "7F", "9F"]


def energy_of(r, label):
    return next(m["energy_ratio"] for m in r["modes"] if m["label"] == label)


def row(r):
    return [r["peak_force_n"], r["duration_s"] * 1e6, r["rebound_m_s"]] + [energy_of(r, m) for m in ODD] + [r["beam_mode_energy"]]


ROW_HEAD = "| peak force [N] | duration [us] | rebound [m/s] | " + " | ".join(f"E_{m}/E_0" for m in ODD) + " | all modes |"
ROW_FMT = ["{:.4f}", "{:.5f}", "{:.6f}"] + ["{:.6f}"] * 5 + ["{:.6f}"]


def fmt_row(values):
    return " | ".join(f.format(v) for f, v in zip(ROW_FMT, values))


def rel_change(a, b):
    """Largest relative change between two result rows (energies relative to themselves)."""
    return max(abs(x - y) / abs(y) for x, y in zip(a, b))


# ------------------------------------------------------------------- bracket: side calculations
def sphere_compliance(case, csv_path):
    """The finite sphere's approach deficit against Hertz's half-space, C_s = d(delta)/dF < 0:
    from finite_sphere.py's CalculiX law of a sphere on a rigid plane (centre-of-mass
    approach delta, and delta_hertz), fitted as delta = delta_hertz + c F / (E R) (the
    regular part of the sphere's field: linear in F by dimensional analysis) and scaled to
    this sphere (same nu required)."""
    meta, rows = {}, []
    with open(csv_path) as f:
        for line in f:
            if line.startswith("#"):
                for tok in line[1:].split():
                    if "=" in tok:
                        k, v = tok.split("=", 1)
                        meta.setdefault(k, v)
            elif line[0].isdigit():
                rows.append([float(v) for v in line.split(",")[:3]])
    rows = np.array(rows)
    E, nu, R = float(meta["E_pa"]), float(meta["nu"]), float(meta["radius_m"])
    if abs(nu - case["nu_s"]) > 1e-12:
        raise SystemExit(f"{csv_path}: nu {nu} is not the sphere's {case['nu_s']}")
    F, deficit = rows[:, 0], rows[:, 2] - rows[:, 1]
    C = np.sum(F * deficit) / np.sum(F * F)
    c = C * E * R
    spread = np.abs(deficit / F / C - 1)
    top = F >= 0.25 * F.max()                 # the linear fit is the regular part; the first points carry the mesh's round-off
    return {"c": c, "C_m_n": -c / (case["E_s"] * case["R"]), "fit_spread_upper": float(spread[top].max()),
            "fit_spread_all": float(spread.max()), "csv": os.path.relpath(csv_path, ROOT), "csv_radius_m": R,
            "points": len(F)}


# C3D20 (Abaqus/ccx order, as bench/beam_clamped_ccx): corners of the bottom face, of the top
# face, then mid-edges of the bottom face, the top face and the vertical edges; in half-cells
CORNERS = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)]
MIDS = [(1, 0, 0), (2, 1, 0), (1, 2, 0), (0, 1, 0), (1, 0, 2), (2, 1, 2), (1, 2, 2), (0, 1, 2),
        (0, 0, 1), (2, 0, 1), (2, 2, 1), (0, 2, 1)]


def graded(length, s0, growth, smax, must=()):
    """Grid lines on [0, length] from the fine end 0: sizes s0 growth^k up to smax, the last
    one stretched to end at length; the nearest lines moved onto the distances in `must`."""
    xs, s = [0.0], s0
    while xs[-1] < length - 1e-12:
        xs.append(xs[-1] + s)
        s = min(s * growth, smax)
    if len(xs) > 2 and xs[-1] - length > 0.5 * (xs[-1] - xs[-2]):
        xs.pop()
    xs[-1] = length
    xs = np.array(xs)
    for m in must:
        xs[int(np.argmin(np.abs(xs - m)))] = m
    return np.unique(xs)


def serendipity_face(n_sub=6, n_gauss=4):
    """Quadrature of an 8-node face on [-1, 1]^2 (n_sub^2 cells of n_gauss^2 points: the Hertz
    pressure's square-root edge): points, weights, shape values (points x 8), the nodes
    ordered as the corners (-1,-1), (1,-1), (1,1), (-1,1), then the mid-sides (0,-1), (1,0), (0,1), (-1,0)."""
    g, w = np.polynomial.legendre.leggauss(n_gauss)
    edges = np.linspace(-1, 1, n_sub + 1)
    pts = np.array([(edges[i] + (a + 1) / n_sub, edges[j] + (c + 1) / n_sub)
                    for i in range(n_sub) for j in range(n_sub) for a in g for c in g])
    wts = np.array([wa * wc / n_sub ** 2 for i in range(n_sub) for j in range(n_sub) for wa in w for wc in w])
    xi, eta = pts[:, 0], pts[:, 1]
    N = [(1 + a * xi) * (1 + b * eta) * (a * xi + b * eta - 1) / 4 for a, b in [(-1, -1), (1, -1), (1, 1), (-1, 1)]]
    N += [(1 - xi ** 2) * (1 - eta) / 2, (1 + xi) * (1 - eta ** 2) / 2, (1 - xi ** 2) * (1 + eta) / 2, (1 - xi) * (1 - eta ** 2) / 2]
    return pts, wts, np.array(N).T


class QuarterBeam:
    """Structured C3D20 grid of the beam's quarter (mm): x in [0, L/2] (x = L/2 the impact
    section, a symmetry plane), y in [0, h] (y = h the impacted face), z in [0, b/2] (z = b/2
    the symmetry plane through the impact point)."""

    def __init__(self, X, Y, Z):
        self.lines = [X, Y, Z]
        self.half = [np.concatenate([np.ravel(np.column_stack([l[:-1], 0.5 * (l[:-1] + l[1:])])), [l[-1]]]) for l in self.lines]
        self.node_id, self.els = {}, []
        self.n = [len(X) - 1, len(Y) - 1, len(Z) - 1]
        for i in range(self.n[0]):
            for j in range(self.n[1]):
                for k in range(self.n[2]):
                    self.els.append([self.node_id.setdefault((2 * i + o[0], 2 * j + o[1], 2 * k + o[2]), len(self.node_id) + 1)
                                     for o in CORNERS + MIDS])

    def nodes_on(self, axis, index2):
        return [nid for key, nid in self.node_id.items() if key[axis] == index2]

    def face_integral(self, axis, index2, density):
        """{node: integral of N_node * density(u, v)} over the grid face key[axis] == index2
        (u, v its two coordinates in increasing axis order): consistent nodal loads."""
        pts, wts, N = serendipity_face()
        a1, a2 = [a for a in range(3) if a != axis]
        L1, L2 = self.lines[a1], self.lines[a2]
        offsets = [(0, 0), (2, 0), (2, 2), (0, 2), (1, 0), (2, 1), (1, 2), (0, 1)]
        out = {}
        for i in range(len(L1) - 1):
            for j in range(len(L2) - 1):
                u = L1[i] + (pts[:, 0] + 1) / 2 * (L1[i + 1] - L1[i])
                v = L2[j] + (pts[:, 1] + 1) / 2 * (L2[j + 1] - L2[j])
                p = density(u, v)
                if not np.any(p):
                    continue
                f = N.T @ (wts * p) * (L1[i + 1] - L1[i]) * (L2[j + 1] - L2[j]) / 4
                for (o1, o2), fi in zip(offsets, f):
                    key = [0, 0, 0]
                    key[axis], key[a1], key[a2] = index2, 2 * i + o1, 2 * j + o2
                    nid = self.node_id[tuple(key)]
                    out[nid] = out.get(nid, 0.0) + fi
        return out

    def write(self, path, E, nu, rho, body):
        with open(path, "w") as f:
            f.write("*NODE, NSET=NALL\n")
            for key, nid in sorted(self.node_id.items(), key=lambda kv: kv[1]):
                f.write(f"{nid}, " + ", ".join(f"{self.half[a][key[a]]:.12g}" for a in range(3)) + "\n")
            f.write("*ELEMENT, TYPE=C3D20, ELSET=EALL\n")
            for e, ids in enumerate(self.els):
                f.write(f"{e + 1}, " + ", ".join(map(str, ids[:15])) + ",\n" + ", ".join(map(str, ids[15:])) + "\n")
            # mm, N, t: E in MPa, density in t/mm^3
            f.write(f"*MATERIAL, NAME=STEEL\n*ELASTIC\n{E * 1e-6:.12g}, {nu}\n*DENSITY\n{rho * 1e-12:.12g}\n"
                    "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n")
            f.write(body)


def quarter_mesh(case, s0, growth, smax_x, smax_yz, x_must=()):
    """The quarter beam graded toward the impact point (mm): smallest element s0, growing by
    `growth` up to smax_x along the beam and smax_yz across; a grid line at half the height
    (the pinned node's) and at the distances `x_must` from the impact section."""
    L, h, b = case["L"] * 1e3, case["h"] * 1e3, case["b"] * 1e3
    X = L / 2 - graded(L / 2, s0, growth, smax_x, must=x_must)[::-1]
    Y = h - graded(h, s0, growth, smax_yz, must=(h / 2,))[::-1]
    Z = b / 2 - graded(b / 2, s0, growth, smax_yz)[::-1]
    return QuarterBeam(X, Y, Z)


def hertz_face_loads(case, q, F):
    """Consistent nodal loads (N, downward) of the quarter of Hertz's pressure of the force F
    (p0 sqrt(1 - r^2/a^2), a of the two bodies' E*) on the impacted face of the quarter beam q."""
    L, b = case["L"] * 1e3, case["b"] * 1e3
    a = contact_radius_m(case, F) * 1e3
    p0 = 3 * F / (2 * math.pi * a * a)
    p = lambda u, v: p0 * np.sqrt(np.clip(1 - ((u - L / 2) ** 2 + (v - b / 2) ** 2) / a ** 2, 0, None))
    loads = q.face_integral(1, 2 * q.n[1], p)
    total = sum(loads.values())
    if total <= 0:          # a contact radius below the quadrature's spacing: the force at the centre
        return {q.node_id[(2 * q.n[0], 2 * q.n[1], 2 * q.n[2])]: F / 4}
    return {n: f * (F / 4) / total for n, f in loads.items()}     # the square-root edge's quadrature: exact total


def remove_run_folder(folder, keep):
    """Removes a CalculiX run's temporary folder, unless it is the caller's `keep` folder."""
    if keep is None:
        for name in os.listdir(folder):
            os.remove(os.path.join(folder, name))
        os.rmdir(folder)


def ccx_number(x):
    """x for a CalculiX input field: ccx reads at most 20 characters of a field, so a longer
    number is cut (-5.84829232448421e-07 would be read as -5.84829232448421e-0); 13 significant
    digits in exponent form fit, sign and three-digit exponent included."""
    return f"{x:.12e}"


def ccx_displacements(dat_text):
    """The displacement blocks of a CalculiX .dat text (*NODE PRINT U, one per step or mode), in
    order: [{node: (ux, uy, uz)}] in the file's units."""
    blocks = []
    for block in dat_text.split("displacements (vx,vy,vz)")[1:]:
        U = {}
        for line in block.splitlines()[1:]:
            parts = line.split()
            if len(parts) == 4 and parts[0].isdigit():
                U[int(parts[0])] = tuple(float(v) for v in parts[1:])
            elif U and line.strip():
                break
        blocks.append(U)
    return blocks


def ccx_frequencies(dat_text):
    """The eigenfrequencies [Hz] of a CalculiX *FREQUENCY step, from its .dat text, in order."""
    freqs = []
    for row_ in dat_text.split("E I G E N V A L U E   O U T P U T")[1].splitlines():
        parts = row_.split()
        if len(parts) >= 4 and parts[0].isdigit():
            freqs.append(float(parts[3]))
        elif freqs and row_.strip() == "":
            break
    return freqs


def ccx_set(kind, name, ids):
    ids = list(ids)
    return f"*{kind}, {kind}={name}\n" + "".join(", ".join(map(str, ids[i:i + 12])) + ",\n" for i in range(0, len(ids), 12))


def run_ccx(q, stem, body, E, nu, rho, keep):
    """Writes the quarter beam `q` with the CalculiX input `body` as <folder>/<stem>.inp (folder:
    `keep`, or a fresh temporary one), runs ccx on one thread and returns (folder, path, wall s)."""
    folder = keep or tempfile.mkdtemp(prefix="timoshenko_hertz_")
    path = os.path.join(folder, stem + ".inp")
    q.write(path, E, nu, rho, body)
    t0 = time.time()
    run = subprocess.run(["ccx", "-i", stem], cwd=folder, capture_output=True, text=True,
                         env=dict(os.environ, OMP_NUM_THREADS="1"))
    wall = time.time() - t0
    if run.returncode != 0 or not os.path.exists(path[:-4] + ".dat"):
        raise RuntimeError(f"ccx failed in {folder}: {run.stdout[-1500:]}{run.stderr[-500:]}")
    return folder, path, wall


def timoshenko_static(case, kappa, F, slab=0.0):
    """Static Timoshenko beam, free-free, centric load F (a point load, or spread evenly over
    |x - x_c| < slab) balanced by the inertia relief F / L: the deflection of the impact
    section relative to the end section, and the bending moment there (closed-form integrals
    over the half beam; a centric impact)."""
    E, nu, L, h, b = case["E_b"], case["nu_b"], case["L"], case["h"], case["b"]
    G, A, I = E / (2 * (1 + nu)), b * h, b * h ** 3 / 12
    q0, c = F / L, L / 2
    # shear V(t) = q0 t - P(t), moment M(t) = q0 t^2/2 - intP(t), P(t) the load from the end to t
    if slab > 0:
        p = F / (2 * slab)
        intP = lambda t: p * max(0.0, t - (c - slab)) ** 2 / 2
    else:
        intP = lambda t: 0.0
    # int_0^c t M dt = q0 c^4/8 - int_0^c t intP(t) dt; int_0^c V dt = q0 c^2/2 - int_0^c P dt
    t_int = (p * (slab ** 4 / 8 + (c - slab) * slab ** 3 / 6)) if slab > 0 else 0.0   # int t (t-c+s)^2/2 p dt
    bend = (q0 * c ** 4 / 8 - t_int) / (E * I)
    shear = (q0 * c * c / 2 - (F / 2 * slab / 2 if slab > 0 else 0.0)) / (kappa * G * A)
    return {"deflection_m": bend + shear, "bending_m": bend, "shear_m": shear, "moment_n_m": q0 * c * c / 2 - intP(c)}


def beam_local_fe(case, kappa, F, s0_over_a, growth, smax_x=4e-3, smax_yz=2e-3, slab=5e-3, keep=None):
    """The beam's local compliance against Timoshenko + Hertz's half-space, by a static 3D
    CalculiX model of the quarter beam under inertia relief (body force F / V upward) and:
    A: the Hertz pressure of the force F (p0 sqrt(1 - r^2/a^2), a of the two bodies' E*) at the
       impact point; B: the same force as a body force over the slab |x - x_c| < slab.
    A - B is a self-equilibrated local load: the beam-theory parts of both (Timoshenko's
    deflections, the Saint-Venant anticlastic offset of the top face nu (2 h^2 + b^2)/24 M/EI)
    and the half-space's pressure-weighted approach of the beam's side (0.8 of its centre
    value) are taken out; what is left is the local correction C_b F. Lengths in mm for ccx."""
    E, nu, rho = case["E_b"], case["nu_b"], case["rho_b"]
    L, h, b = case["L"] * 1e3, case["h"] * 1e3, case["b"] * 1e3
    a = contact_radius_m(case, F) * 1e3
    p0 = 3 * F / (2 * math.pi * a * a)
    s0, sl = a * s0_over_a, slab * 1e3
    q = quarter_mesh(case, s0, growth, smax_x * 1e3, smax_yz * 1e3, x_must=(sl,))
    X, Y, _ = q.lines
    nx, ny, nz = q.n
    loads = hertz_face_loads(case, q, F)
    ones = lambda u, v: np.ones_like(u)
    w_end, w_mid = q.face_integral(0, 0, ones), q.face_integral(0, 2 * nx, ones)
    rho_mm = rho * 1e-12
    g_relief, g_slab = F / (rho_mm * L * h * b), F / (rho_mm * 2 * sl * h * b)
    ix = int(np.argmin(np.abs(X - (L / 2 - sl))))
    slab_els = [e + 1 for e in range(len(q.els)) if e // (ny * nz) >= ix]
    rest_els = [e + 1 for e in range(len(q.els)) if e // (ny * nz) < ix]
    iy = int(np.argmin(np.abs(Y - h / 2)))
    n_fix, n_top = q.node_id[(0, 2 * iy, 2 * nz)], q.node_id[(2 * nx, 2 * ny, 2 * nz)]
    axis_nodes = [(Y[-1] - q.half[1][j], q.node_id[(2 * nx, j, 2 * nz)]) for j in range(2 * ny, -1, -1)]
    out_nodes = sorted(set(loads) | set(w_end) | set(w_mid) | {n for _, n in axis_nodes})
    body = (ccx_set("NSET", "NXSYM", q.nodes_on(0, 2 * nx)) + ccx_set("NSET", "NZSYM", q.nodes_on(2, 2 * nz))
            + ccx_set("NSET", "NFIX", [n_fix]) + ccx_set("NSET", "NOUT", out_nodes)
            + ccx_set("ELSET", "ESLAB", slab_els) + ccx_set("ELSET", "EREST", rest_els)
            + "*BOUNDARY\nNXSYM, 1, 1\nNZSYM, 3, 3\nNFIX, 2, 2\n"
            + "*STEP\n*STATIC\n*CLOAD\n" + "".join(f"{n}, 2, {ccx_number(-f)}\n" for n, f in loads.items())
            + f"*DLOAD\nEALL, GRAV, {ccx_number(g_relief)}, 0., 1., 0.\n*NODE PRINT, NSET=NOUT\nU\n*END STEP\n"
            + "*STEP\n*STATIC\n*CLOAD, OP=NEW\n*DLOAD, OP=NEW\n"
            + f"EREST, GRAV, {ccx_number(g_relief)}, 0., 1., 0.\nESLAB, GRAV, {ccx_number(g_slab - g_relief)}, 0., -1., 0.\n"
            + "*NODE PRINT, NSET=NOUT\nU\n*END STEP\n")
    folder, path, wall = run_ccx(q, "beam_local", body, E, nu, rho, keep)
    # downward, m
    steps = [{n: -u[1] * 1e-3 for n, u in U.items()} for U in ccx_displacements(open(path[:-4] + ".dat").read())]
    remove_run_folder(folder, keep)
    mean = lambda U, w: sum(w[n] * U[n] for n in w) / sum(w.values())
    UA, UB = steps
    # under the contact, down the axis: the pressure-weighted approach minus the displacement at
    # depth d, against the half-space's (Boussinesq over the Hertz pressure)
    G = E / (2 * (1 + nu))
    lw = mean(UA, loads)
    axis_fe, axis_hs = [], []
    for d, nid in axis_nodes:
        axis_fe.append(lw - UA[nid])
        axis_hs.append(None if d == 0 else half_space_axis(p0 * 1e6, a * 1e-3, G, nu, d * 1e-3))
    A_lw, A_top, A_end = mean(UA, loads), UA[n_top], mean(UA, w_end)
    B_top, B_mid, B_end = UB[n_top], mean(UB, w_mid), mean(UB, w_end)
    tA, tB = timoshenko_static(case, kappa, F), timoshenko_static(case, kappa, F, slab)
    EI = case["E_b"] * case["b"] * case["h"] ** 3 / 12
    c_anti = case["nu_b"] * (2 * case["h"] ** 2 + case["b"] ** 2) / 24
    u0 = math.pi * p0 * a * (1 - nu * nu) / (2 * E * 1e-6) * 1e-3            # half-space, beam's side, centre [m]
    u_hs = 0.8 * u0                                                          # pressure-weighted
    measured = (A_lw - A_end) - (B_top - B_end)
    beam_theory = (tA["deflection_m"] - tB["deflection_m"]) - c_anti * (tA["moment_n_m"] - tB["moment_n_m"]) / EI
    return {
        "F_n": F, "a_m": a * 1e-3, "s0_m": s0 * 1e-3, "growth": growth, "elements": len(q.els), "nodes": len(q.node_id),
        "dofs": 3 * len(q.node_id), "ccx_wall_s": wall,
        "A_pressure_weighted_m": A_lw - A_end, "A_top_centre_m": A_top - A_end,
        "B_top_m": B_top - B_end, "B_section_mean_m": B_mid - B_end,
        "timoshenko_A_m": tA["deflection_m"], "timoshenko_B_m": tB["deflection_m"],
        "moment_A_n_m": tA["moment_n_m"], "moment_B_n_m": tB["moment_n_m"],
        "anticlastic_B_fe_m": B_top - B_mid, "anticlastic_B_formula_m": -c_anti * tB["moment_n_m"] / EI,
        "global_B_fe_minus_timoshenko_m": (B_mid - B_end) - tB["deflection_m"],
        "half_space_weighted_m": u_hs, "half_space_centre_m": u0,
        "centre_minus_weighted_fe_m": A_top - A_lw, "centre_minus_weighted_half_space_m": u0 - u_hs,
        "local_m": measured - beam_theory - u_hs, "C_b_m_n": (measured - beam_theory - u_hs) / F,
        "axis": [{"depth_m": d * 1e-3, "fe_m": fe, "half_space_m": None if hs is None else 0.8 * u0 - hs}
                 for (d, _), fe, hs in zip(axis_nodes, axis_fe, axis_hs)],
    }


def half_space_axis(p0, a, G, nu, z):
    """Downward displacement of a half-space on the axis at depth z under the Hertz pressure
    p0 sqrt(1 - r^2/a^2): Boussinesq's u_z = P / (4 pi G R) (2 (1 - nu) + z^2 / R^2) integrated
    (r = a sin t)."""
    from scipy.integrate import quad
    def integrand(t):
        r = a * math.sin(t)
        R = math.hypot(r, z)
        return p0 * math.cos(t) * (2 * (1 - nu) / R + z * z / R ** 3) / (4 * math.pi * G) * 2 * math.pi * r * a * math.cos(t)
    return quad(integrand, 0, math.pi / 2, epsabs=0, epsrel=1e-12, limit=200)[0]


def beam_modes_3d(case, size_x, n_y, n_z, count=14, keep=None):
    """Symmetric bending frequencies of the free-free beam in the impact plane (1F, 3F, 5F, ...)
    by a 3D CalculiX model of the quarter beam (C3D20, symmetry planes x = L/2: u_x = 0 and
    z = b/2: u_z = 0, otherwise free; the rigid translation along y is the zero mode): an
    independent view of the Timoshenko frequencies. A mode is a y-bending mode when u_y
    dominates along the beam's axis line."""
    E, nu, rho = case["E_b"], case["nu_b"], case["rho_b"]
    L, h, b = case["L"] * 1e3, case["h"] * 1e3, case["b"] * 1e3
    X = np.linspace(0, L / 2, int(round(L / 2 / (size_x * 1e3))) + 1)
    Y, Z = np.linspace(0, h, n_y + 1), np.linspace(0, b / 2, n_z + 1)
    q = QuarterBeam(X, Y, Z)
    nx, ny, nz = q.n
    line = [q.node_id[(i, ny if ny % 2 == 0 else 2 * (ny // 2), 2 * nz)] for i in range(2 * nx + 1)]
    body = (ccx_set("NSET", "NXSYM", q.nodes_on(0, 2 * nx)) + ccx_set("NSET", "NZSYM", q.nodes_on(2, 2 * nz))
            + ccx_set("NSET", "NLINE", line) + "*BOUNDARY\nNXSYM, 1, 1\nNZSYM, 3, 3\n"
            + f"*STEP\n*FREQUENCY\n{count + 1}, 1.0\n*NODE PRINT, NSET=NLINE\nU\n*END STEP\n")
    folder, path, wall = run_ccx(q, "beam_modes", body, E, nu, rho, keep)
    text = open(path[:-4] + ".dat").read()
    remove_run_folder(folder, keep)
    freqs = ccx_frequencies(text)
    bending = []
    for k, U in enumerate(ccx_displacements(text)):
        u = np.array(list(U.values()))
        if k < len(freqs) and freqs[k] > 1.0 and np.abs(u[:, 1]).max() > 2 * np.abs(u[:, 0]).max():
            bending.append(freqs[k])
    return {"frequencies_hz": {f"{2 * k + 1}F": f for k, f in enumerate(bending)}, "all_hz": freqs,
            "elements": len(q.els), "dofs": 3 * len(q.node_id), "ccx_wall_s": wall, "size_x_m": size_x, "n_y": n_y, "n_z": n_z}


# ------------------------------------------------------------------------------------ main
def pct(a, b):
    return 100.0 * (a / b - 1.0)


def effects(base, other):
    """Relative changes [%] of the reported quantities."""
    out = {k: pct(other[k], base[k]) for k in KEYS + ["beam_mode_energy"]}
    for mb, mo in zip(base["modes"][:N_BENDING], other["modes"][:N_BENDING]):
        if mb["energy_ratio"] > 1e-12:
            out["E_" + mb["label"]] = pct(mo["energy_ratio"], mb["energy_ratio"])
        out["r_" + mb["label"]] = pct(mo["restitution"], mb["restitution"])
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scene", default=os.path.join(ROOT, "models", "sphere_on_beam_free.scene.toml"))
    ap.add_argument("--json", default=os.path.join(HERE, "timoshenko_hertz_free.json"))
    ap.add_argument("--elements", type=int, default=40, help="beam elements of the reference run (degree 5)")
    ap.add_argument("--cutoff", type=float, default=800e3, help="modes retained below this frequency [Hz]")
    ap.add_argument("--rtol", type=float, default=1e-11)
    ap.add_argument("--no-ccx", action="store_true", help="skip the 3D CalculiX side calculation of the beam's local "
                    "compliance (the bracket then takes it from the JSON written before, if any)")
    ap.add_argument("--ccx-meshes", default="0.25:1.6,0.125:1.4",
                    help="s0/a:growth of the CalculiX meshes (smallest element over the contact radius, grading)")
    ap.add_argument("--sphere-law", default=os.path.join(HERE, "finite_sphere_steel_r5_v1.csv"))
    args = ap.parse_args()
    cpu0 = time.process_time()
    case = read_case(args.scene)
    hz = hertz_half_space(case)
    out = []
    p = out.append
    kappa = cowper_kappa(case["nu_b"])
    EI = case["E_b"] * case["b"] * case["h"] ** 3 / 12

    p("## Classical reference: Hertz contact on a Timoshenko beam, sphere on the free-free beam")
    p(f"`bench/reference/timoshenko_hertz.py` (numpy {np.__version__}, scipy {__import__('scipy').__version__}); inputs read from "
      f"{case['scene']}, {case['beam_model']} and {case['sphere_model']}. Machine-independent: no timing enters the values.")
    p("")
    p("| input | value |")
    p("|---|---|")
    p(f"| beam | {case['L'] * 1e3:g} x {case['h'] * 1e3:g} (impact direction) x {case['b'] * 1e3:g} mm, E {case['E_b'] / 1e9:g} GPa, "
      f"nu {case['nu_b']:g}, rho {case['rho_b']:g} kg/m^3, mass {case['rho_b'] * case['L'] * case['h'] * case['b'] * 1e3:.4f} g, "
      f"free-free; Timoshenko, kappa = 10(1+nu)/(12+11nu) = {kappa:.6f} |")
    p(f"| sphere | R {case['R'] * 1e3:g} mm, E {case['E_s'] / 1e9:g} GPa, nu {case['nu_s']:g}, rho {case['rho_s']:g} kg/m^3, "
      f"mass {case['m_s'] * 1e3:.5f} g (rigid except in Hertz's law) |")
    p(f"| impact | at x_c = {case['x_c'] * 1e3:g} mm (z = {case['across_m'] * 1e3:g} mm, the face's centre line), "
      f"v0 = {case['v0']:g} m/s, E_0 = {0.5 * case['m_s'] * case['v0'] ** 2 * 1e3:.6f} mJ |")
    p(f"| Hertz | E* = {hz['E_star'] / 1e9:.4f} GPa, K = 4/3 E* sqrt(R) = {hz['K']:.6e} N/m^1.5; on a half-space (immovable): "
      f"peak {hz['peak_force_n']:.2f} N, duration {hz['duration_s'] * 1e6:.3f} us, approach {hz['delta_max_m'] * 1e6:.3f} um, "
      f"contact radius {hz['a_max_m'] * 1e3:.4f} mm |")
    p("")

    # ---- 3D CalculiX side calculations: read back from the JSON when not run
    have_ccx = not args.no_ccx and shutil_which("ccx") is not None
    stored = {}
    if not have_ccx and os.path.exists(args.json):
        with open(args.json) as f:
            stored = json.load(f).get("side_calculations", {})
    modes3d = None
    if have_ccx:
        runs3d = [beam_modes_3d(case, sx, ny, nz) for sx, ny, nz in ((3e-3, 4, 2), (1.5e-3, 8, 4))]
        modes3d = {"runs": runs3d, "frequencies_hz": runs3d[-1]["frequencies_hz"],
                   "mesh_change": max(abs(runs3d[-1]["frequencies_hz"][k] / runs3d[-2]["frequencies_hz"][k] - 1)
                                      for k in runs3d[-1]["frequencies_hz"] if int(k[:-1]) <= N_BENDING)}
    elif stored.get("beam_modes_3d"):
        modes3d = dict(stored["beam_modes_3d"], note=f"read back from {os.path.relpath(args.json, ROOT)} (no ccx run)")
    f3d = modes3d["frequencies_hz"] if modes3d else {}

    # ---- frequencies
    eb = euler_bernoulli(case, N_FREQ)
    meshes = [5, 10, 20, 40, 80]
    freq = {}
    for n in meshes:
        f, _ = Beam(case, n).modes(count=N_FREQ)
        freq[n] = f[:N_FREQ]
    change = np.abs(freq[meshes[-1]] / freq[meshes[-2]] - 1)
    p("### Beam: bending frequencies in the impact plane")
    p("Timoshenko FE, degree-5 elements (w and theta on the same GLL basis), n elements; 'change' = |f(80) / f(40) - 1|. "
      "Euler-Bernoulli: free-free closed form. 3D: CalculiX C3D20, quarter beam (symmetric modes only), "
      + (f"{modes3d['runs'][-1]['size_x_m'] * 1e3:g} mm along, {modes3d['runs'][-1]['n_y']} x {modes3d['runs'][-1]['n_z']} "
         f"elements over the quarter section, 1F..9F change by at most {modes3d['mesh_change']:.1e} from the mesh twice as coarse"
         if modes3d and modes3d.get("runs") else "not run") + ". Project: bench/RESULTS.md (3D, MacNeal model of the beam at "
      "commit 5f7f634).")
    p("")
    p("| mode | " + " | ".join(f"n = {n} [Hz]" for n in meshes) + " | change | Euler-Bernoulli [Hz] | Timoshenko vs EB | "
      "3D CalculiX [Hz] | Timoshenko vs 3D | project [Hz] | project vs 3D |")
    p("|---|" + "---|" * (len(meshes) + 7))
    for k in range(N_FREQ):
        label = f"{k + 1}F"
        proj = PROJECT["MacNeal"]["frequency_hz"].get(label)
        f_3 = f3d.get(label)
        p(f"| {label} | " + " | ".join(f"{freq[n][k]:.4f}" for n in meshes) + f" | {change[k]:.1e} | {eb[k]:.2f} | "
          f"{pct(freq[meshes[-1]][k], eb[k]):+.2f} % | " + (f"{f_3:.2f} | {pct(freq[meshes[-1]][k], f_3):+.3f} % | " if f_3 else " | | ")
          + (f"{proj} | " + (f"{pct(proj, f_3):+.3f} % |" if f_3 else " |") if proj else " | |"))
    p("")
    freq_ok = change.max() < 1e-5

    # ---- impact convergence
    beam = Beam(case, args.elements)
    cut_list = [50e3, 100e3, 200e3, 400e3, 800e3, 1600e3]
    p("### Impact: convergence")
    p(f"{args.elements} elements of degree 5; DOP853 at rtol {args.rtol:g} unless stated. Plain: the modes below the cutoff alone; "
      f"corrected: plus the static flexibility of the modes above it in series with the contact (c_res). "
      f"Energies E_k / E_0 at the release; 'all modes' sums every retained elastic mode.")
    p("")
    p("| cutoff [kHz] | modes (excited) | variant | c_res [m/N] | " + ROW_HEAD[2:])
    p("|---|---|---|---|" + "---|" * 9)
    by_cut = {}
    for fc in cut_list:
        for corrected in (False, True):
            r = simulate(case, beam, fc, rtol=args.rtol, static_correction=corrected)
            by_cut[(fc, corrected)] = r
            p(f"| {fc / 1e3:g} | {r['modes_below_cut']} ({r['modes_integrated']}) | {'corrected' if corrected else 'plain'} | "
              f"{r['c_res_m_n']:.3e} | {fmt_row(row(r))} |")
    p("")
    p("| integrator rtol | steps | right-hand sides | " + ROW_HEAD[2:] + " energy error | momentum error |")
    p("|---|---|---|" + "---|" * 11)
    by_tol = {}
    for tol in (1e-8, 1e-9, 1e-10, 1e-11, 1e-12):
        r = simulate(case, beam, args.cutoff, rtol=tol)
        by_tol[tol] = r
        p(f"| {tol:g} | {r['steps']} | {r['rhs']} | {fmt_row(row(r))} | {r['energy_error']:.1e} | {r['momentum_error']:.1e} |")
    p("")
    p("| beam elements (degree 5) | " + ROW_HEAD[2:])
    p("|---|" + "---|" * 9)
    by_mesh = {}
    for n in (20, 40, 80):
        r = simulate(case, Beam(case, n), args.cutoff, rtol=args.rtol)
        by_mesh[n] = r
        p(f"| {n} | {fmt_row(row(r))} |")
    p("")
    ref = by_tol[args.rtol] if args.rtol in by_tol else simulate(case, beam, args.cutoff, rtol=args.rtol)
    numerical = {
        "cutoff (x2)": rel_change(row(by_cut[(1600e3, True)]), row(by_cut[(800e3, True)])) if args.cutoff == 800e3 else None,
        "integrator (rtol / 10)": rel_change(row(by_tol[1e-12]), row(by_tol[1e-11])),
        "mesh (x2)": rel_change(row(by_mesh[80]), row(by_mesh[40])),
    }
    num_err = max(v for v in numerical.values() if v is not None)
    p("Largest relative change of any column from the reference run (cutoff " + f"{args.cutoff / 1e3:g} kHz corrected, "
      f"{args.elements} elements, rtol {args.rtol:g}): " + ", ".join(f"{k}: {v:.1e}" for k, v in numerical.items() if v is not None)
      + f". Plain truncation converges like 1/cutoff towards the corrected values (at 1600 kHz it is still "
      f"{pct(by_cut[(1600e3, False)]['peak_force_n'], ref['peak_force_n']):+.3f} % off in peak force).")
    p("")
    p(f"Conservation at the release (reference run): energy (sphere + modes + contact potential) relative error "
      f"{ref['energy_error']:.1e}, momentum (sphere + beam translation) {ref['momentum_error']:.1e}. "
      f"Force maxima during the contact: {ref['force_maxima']} (a single peak). After the release the free motion is "
      f"evaluated exactly up to {ref['max_gap_checked_s'] * 1e6:g} us (the project's run length): "
      + ("no second contact, smallest gap " + f"{ref['min_gap_after_m'] * 1e6:.3f} um after the release's first 10 ns"
         if ref["recontact_s"] is None else f"SECOND CONTACT at {ref['recontact_s'] * 1e6:.3f} us") + ".")
    p("")

    # ---- bracket
    side = {}
    sph = sphere_compliance(case, args.sphere_law)
    side["sphere"] = sph
    local = None
    if have_ccx:
        fe_runs = []
        for spec in args.ccx_meshes.split(","):
            s0, g = (float(v) for v in spec.split(":"))
            fe_runs.append(beam_local_fe(case, kappa, ref["peak_force_n"], s0, g))
        local = {"runs": fe_runs, "C_b_m_n": fe_runs[-1]["C_b_m_n"],
                 "mesh_change_m_n": abs(fe_runs[-1]["C_b_m_n"] - fe_runs[-2]["C_b_m_n"]) if len(fe_runs) > 1 else None}
    elif stored.get("beam_local"):
        local = dict(stored["beam_local"], note=f"read back from {os.path.relpath(args.json, ROOT)} (no ccx run)")
    side["beam_local"] = local
    side["beam_modes_3d"] = modes3d
    c_anti = case["nu_b"] * (2 * case["h"] ** 2 + case["b"] ** 2) / 24
    ratio_dyn = ref["moment_over_force_ls_m"]
    C_anti_dyn = -c_anti * ratio_dyn / EI
    C_anti_static = -c_anti * (case["L"] / 8) / EI
    runs = {}
    runs["sphere finite size (C_s)"] = simulate(case, beam, args.cutoff, rtol=args.rtol, extra_compliance=sph["C_m_n"])
    if local:
        runs["beam local 3D field (C_b)"] = simulate(case, beam, args.cutoff, rtol=args.rtol, extra_compliance=local["C_b_m_n"])
    runs["anticlastic top face, dynamic M/F"] = simulate(case, beam, args.cutoff, rtol=args.rtol, extra_compliance=C_anti_dyn)
    runs["anticlastic top face, static M/F = L/8 (for scale only)"] = simulate(case, beam, args.cutoff, rtol=args.rtol, extra_compliance=C_anti_static)
    runs["kappa = 5/6"] = simulate(case, Beam(case, args.elements, kappa=5.0 / 6.0), args.cutoff, rtol=args.rtol)
    runs["kappa x 0.95"] = simulate(case, Beam(case, args.elements, kappa=0.95 * kappa), args.cutoff, rtol=args.rtol)
    if f3d:
        freq_name = f"{min(f3d, key=lambda l: int(l[:-1]))}..{max(f3d, key=lambda l: int(l[:-1]))} at the 3D frequencies (CalculiX)"
        override = {int(l[:-1]) - 1: f for l, f in f3d.items()}
    else:   # no 3D model: the project's (clearly not independent)
        freq_name = "1F..9F at the project's 3D frequencies"
        override = {k: PROJECT["MacNeal"]["frequency_hz"][f"{k + 1}F"] for k in range(N_BENDING)}
    runs[freq_name] = simulate(case, beam, args.cutoff, rtol=args.rtol, frequency_override=override)
    best_C = sph["C_m_n"] + (local["C_b_m_n"] if local else 0.0) + C_anti_dyn
    best_name = "all: C_s + C_b + anticlastic (dynamic) + 3D frequencies"
    runs[best_name] = best = simulate(case, beam, args.cutoff, rtol=args.rtol, extra_compliance=best_C, frequency_override=override)
    p("### Modelling error of the classical model (bracket)")
    p("Each line reruns the reference with one change; effects in % of the reference values. Linear compliances C act in series "
      "with Hertz (the approach is delta_Hertz(F) + C F; C < 0 stiffens). Hertz's secant compliance at the peak is "
      f"{(ref['peak_force_n'] / hz['K']) ** (2 / 3) / ref['peak_force_n']:.3e} m/N for comparison.")
    p("")
    p("| change | C [m/N] | peak force | duration | rebound | " + " | ".join(f"E_{m}" for m in ODD) + " |")
    p("|---|---|---|---|---|" + "---|" * 5)
    comp = {"sphere finite size (C_s)": sph["C_m_n"], "anticlastic top face, dynamic M/F": C_anti_dyn,
            "anticlastic top face, static M/F = L/8 (for scale only)": C_anti_static, best_name: best_C}
    if local:
        comp["beam local 3D field (C_b)"] = local["C_b_m_n"]
    eff = {}
    for name, r in runs.items():
        e = effects(ref, r)
        eff[name] = e
        c_cell = f"{comp[name]:.3e}" if name in comp else ""
        p(f"| {name} | {c_cell} | {e['peak_force_n']:+.2f} % | {e['duration_s']:+.2f} % | "
          f"{e['rebound_m_s']:+.2f} % | " + " | ".join(f"{e['E_' + m]:+.1f} %" for m in ODD) + " |")
    p("")
    p(f"- Sphere: {sph['csv']} (R = {sph['csv_radius_m'] * 1e3:g} mm on a rigid plane, CalculiX) gives the centre-of-mass "
      f"approach delta = delta_Hertz - c F / (E R) with c = {sph['c']:.4f} (fit over {sph['points']} points; "
      f"spread {100 * sph['fit_spread_upper']:.1f} % above a quarter of the largest force); for this sphere "
      f"C_s = {sph['C_m_n']:.3e} m/N.")
    if local:
        for r in local["runs"]:
            p(f"- Beam, CalculiX quarter model, smallest element {r['s0_m'] * 1e6:.1f} um (a/{r['a_m'] / r['s0_m']:.0f}), growth "
              f"{r['growth']:g}, {r['elements']} C3D20, {r['dofs']} dofs, F = {r['F_n']:.1f} N (a = {r['a_m'] * 1e3:.4f} mm): "
              f"A pressure-weighted {r['A_pressure_weighted_m'] * 1e6:.4f} um (Timoshenko {r['timoshenko_A_m'] * 1e6:.4f} + "
              f"half-space {r['half_space_weighted_m'] * 1e6:.4f} - anticlastic "
              f"{case['nu_b'] * (2 * case['h'] ** 2 + case['b'] ** 2) / 24 * r['moment_A_n_m'] / EI * 1e6:.4f}); "
              f"B: section mean vs Timoshenko {r['global_B_fe_minus_timoshenko_m'] * 1e6:+.4f} um, top vs section mean "
              f"{r['anticlastic_B_fe_m'] * 1e6:+.4f} um (Saint-Venant {r['anticlastic_B_formula_m'] * 1e6:+.4f}); centre minus "
              f"pressure-weighted {r['centre_minus_weighted_fe_m'] * 1e6:.4f} um (half-space "
              f"{r['centre_minus_weighted_half_space_m'] * 1e6:.4f}); local correction {r['local_m'] * 1e6:+.4f} um, "
              f"C_b = {r['C_b_m_n']:.3e} m/N.")
        if local.get("note"):
            p(f"- ({local['note']})")
    else:
        p("- Beam local field: not computed (no ccx, no earlier JSON).")
    p(f"- Anticlastic: the top face under the sphere moves by w - nu (2 h^2 + b^2) / 24 M / EI (Saint-Venant; "
      f"c = {c_anti:.4e} m^2); in the reference run M / F = {ratio_dyn * 1e3:.3f} mm (least squares of M(t) ~ r F(t) over "
      f"the pulse; {ref['moment_at_peak_n_m'] / ref['peak_force_n'] * 1e3:.3f} mm at the peak; static: L/8 = "
      f"{case['L'] / 8 * 1e3:.2f} mm), an equivalent C = -c (M/F) / EI.")
    p(f"- Beam dynamics: '{freq_name}' keeps the Timoshenko mode shapes and sets those frequencies to the 3D ones "
      f"(table above); 'kappa' reruns the whole beam model with another shear coefficient.")
    if modes3d and modes3d.get("note"):
        p(f"- ({modes3d['note']})")
    p("")

    # the bracket: the reference with all corrections is the best estimate of the 3D problem;
    # around it: 15 % of the sphere's term (the scaling of a 5 mm sphere's law), 25 % of the
    # beam's local term (its quasistatic use in the pulse, the mesh), 50 % of the anticlastic
    # term (Saint-Venant's kinematics under a concentrated load, M/F varying over the pulse), and
    # for the beam's dynamics beyond its frequencies (mode shapes, participation) the larger of
    # half the frequency term and the kappa = 5/6 run; the terms add linearly
    unc = {}
    for k in eff[best_name]:
        shift = eff[best_name][k]
        sym = 0.15 * abs(eff["sphere finite size (C_s)"].get(k, 0.0)) \
            + 0.25 * abs(eff.get("beam local 3D field (C_b)", {}).get(k, 0.0)) \
            + 0.5 * abs(eff["anticlastic top face, dynamic M/F"].get(k, 0.0)) \
            + max(0.5 * abs(eff[freq_name].get(k, 0.0)), abs(eff["kappa = 5/6"].get(k, 0.0)))
        unc[k] = (shift - sym, shift + sym)
    # ---- results and comparison
    p("### Reference values and comparison with the project")
    p(f"Classical model, converged (numerical error below {num_err:.0e} relative on every value shown); 'best 3D estimate' "
      f"is the line 'all' above; the bracket is where the 3D problem's value lies against the classical one "
      f"(the best estimate's shift, widened by 15 % of the sphere's term, 25 % of the beam's local term, 50 % of the "
      f"anticlastic term and the larger of half the 3D-frequency term and the kappa = 5/6 term, added linearly). Project: {', '.join(PROJECT)} as in bench/RESULTS.md "
      f"(sphere_on_beam, commit 5f7f634).")
    p("")
    p("| quantity | classical reference | bracket (3D vs classical) | best 3D estimate | MacNeal | vs reference | "
      "vs best 3D | Craig-Bampton | vs reference | vs best 3D |")
    p("|---|---|---|---|---|---|---|---|---|---|")

    def line(name, key, val, best_val, scale, fmt, unit, pk=None):
        pk = pk or key
        lo, hi = unc.get(key, (0, 0))
        mac, cb = PROJECT["MacNeal"], PROJECT["Craig-Bampton"]
        pm = mac.get(pk) if not isinstance(pk, tuple) else mac[pk[0]].get(pk[1])
        pc = cb.get(pk) if not isinstance(pk, tuple) else cb[pk[0]].get(pk[1])
        cell = lambda v: (fmt.format(v * scale) + unit) if v is not None else ""
        diff = lambda v, w: f"{pct(v, w):+.2f} %" if v is not None else ""
        p(f"| {name} | {cell(val)} | {lo:+.2f} .. {hi:+.2f} % | {cell(best_val)} | {cell(pm)} | {diff(pm, val)} | "
          f"{diff(pm, best_val)} | {cell(pc)} | {diff(pc, val)} | {diff(pc, best_val)} |")

    line("peak force", "peak_force_n", ref["peak_force_n"], best["peak_force_n"], 1, "{:.2f}", " N")
    line("contact duration", "duration_s", ref["duration_s"], best["duration_s"], 1e6, "{:.3f}", " us")
    line("sphere rebound", "rebound_m_s", ref["rebound_m_s"], best["rebound_m_s"], 1, "{:.4f}", " m/s")
    line("energy in the beam's modes", "beam_mode_energy", ref["beam_mode_energy"], best["beam_mode_energy"], 1, "{:.4f}", "")
    for m in [f"{k + 1}F" for k in range(N_BENDING)]:
        e_ref, e_best = energy_of(ref, m), energy_of(best, m)
        if e_ref < 1e-12:
            continue
        line(f"E_{m} / E_0", "E_" + m, e_ref, e_best, 1, "{:.4f}", "", ("energy_ratio", m))
    for m in [f"{k + 1}F" for k in range(N_BENDING)]:
        r_ref = next(x["restitution"] for x in ref["modes"] if x["label"] == m)
        r_best = next(x["restitution"] for x in best["modes"] if x["label"] == m)
        line(f"r_{m}", "r_" + m, r_ref, r_best, 1, "{:.4f}", "", ("restitution", m))
    p("")
    p(f"Where the sphere's energy goes (classical): beam modes {ref['beam_mode_energy']:.4f} (below 70 kHz, the project's "
      f"band: {ref['beam_mode_energy_below_70khz']:.4f}), beam translation "
      f"{ref['beam_rigid_energy']:.4f}, sphere {ref['sphere_energy']:.4f} of E_0; impulse {ref['impulse_n_s'] * 1e3:.4f} mN s. "
      f"CPU: {time.process_time() - cpu0:.0f} s in Python, {children_cpu():.0f} s in CalculiX.")

    print("\n".join(out))
    result = {
        "what": "classical reference (Hertz contact, rigid sphere, Timoshenko beam by modal superposition) for "
                + case["scene"] + "; bench/reference/timoshenko_hertz.py",
        "inputs": {k: case[k] for k in ("L", "h", "b", "E_b", "nu_b", "rho_b", "R", "E_s", "nu_s", "rho_s", "m_s", "v0", "x_c")}
        | {"kappa": kappa, "E_star": hz["E_star"], "K": hz["K"]},
        "hertz_half_space": hz,
        "numerical": {"elements": args.elements, "degree": 5, "cutoff_hz": args.cutoff, "rtol": args.rtol,
                      "largest_relative_change": numerical, "energy_error": ref["energy_error"],
                      "momentum_error": ref["momentum_error"], "force_maxima": ref["force_maxima"],
                      "second_contact_s": ref["recontact_s"], "checked_until_s": ref["max_gap_checked_s"],
                      "frequencies_converged_1e-5": bool(freq_ok)},
        "peak_force_n": ref["peak_force_n"], "duration_s": ref["duration_s"], "rebound_m_s": ref["rebound_m_s"],
        "peak_time_s": ref["peak_time_s"], "beam_mode_energy": ref["beam_mode_energy"],
        "beam_mode_energy_below_70khz": ref["beam_mode_energy_below_70khz"],
        "beam_rigid_energy": ref["beam_rigid_energy"], "impulse_n_s": ref["impulse_n_s"],
        "modes": {m["label"]: {"frequency_hz": m["frequency_hz"], "energy_ratio": m["energy_ratio"], "restitution": m["restitution"]}
                  for m in ref["modes"][:N_BENDING]},
        "frequencies_hz": {f"{k + 1}F": float(freq[meshes[-1]][k]) for k in range(N_FREQ)},
        "euler_bernoulli_hz": {f"{k + 1}F": float(eb[k]) for k in range(N_FREQ)},
        "bracket_percent": {k: list(v) for k, v in unc.items()},
        "bracket_absolute": {k: [ref[k] * (1 + lo / 100), ref[k] * (1 + hi / 100)] for k, (lo, hi) in unc.items() if k in KEYS},
        "best_3d_estimate": {"peak_force_n": best["peak_force_n"], "duration_s": best["duration_s"],
                             "rebound_m_s": best["rebound_m_s"], "extra_compliance_m_n": best_C,
                             "modes": {m["label"]: {"energy_ratio": m["energy_ratio"], "restitution": m["restitution"]}
                                       for m in best["modes"][:N_BENDING]}},
        "sensitivities_percent": eff,
        "side_calculations": side | {"anticlastic_c_m2": c_anti, "moment_over_force_m": ratio_dyn,
                                     "moment_over_force_at_peak_m": ref["moment_at_peak_n_m"] / ref["peak_force_n"]},
        "project_compared": PROJECT,
    }
    with open(args.json, "w") as f:
        json.dump(result, f, indent=1, default=float)
        f.write("\n")


def children_cpu():
    import resource
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def shutil_which(name):
    import shutil
    return shutil.which(name)


if __name__ == "__main__":
    main()

