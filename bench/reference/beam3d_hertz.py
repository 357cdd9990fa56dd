#!/usr/bin/python3
"""Sphere on the free-free beam: Hertz's sphere on a 3D finite-element beam by modes, an
independent reference for the project's 3D contact (sphere on a beam, case F of [R3] in
docs/references.md).

Why beside timoshenko_hertz.py. That classical model adds the beam's local 3D field as a
static compliance C_b in series with the contact (a static CalculiX solve, inertia relief):
it assumes the whole of that field acts at once. This model needs no such split: the beam is
a 3D CalculiX model whose lowest modes respond dynamically and whose static residual (the rest
of its exact static response) acts at once, as in mode acceleration. The two models differ in
how they share the beam's 3D static field between the two; their difference is the error of
the classical model's assumption.

Model (inputs read from the scene and its model files, as timoshenko_hertz.py):
- Beam: the quarter beam in C3D20 (CalculiX, symmetry planes through the impact point),
  graded toward the contact (smallest element s0, growth g), free-free. Its modes below a
  cutoff (CalculiX *FREQUENCY, mass-normalized; the rigid translation put in exactly) respond
  dynamically; for each mode the loaded nodes' displacements give its load per force. The
  static residual at the contact centre, r(F) = u_static(F) - sum_k phi_k(c) p_k(F) / w_k^2
  (both relative to a pinned point at the beam's end, CalculiX *STATIC under the Hertz
  pressure of F and the inertia-relief body force), acts at once; it is computed at a few
  forces and interpolated in log F (the pressure's radius changes with F).
- Load: Hertz's pressure p0 sqrt(1 - r^2/a^2) of the current force F on the top face, a of
  both bodies' E* (consistent nodal loads, summed exactly to F).
- Sphere: rigid mass; its own side of the approach is Hertz's (the sphere's share of the
  half-space approach, (1 - nu_s^2)/E_s of 1/E*) plus its finite size, the linear compliance
  C_s of timoshenko_hertz.py (CalculiX sphere on a rigid plane).
- Contact: sphere displacement - beam's centre displacement = sphere's approach(F), F >= 0.
  The beam's centre displacement is the rigid translation, the modes and the residual.
- Time: modes, rigid translation and sphere are advanced exactly for a force linear within a
  step (dt); the force at the step's end solves the contact equation (Brent).

Checks printed: with the Timoshenko beam of timoshenko_hertz.py in place of the 3D modes (and
Hertz's whole approach on the sphere's side) the same integrator gives the classical model's
values; reruns with the step halved, the cutoff at 0.6 of it, the approach observed as the
pressure-weighted displacement, and without C_s; the static residual per force beside the
half-space's share, at each force computed. CalculiX's zero mode is checked to be the rigid
translation 1/sqrt(m) (the unit conversions of the mode shapes).

Limits: Hertz's pressure shape on the beam (the contact's true pressure on a finite beam is
Hertz's within the local field's small offset); the beam's centre displacement stands for its
surface inside the contact (Hertz's geometry); the sphere's side is Hertz's plus C_s.

Usage: beam3d_hertz.py [--scene ...] [--mesh 0.125:1.4] [--modes 60] [--cutoff 1.5e5] [--dt 2e-9]
    [--no-ccx] [--json bench/reference/beam3d_hertz_free.json]
Writes bench/reference/beam3d_hertz_free.json (the CalculiX results, read back with
--no-ccx) and prints a markdown section."""
import argparse
import json
import math
import os
import sys
import time

import numpy as np
from scipy import optimize

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import timoshenko_hertz as th  # noqa: E402  (the classical model's inputs, meshes and CalculiX helpers)

HERE = th.HERE
FORCES = (40.0, 150.0, 350.0, 550.0, 750.0)   # static residual at these forces [N]
F_TOP = 900.0                                  # the load table's largest force [N]


# ---------------------------------------------------------------------- CalculiX beam
def quarter_mesh(case, s0_over_a, growth):
    """The CalculiX quarter beam graded to s0 = s0_over_a times the peak's Hertz contact radius
    (4 mm along the beam and 2 mm across at most), and s0 [m]."""
    s0 = th.contact_radius_m(case, th.hertz_half_space(case)["peak_force_n"]) * 1e3 * s0_over_a
    return th.quarter_mesh(case, s0, growth, 4.0, 2.0), s0 * 1e-3


def beam_3d(case, s0_over_a, growth, n_modes, keep=None):
    """Modes and static residuals of the CalculiX quarter beam (SI units in the result)."""
    E, nu, rho = case["E_b"], case["nu_b"], case["rho_b"]
    q, s0 = quarter_mesh(case, s0_over_a, growth)
    nx, ny, nz = q.n
    L, b = case["L"] * 1e3, case["b"] * 1e3
    iy = int(np.argmin(np.abs(q.lines[1] - case["h"] * 1e3 / 2)))
    n_fix, n_top = q.node_id[(0, 2 * iy, 2 * nz)], q.node_id[(2 * nx, 2 * ny, 2 * nz)]
    # the nodes that the load table's largest force loads (smaller forces load fewer)
    loaded = sorted(set(th.hertz_face_loads(case, q, F_TOP)) | {n_top})
    out_nodes = loaded + [n_fix]
    sets = (th.ccx_set("NSET", "NXSYM", q.nodes_on(0, 2 * nx)) + th.ccx_set("NSET", "NZSYM", q.nodes_on(2, 2 * nz))
            + th.ccx_set("NSET", "NFIX", [n_fix]) + th.ccx_set("NSET", "NOUT", out_nodes)
            + "*BOUNDARY\nNXSYM, 1, 1\nNZSYM, 3, 3\n")
    # modes: the rigid translation along y is the zero mode
    body = sets + f"*STEP\n*FREQUENCY\n{n_modes + 1}\n*NODE PRINT, NSET=NOUT\nU\n*END STEP\n"
    folder, path, wall_modes = th.run_ccx(q, "beam3d_modes", body, E, nu, rho, keep)
    freqs = th.ccx_frequencies(open(path[:-4] + ".dat").read())
    blocks = th.ccx_displacements(open(path[:-4] + ".dat").read())
    th.remove_run_folder(folder, keep)
    # statics: the Hertz pressure of each force and the inertia relief, pinned at NFIX
    rho_mm = rho * 1e-12
    steps, loads_of = "", {}
    for F in FORCES:
        loads = th.hertz_face_loads(case, q, F)
        loads_of[F] = loads
        g_relief = F / (rho_mm * L * case["h"] * 1e3 * b)
        steps += ("*STEP\n*STATIC\n*BOUNDARY\nNFIX, 2, 2\n*CLOAD, OP=NEW\n" + "".join(f"{n}, 2, {th.ccx_number(-f)}\n" for n, f in loads.items())
                  + f"*DLOAD, OP=NEW\nEALL, GRAV, {th.ccx_number(g_relief)}, 0., 1., 0.\n*NODE PRINT, NSET=NOUT\nU\n*END STEP\n")
    folder, path, wall_static = th.run_ccx(q, "beam3d_static", sets + steps, E, nu, rho, keep)
    statics = th.ccx_displacements(open(path[:-4] + ".dat").read())
    th.remove_run_folder(folder, keep)
    if len(blocks) != len(freqs) or len(statics) != len(FORCES):
        raise RuntimeError(f"CalculiX output: {len(freqs)} frequencies, {len(blocks)} mode blocks, {len(statics)} static blocks")
    # mass-normalized shapes are displacement per (length sqrt(mass)): only the mass unit converts
    # (t -> kg); the quarter's are twice the full beam's (a quarter of its mass)
    modes = [{"f_hz": f, "phi_y": {str(n): U[n][1] * math.sqrt(1e-3) / 2 for n in out_nodes}}
             for f, U in zip(freqs, blocks) if f > 1.0]
    # the rigid translation's shape is 1 / sqrt(the beam's mass): a check of those conversions
    mass = case["rho_b"] * case["L"] * case["h"] * case["b"]
    rigid = [U[n_top][1] * math.sqrt(1e-3) / 2 for f, U in zip(freqs, blocks) if f <= 1.0]
    if len(rigid) != 1 or abs(abs(rigid[0]) * math.sqrt(mass) - 1) > 1e-4:
        raise RuntimeError(f"CalculiX's zero modes {rigid} are not the rigid translation 1/sqrt(m) = {1 / math.sqrt(mass):.6g}")
    return {"mesh": {"s0_m": s0, "s0_over_a": s0_over_a, "growth": growth, "elements": len(q.els), "dofs": 3 * len(q.node_id)},
            "nodes": {"fix": n_fix, "centre": n_top, "top": loaded},
            "modes": modes,
            "static": [{"F_n": F, "u_y_m": {str(n): U[n][1] * 1e-3 for n in (n_fix, n_top)},
                        "u_y_pressure_weighted_m": sum(f * U[n][1] for n, f in loads_of[F].items()) / (F / 4) * 1e-3}
                       for F, U in zip(FORCES, statics)],
            "loads": {str(F): {str(n): f for n, f in loads_of[F].items()} for F in FORCES},
            "ccx_wall_s": wall_modes + wall_static}


# ------------------------------------------------------------------------------ impact
class BeamModel:
    """What the impact needs of a beam, downward positive along the sphere's velocity:
    frequencies w_k [rad/s], the modes' displacements where the contact is observed (a vector,
    or a function of the force), their loads per force p(F) (a vector), the instantaneous
    residual r(F) and the beam's mass."""

    def __init__(self, omega, phi_c, load, residual, mass):
        self.omega, self.load, self.residual, self.mass = omega, load, residual, mass
        self.observe = phi_c if callable(phi_c) else (lambda F: phi_c)


def advance(x, v, p0, p1, omega, dt):
    """Exact step of x'' + w^2 x = p for p linear from p0 to p1 (w = 0 allowed), elementwise."""
    w = np.where(omega > 0, omega, 1.0)
    c, s = np.cos(omega * dt), np.sin(omega * dt)
    dp = p1 - p0
    osc_x = x * c + v * s / w + p0 * (1 - c) / w ** 2 + dp * (dt - s / w) / (w ** 2 * dt)
    osc_v = -x * w * s + v * c + p0 * s / w + dp * (1 - c) / (w ** 2 * dt)
    free_x = x + v * dt + p0 * dt ** 2 / 2 + dp * dt ** 2 / 6
    free_v = v + p0 * dt + dp * dt / 2
    rigid = omega == 0
    return np.where(rigid, free_x, osc_x), np.where(rigid, free_v, osc_v)


def impact(beam, sphere_approach, m_s, v0, dt, f_max=5e3):
    """The sphere (rigid mass, velocity v0 toward the beam) on the beam at rest: the force
    history's peak, duration, the sphere's rebound and the modes' energies at the release."""
    # state: the modes and, last, the beam's rigid translation (load F, mass m_b) and the sphere (load -F)
    omega = np.concatenate([beam.omega, [0.0, 0.0]])
    x, v = np.zeros(len(omega)), np.zeros(len(omega))
    v[-1] = v0
    scale = np.concatenate([np.ones(len(beam.omega)), [1 / beam.mass, -1 / m_s]])
    loads = lambda F: np.concatenate([beam.load(F), [F, F]]) * scale
    p0, t = loads(0.0), 0.0
    hist, onset, h_last = [], None, None
    while True:
        def gap_closure(F):   # sphere - beam - approach at the step's end, for the force F there
            xn, _ = advance(x, v, p0, loads(F), omega, dt)
            beam_centre = xn[-2] + beam.observe(F) @ xn[:-2] + beam.residual(F)
            return xn[-1] - beam_centre - sphere_approach(F)
        h0 = gap_closure(0.0)    # the closure with no force over the step: > 0 in contact
        F1 = 0.0 if h0 <= 0 else optimize.brentq(gap_closure, 0.0, f_max, xtol=1e-12, rtol=1e-14)
        p1 = loads(F1)
        x, v = advance(x, v, p0, p1, omega, dt)
        # onset and release where the force-free closure crosses zero, linear within the step
        if F1 > 0 and onset is None:
            onset = t + dt * (-h_last / (h0 - h_last)) if h_last is not None else t
        if onset is not None and F1 == 0:
            release = t + dt * (h_last / (h_last - h0))
            break
        h_last = h0
        t += dt
        p0 = p1
        hist.append((t, F1))
        if t > 1e-3:
            raise RuntimeError("no release within 1 ms")
    Fs = np.array(hist)[:, 1]
    i = int(np.argmax(Fs))
    # the peak: a parabola through the largest sample and its neighbours
    a_, b_, c_ = Fs[i - 1], Fs[i], Fs[i + 1]
    peak = b_ + (a_ - c_) ** 2 / (8 * (2 * b_ - a_ - c_)) if 2 * b_ - a_ - c_ > 0 else b_
    energies = 0.5 * (v[:-2] ** 2 + (beam.omega * x[:-2]) ** 2)
    return {"peak_force_n": float(peak), "duration_s": float(release - onset), "rebound_m_s": float(-v[-1]),
            "energies_j": energies, "velocities": v, "positions": x, "steps": len(hist)}


def timoshenko_model(case, n_elem, cutoff_hz):
    """The classical model's beam (timoshenko_hertz.py), with its static correction: for the
    check that this integrator gives the classical values."""
    beam = th.Beam(case, n_elem)
    freqs, vecs = beam.modes(f_max_hz=cutoff_hz)
    g = beam.contact_vector()
    phi = g @ vecs
    excited = np.abs(vecs[beam.dof_c]) > 1e-9 * np.abs(vecs[beam.dof_c]).max()
    omega, phi = 2 * math.pi * freqs[excited], phi[excited]
    c_res = beam.flexibility(g) - np.sum(phi ** 2 / omega ** 2)
    return BeamModel(omega, phi, lambda F: phi * F, lambda F: c_res * F, beam.mass)


def load_table(case, data, table_points=160, f_top=F_TOP):
    """The quarter's nodal loads (impacted face's nodes, in data's order) of Hertz's pressure at
    forces even in the contact radius up to f_top: (forces, loads x nodes)."""
    q, _ = quarter_mesh(case, data["mesh"]["s0_over_a"], data["mesh"]["growth"])
    index = {n: i for i, n in enumerate(data["nodes"]["top"])}
    grid = f_top * (np.arange(table_points + 1) / table_points) ** 3
    table = np.zeros((len(grid), len(index)))
    for i, F in enumerate(grid[1:], start=1):
        for n, value in th.hertz_face_loads(case, q, F).items():
            table[i, index[n]] = value
    return grid, table


def model_3d(case, data, cutoff_hz, loads_of_force, pressure_weighted=False):
    """The CalculiX beam's modes below cutoff_hz, its loads per force (tabulated in F:
    load_table's) and the static residual of the rest. The contact's approach is observed at the
    centre, or (pressure_weighted) as the pressure-weighted displacement plus the difference
    of the two on a half-space (0.2 of its centre approach): a check of Hertz's geometry."""
    hz = th.hertz_half_space(case)
    grid, nodal = loads_of_force
    centre, fix = str(data["nodes"]["centre"]), str(data["nodes"]["fix"])
    kept = [m for m in data["modes"] if m["f_hz"] <= cutoff_hz]
    top = [str(n) for n in data["nodes"]["top"]]
    down = np.array([[-m["phi_y"][n] for n in top] for m in kept])          # modes x loaded nodes, downward
    omega = np.array([2 * math.pi * m["f_hz"] for m in kept])
    phi_c = np.array([-m["phi_y"][centre] for m in kept])
    phi_fix = np.array([-m["phi_y"][fix] for m in kept])
    node_index = {n: i for i, n in enumerate(top)}

    def modal_load(loads):        # the full beam's modal loads of the quarter's nodal loads
        f = np.zeros(len(top))
        for n, value in loads.items():
            f[node_index[str(n)]] = value
        return 4 * down @ f
    table = 4 * nodal @ down.T                     # forces x modes: the full beam's modal loads (4 quarters)

    def load(F):                                   # the table's rows, linear in F between forces (np.interp's clamping)
        if F >= grid[-1]:
            return table[-1]
        i = max(int(np.searchsorted(grid, F, side="right")) - 1, 0)
        t = max(F - grid[i], 0.0) / (grid[i + 1] - grid[i])
        return table[i] + t * (table[i + 1] - table[i])
    # the static residual: CalculiX's static response less the kept modes', both against the pinned end
    w_b = (1 - case["nu_b"] ** 2) / case["E_b"] * hz["E_star"]              # the beam's share of Hertz's approach
    delta_h = lambda F: (max(F, 0.0) / hz["K"]) ** (2 / 3)
    forces, remainder, residuals = [], [], []
    for s in data["static"]:
        F = s["F_n"]
        p = modal_load(data["loads"][str(F)])
        if pressure_weighted:
            static = -(s["u_y_pressure_weighted_m"] - s["u_y_m"][fix]) + 0.2 * w_b * delta_h(F)
            r = static - np.sum((p / F - phi_fix) * p / omega ** 2)
        else:
            static = -(s["u_y_m"][centre] - s["u_y_m"][fix])
            r = static - np.sum((phi_c - phi_fix) * p / omega ** 2)
        forces.append(F)
        residuals.append(r)
        remainder.append((r - w_b * delta_h(F)) / F)     # what is left beside the half-space's centre approach, per force
    logF = np.log(forces)
    residual = lambda F: w_b * delta_h(F) + F * float(np.interp(math.log(max(F, 1e-9)), logF, remainder))
    observe = (lambda F: load(F) / F if F > 0 else phi_c) if pressure_weighted else phi_c
    model = BeamModel(omega, observe, load, residual, case["rho_b"] * case["L"] * case["h"] * case["b"])
    model.frequencies_hz = omega / (2 * math.pi)
    model.residual_table = {"F_n": forces, "residual_m": residuals, "beside_half_space_m_n": remainder}
    return model


def labelled(freqs_hz, energies, E0, bending_hz):
    """E_k / E_0 of the 3D modes nearest the bending frequencies (1F, 3F, ...), within 3 %."""
    out = {}
    for name, f in bending_hz.items():
        k = int(np.argmin(np.abs(freqs_hz - f)))
        if abs(freqs_hz[k] / f - 1) < 0.03:
            out[name] = {"frequency_hz": float(freqs_hz[k]), "energy_ratio": float(energies[k] / E0)}
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scene", default=os.path.join(th.ROOT, "models", "sphere_on_beam_free.scene.toml"))
    ap.add_argument("--json", default=os.path.join(HERE, "beam3d_hertz_free.json"))
    ap.add_argument("--mesh", default="0.125:1.4", help="s0/a:growth of the CalculiX mesh (smallest element over the peak's contact radius)")
    ap.add_argument("--modes", type=int, default=60, help="modes CalculiX extracts (the quarter beam's doubly symmetric ones)")
    ap.add_argument("--cutoff", type=float, default=150e3, help="modes below this frequency respond dynamically [Hz]")
    ap.add_argument("--dt", type=float, default=2e-9, help="time step [s]")
    ap.add_argument("--no-ccx", action="store_true", help="read the CalculiX results from --json instead of running ccx")
    ap.add_argument("--sphere-law", default=os.path.join(HERE, "finite_sphere_steel_r5_v1.csv"))
    args = ap.parse_args()
    cpu0 = time.process_time()
    case = th.read_case(args.scene)
    hz = th.hertz_half_space(case)
    classical = json.load(open(os.path.join(HERE, "timoshenko_hertz_free.json")))
    s0_over_a, growth = (float(v) for v in args.mesh.split(":"))
    if args.no_ccx:
        data = json.load(open(args.json))["calculix"]
    else:
        data = beam_3d(case, s0_over_a, growth, args.modes)
        with open(args.json, "w") as f:          # kept at once: the impacts below can be rerun with --no-ccx
            json.dump({"calculix": data}, f)
    E0 = 0.5 * case["m_s"] * case["v0"] ** 2
    sph = th.sphere_compliance(case, args.sphere_law)
    w_s = (1 - case["nu_s"] ** 2) / case["E_s"] * hz["E_star"]               # the sphere's share of Hertz's approach
    delta_h = lambda F: (max(F, 0.0) / hz["K"]) ** (2 / 3)
    sphere_side = lambda F: w_s * delta_h(F) + sph["C_m_n"] * F
    out = []
    p = out.append

    # the integrator against the classical model (Hertz's whole approach, the Timoshenko beam)
    check = impact(timoshenko_model(case, 40, 800e3), delta_h, case["m_s"], case["v0"], args.dt)
    runs, loads_of_force = {}, load_table(case, data)
    for name, cutoff, dt, approach, weighted in (
            ("reference", args.cutoff, args.dt, sphere_side, False),
            ("step / 2", args.cutoff, args.dt / 2, sphere_side, False),
            ("cutoff x 0.6", 0.6 * args.cutoff, args.dt, sphere_side, False),
            ("approach observed pressure-weighted (+ 0.2 of the half-space's centre approach)", args.cutoff, args.dt, sphere_side, True),
            ("without C_s (the sphere's side a half-space)", args.cutoff, args.dt, lambda F: w_s * delta_h(F), False)):
        if weighted and "u_y_pressure_weighted_m" not in data["static"][0]:
            continue
        model = model_3d(case, data, cutoff, loads_of_force, weighted)
        r = impact(model, approach, case["m_s"], case["v0"], dt)
        bending = classical["side_calculations"]["beam_modes_3d"]["frequencies_hz"]     # 1F, 3F, ... of an earlier CalculiX run
        r["modes"] = labelled(model.frequencies_hz, r["energies_j"], E0, bending)
        r["modes_kept"], r["cutoff_hz"], r["dt_s"] = len(model.omega), cutoff, dt
        r["residual_table"] = model.residual_table
        runs[name] = r
    ref = runs["reference"]

    p("## Sphere on the free-free beam: Hertz's sphere on the 3D CalculiX beam by modes")
    p(f"`bench/reference/beam3d_hertz.py` (numpy {np.__version__}, scipy {__import__('scipy').__version__}); inputs read from "
      f"{case['scene']}, {case['beam_model']} and {case['sphere_model']}. Machine-independent: no timing enters the values.")
    p("")
    m = data["mesh"]
    p(f"Beam: CalculiX quarter beam, C3D20, smallest element {m['s0_m'] * 1e6:.1f} um (a/{1 / m['s0_over_a']:g} of the peak's "
      f"contact radius), growth {m['growth']:g}, {m['elements']} elements, {m['dofs']} DOFs; {len(data['modes'])} elastic doubly "
      f"symmetric modes up to {max(x['f_hz'] for x in data['modes']) / 1e3:.1f} kHz. Sphere: rigid mass, its side of the approach "
      f"Hertz's ({w_s:.3f} of it) plus C_s = {sph['C_m_n']:.4g} m/N (the finite sphere, {sph['csv']}).")
    p("")
    p("| run | modes kept | step [ns] | peak force [N] | duration [us] | rebound [m/s] | " +
      " | ".join(f"E_{k}/E_0" for k in ("1F", "3F", "5F", "7F", "9F")) + " |")
    p("|---|---|---|---|---|---|---|---|---|---|---|")
    for name, r in runs.items():
        p(f"| {name} | {r['modes_kept']} (below {r['cutoff_hz'] / 1e3:g} kHz) | {r['dt_s'] * 1e9:g} | {r['peak_force_n']:.3f} | "
          f"{r['duration_s'] * 1e6:.4f} | {r['rebound_m_s']:.5f} | " +
          " | ".join(f"{r['modes'][k]['energy_ratio']:.4f}" if k in r["modes"] else "—" for k in ("1F", "3F", "5F", "7F", "9F")) + " |")
    p(f"| check: this integrator on the classical model (Timoshenko, Hertz's whole approach) | — | {args.dt * 1e9:g} | "
      f"{check['peak_force_n']:.3f} | {check['duration_s'] * 1e6:.4f} | {check['rebound_m_s']:.5f} | — | — | — | — | — |")
    p(f"| classical model (timoshenko_hertz.py, DOP853) | — | — | {classical['peak_force_n']:.3f} | {classical['duration_s'] * 1e6:.4f} | "
      f"{classical['rebound_m_s']:.5f} | " + " | ".join(f"{classical['modes'][k]['energy_ratio']:.4f}" for k in ("1F", "3F", "5F", "7F", "9F")) + " |")
    best = classical["best_3d_estimate"]
    p(f"| classical best 3D estimate (its local field at once) | — | — | {best['peak_force_n']:.3f} | {best['duration_s'] * 1e6:.4f} | "
      f"{best['rebound_m_s']:.5f} | " + " | ".join(f"{best['modes'][k]['energy_ratio']:.4f}" for k in ("1F", "3F", "5F", "7F", "9F")) + " |")
    p("")
    res = ref["residual_table"]
    p("Static residual at the contact centre (what the modes above the cutoff give; it acts at once), and beside it the beam's "
      "half-space share of Hertz's centre approach: " +
      ", ".join(f"{F:g} N: {r * 1e6:.4f} um ({(r - c * F) * 1e6:.4f} um)"
                for F, r, c in zip(res["F_n"], res["residual_m"], res["beside_half_space_m_n"])) +
      ". What the residual holds beside the half-space, per force: " + ", ".join(f"{c:.4g}" for c in res["beside_half_space_m_n"]) + " m/N.")
    p("")
    p(f"CPU of this run: {time.process_time() - cpu0 + th.children_cpu():.0f} s" +
      ("" if args.no_ccx else f" (CalculiX {data['ccx_wall_s']:.0f} s wall)") + ".")
    print("\n".join(out))
    save = {"what": "sphere on the free-free beam: Hertz's sphere on the 3D CalculiX beam by modes (bench/reference/beam3d_hertz.py)",
            "peak_force_n": ref["peak_force_n"], "duration_s": ref["duration_s"], "rebound_m_s": ref["rebound_m_s"],
            "modes": ref["modes"],
            "numerical": {name: {k: r[k] for k in ("peak_force_n", "duration_s", "rebound_m_s", "modes_kept", "cutoff_hz", "dt_s")}
                          for name, r in runs.items()},
            "check_classical": {k: check[k] for k in ("peak_force_n", "duration_s", "rebound_m_s")},
            "sphere_compliance_m_n": sph["C_m_n"], "calculix": data}
    with open(args.json, "w") as f:
        json.dump(save, f, indent=1)


if __name__ == "__main__":
    main()
