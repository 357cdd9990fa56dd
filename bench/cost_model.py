#!/usr/bin/python3
"""Cost model of the runtime: for each validation scene, the time per right-hand side
split into the quasistatic static solve, contact detection and forces, joints, the floating-frame
equations and output (summary.json `time_split_s`), set against a bound from the work no
evaluation can avoid:
  - the dense floating-frame terms: one product with each body's coupled (nq + 6)^2 mass matrix,
    and the contractions of the SID's first-order terms with q (and qdot) that its equations
    need (first_order_multiply_adds: Ct1, and for the free rotation axes Cr1, Gr1, Ge, Oe1),
  - mapping displacements to and forces from the loaded contact points: 2 x 3 x nq multiply-adds
    each way per point (summary.json `rhs_cost.mean_active_points`),
at this core's dense floating-point rate, measured here with one BLAS thread. The ratio says how
far an evaluation is from that bound. Evaluations at the state of the one before are answered
from it (summary.json `rhs_cost.repeated`) and cost nothing: times are per computed evaluation.
Writes the 'cost-model' section of bench/RESULTS.md.
Usage: bench/cost_model.py"""
import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # the rate of one core, as isosid-run uses
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402

import h5py  # noqa: E402
import numpy as np  # noqa: E402
import tomllib  # noqa: E402

from bench_common import BUILD, ROOT, machine, run_json, update_section  # noqa: E402

RUN = os.path.join(BUILD, "runtime", "isosid-run")
SCENES = [("A", "sphere_hertz"), ("A′", "sphere_pair"), ("B", "rod_impact"), ("C", "cylinder_friction")]
PARTS = ["static_solve", "contacts", "joints", "floating_frame", "output"]


def dense_rate():
    """Multiply-adds per second of a 600 x 600 matrix-vector product on one core (best of five):
    the work of an evaluation is matrix-vector work, which a matrix-matrix rate would overstate."""
    rng = np.random.default_rng(0)
    a, x = rng.standard_normal((600, 600)), rng.standard_normal(600)
    best = float("inf")
    for _ in range(5):
        t0 = time.perf_counter()
        for _ in range(200):
            a @ x
        best = min(best, (time.perf_counter() - t0) / 200)
    return 600 ** 2 / best


def first_order_multiply_adds(scene_file, body, n, nv):
    """The contractions with q (and qdot) of a flexible body's first-order SID terms that its
    equations need per evaluation: Ct1 3 m^2 always; for k free rotation axes Cr1 k m^2,
    Gr1 3 k nv m, Ge k m nv and Oe1 k (k + 1) / 2 m^2 (the columns of w and w^2 that are not
    zero), each where the SID carries it; m the coordinates with inertia (n less a massless
    boundary), nv those with velocities."""
    with open(scene_file, "rb") as f:
        scene = tomllib.load(f)
    dimension = scene["simulation"].get("dimension", "3d")
    spec = next(b for b in scene.get("flexible_body", []) if b["name"] == body)
    k = len({"axisymmetric": set(), "planar": {"rz"}}.get(dimension, {"rx", "ry", "rz"}) - set(spec.get("locked", [])))
    with h5py.File(os.path.join(os.path.dirname(scene_file), spec["sid"]), "r") as sid:
        first_order = {t for t in ("Ct", "Cr", "Gr", "Oe") if f"terms/{t}/M1" in sid}
        method = sid["refmod/reduction_method"][()]
        method = method.decode() if isinstance(method, bytes) else str(method)
        massless = int(sid["refmod/n_high"][()]) if method in ("macneal", "craig-bampton-massless") else 0
    m = n - massless
    nv = min(nv, m)
    return (3 * m * m * ("Ct" in first_order) + k * m * m * ("Cr" in first_order) + 3 * k * nv * m * ("Gr" in first_order) +
            k * m * nv + k * (k + 1) // 2 * m * m * ("Oe" in first_order))


def bound_multiply_adds(summary, scene_file):
    nq = [b["nq"] for b in summary["bodies"]]
    frame = sum((n + 6) ** 2 for n in nq)
    frame += sum(first_order_multiply_adds(scene_file, b["name"], b["nq"], b["nq"] - b["quasistatic_modes"])
                 for b in summary["bodies"] if b["nq"] > 0)
    points = summary["rhs_cost"]["mean_active_points"]
    # a loaded point maps through the rows of the body it belongs to (the larger one, to bound from below)
    mapping = 2 * 3 * max(nq, default=0) * points
    return frame + mapping


def per_rhs(summary, scene_file, rate):
    """The computed right-hand sides (repeated ones are answered from the one before), µs per
    computed RHS by part, their total, and the bound in µs at `rate` multiply-adds per second."""
    n = summary["rhs_cost"]["evaluations"] - summary["rhs_cost"]["repeated"]
    per = {p: 1e6 * summary["time_split_s"][p] / n for p in PARTS}
    return n, per, sum(per.values()), 1e6 * bound_multiply_adds(summary, scene_file) / rate


def main():
    rate = dense_rate()
    info = machine()
    lines = ["## Runtime: cost per right-hand side against its bound",
             f"{info['date']}, {info['machine']}, commit {info['commit']}; `bench/cost_model.py`. "
             f"Time per computed right-hand side (RHS) from summary.json `time_split_s` (output: per RHS as well, though it runs per step; "
             f"RHS at the state of the one before are answered from it and not counted); "
             f"bound: the unavoidable multiply-adds (one product with each body's (nq + 6)^2 mass matrix; the SID's first-order terms "
             f"contracted with q and qdot where it carries them, Ct1 3 m^2 and, for k free rotation axes, Cr1 k m^2 + Gr1 3 k nv m + "
             f"Ge k m nv + Oe1 k (k + 1) / 2 m^2, m the coordinates with inertia and nv the integrated ones; and 2 x 3 x nq per loaded "
             f"contact point) at this core's dense rate, {rate / 1e9:.1f} G multiply-adds/s (600 x 600 matrix-vector product, one thread).",
             "The static solve runs passes over the contact points (a Newton step's residual, then its model solve); the last "
             "three columns give the passes per computed RHS, the static solve's mean time per pass (the clear surface's cheap "
             "passes included) and that time against the bound: while a pass costs more than 3x the bound on average, the "
             "evaluations that need one cannot be within 3x of it on average.",
             "", "| scene | nq (quasistatic) | RHS (repeated) | mean loaded points | µs per RHS | " + " | ".join(PARTS) +
             " | bound [µs] | ratio | static passes per RHS | µs per static pass | pass / bound |",
             "|---|---|---|---|---|" + "---|" * len(PARTS) + "---|---|---|---|---|"]
    with tempfile.TemporaryDirectory() as scratch:
        for label, name in SCENES:
            scene_file = os.path.join(ROOT, "models", name + ".scene.toml")
            s = run_json([RUN, "-q", "--json", scene_file, "-o", scratch])
            repeated = s["rhs_cost"]["repeated"]
            n, per, total, bound = per_rhs(s, scene_file, rate)
            nq = " + ".join(f"{b['nq']} ({b['quasistatic_modes']})" for b in s["bodies"] if b["nq"] > 0)
            passes = s["rhs_cost"]["quasistatic_passes"]
            per_pass = 1e6 * s["time_split_s"]["static_solve"] / passes if passes else 0.0
            lines.append(f"| {label} `{name}` | {nq} | {n + repeated} ({repeated}) | {s['rhs_cost']['mean_active_points']:.1f} | {total:.1f} | " +
                         " | ".join(f"{per[p]:.2f}" for p in PARTS) + f" | {bound:.2f} | {total / bound:.0f} | {passes / n:.2f} | "
                         f"{per_pass:.1f} | {per_pass / bound:.0f} |")
            print(lines[-1], file=sys.stderr)
    update_section("cost-model", "\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
