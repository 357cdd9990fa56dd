#!/usr/bin/env python3
"""Finite-sphere reference for sphere impacts: the static force-approach law
F(delta) of a linear elastic sphere pressed on a rigid, frictionless plane, computed with
CalculiX (ccx, Debian package calculix-ccx), and the impact it gives by integrating
m x'' = -F(x) (sphere on sphere, case A of docs/references.md, and two other spheres). Hertz is
the half-space limit.

Model (all choices below are the comparison's: the reduced model is linear, small strain,
frictionless):
- Axisymmetric meridian half disc of the sphere, quadratic CAX8 elements (ccx: x radial,
  y axial; it expands them to 2-degree C3D20 wedges, so reactions come per 2 degrees and are
  multiplied by 180 here; concentrated loads would be per 360 degrees). Mesh:
  finite_sphere_mesh.py, log-polar around the contact pole: every element near the contact
  is about 1.6/n_phi of its distance from the pole, so the contact radius is resolved by the
  same number of elements at every load; a uniform core of rho_c = 0.05 a_max (a_max the Hertz
  contact radius at 1.3 x the Hertz peak force) has elements rho_c/n_phi. Lengths go to ccx
  in mm (ccx rejects elements whose 3-D Jacobian is below 1e-20 in its units, which the
  sub-micron elements of a metre model are).
- Loading as in the impact: the plane stops the sphere, which is decelerated uniformly, so the
  static problem is the sphere under a uniform body force (d'Alembert, ccx *DLOAD GRAV)
  balanced by the contact reaction F = m g. The approach delta is the mass-weighted mean
  downward displacement of the sphere, i.e. the motion of its centre of mass: that is the x
  of m x'' = -F(x) exactly (momentum balance) and what the floating frame of the reduced model
  follows. The displacement of the centre node is reported as well (column delta_centre_m):
  it is not the right coordinate for m x'' = -F (the sphere's mean motion is), but shows how
  much the choice matters.
- Contact: exact frictionless node-on-plane contact by active sets, no penalty. Surface node
  i (height y0_i above the plane) is active when it touches: u_y = -y0_i. For the active set
  A_k = the k surface nodes nearest the axis the problem is linear, so two ccx solves give
  every equilibrium with that set: u = u0 + s u1, u0 closing the gaps of A_k without body
  force, u1 under unit body force with u_y = 0 on A_k. The set is the true one for all s with
  every reaction of A_k compressive and no other surface node below the plane; that is an
  interval [s_lo, s_hi] (linear inequalities in s). The free sphere is well posed in both
  solves: A_k holds the axial translation, the axis nodes have u_x = 0, nothing else is
  constrained, and the total reaction equals m s (checked). Each k thus gives an exact
  segment of the discrete law (F linear in delta on it); k is chosen near the Hertz
  contact radius of ~20 target forces from 0 to 1.3 x the Hertz peak. A k with an empty
  interval (a set that is never the equilibrium one) is reported and skipped.
- Convergence: meshes n_phi = 8, 16, 32, ... (each halves every element); the approach at
  0.25, 0.5, 1 and 1.3 x the Hertz peak force is printed per mesh (from the segments, the
  ratio delta/delta_Hertz interpolated linearly in F between them), and the curve of the
  finest mesh is stored.
- Impact: F(delta) = K delta^(3/2) phi(delta), K = 4/3 E* sqrt(R); phi (1 at the half-space
  limit, a few per cent below at these loads) is interpolated monotone-cubically in
  sqrt(delta) between the stored points (phi held at its first value below the first point,
  extrapolated linearly beyond the last). m x'' = -F(x) is integrated with RK4 from x = 0,
  x' = v0 until x returns to 0 (zero crossing interpolated); the peak force is F at the
  turning point (from the energy balance). The interpolation error is estimated by redoing it
  with phi piecewise linear, the integration error by halving the step; the same integrator
  run on the Hertz law is compared with Hertz's closed form.

Usage:
  finite_sphere.py NAME --radius R --E E --nu NU --rho RHO --v0 V [--meshes 8,16,32] [--levels 20]
      runs ccx (OMP_NUM_THREADS=1) for each mesh, prints the convergence table and the impact,
      writes bench/reference/finite_sphere_NAME.csv
  finite_sphere.py --check CSV [CSV...]
      re-integrates the impact from stored curves (no ccx), prints JSON and exits 1 if a result
      differs by more than 0.01 % from the value recorded in the CSV header.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

SEGMENT = 180.0
# Hertz contact time / (delta_max / v0) = 2 integral_0^1 dx / sqrt(1 - x^(5/2)) = (4/5) B(2/5, 1/2)
TC_FACTOR = 0.8 * math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9)  # ccx expands CAX elements to 2-degree wedges: reactions x 180 = whole ring


# ---------------------------------------------------------------------------------- Hertz
def hertz(R, E, nu, rho, v0):
    Es = E / (1 - nu * nu)
    m = 4.0 / 3.0 * math.pi * R ** 3 * rho
    K = 4.0 / 3.0 * Es * math.sqrt(R)
    dmax = (15 * m * v0 * v0 / (16 * Es * math.sqrt(R))) ** 0.4
    fmax = K * dmax ** 1.5
    return {"mass_kg": m, "K": K, "delta_max_m": dmax, "peak_force_n": fmax,
            "contact_time_s": TC_FACTOR * dmax / v0, "a_max_m": math.sqrt(R * dmax)}


# ------------------------------------------------------------------------- interpolation
def pchip_slopes(x, y):
    """Fritsch-Carlson monotone cubic slopes."""
    n = len(x)
    h = [x[i + 1] - x[i] for i in range(n - 1)]
    d = [(y[i + 1] - y[i]) / h[i] for i in range(n - 1)]
    m = [0.0] * n
    m[0], m[-1] = d[0], d[-1]
    for i in range(1, n - 1):
        if d[i - 1] * d[i] <= 0:
            m[i] = 0.0
        else:
            w1, w2 = 2 * h[i] + h[i - 1], h[i] + 2 * h[i - 1]
            m[i] = (w1 + w2) / (w1 / d[i - 1] + w2 / d[i])
    return m


class Law:
    """F(delta) = K delta^1.5 phi(sqrt(delta)), phi interpolated (cubic or linear)."""

    def __init__(self, K, delta, force, cubic=True):
        pts = sorted((math.sqrt(d), f / (K * d ** 1.5)) for d, f in zip(delta, force) if d > 0)
        self.K, self.x, self.y, self.cubic = K, [p[0] for p in pts], [p[1] for p in pts], cubic
        self.m = pchip_slopes(self.x, self.y) if cubic else None

    def phi(self, s):
        x, y = self.x, self.y
        if s <= x[0]:
            return y[0]
        if s >= x[-1]:
            return y[-1] + (y[-1] - y[-2]) / (x[-1] - x[-2]) * (s - x[-1])
        lo, hi = 0, len(x) - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if x[mid] <= s:
                lo = mid
            else:
                hi = mid
        h = x[hi] - x[lo]
        t = (s - x[lo]) / h
        if not self.cubic:
            return y[lo] + t * (y[hi] - y[lo])
        return ((2 * t ** 3 - 3 * t * t + 1) * y[lo] + (t ** 3 - 2 * t * t + t) * h * self.m[lo]
                + (-2 * t ** 3 + 3 * t * t) * y[hi] + (t ** 3 - t * t) * h * self.m[hi])

    def __call__(self, d):
        return self.K * d ** 1.5 * self.phi(math.sqrt(d)) if d > 0 else 0.0


def impact(force, m, v0, t_est, steps=20000):
    """RK4 on m x'' = -F(x), x(0) = 0, x'(0) = v0, until x returns to 0. Returns contact time,
    largest approach (turning point, where x' changes sign, interpolated) and peak force."""
    dt = t_est / steps
    t, x, v = 0.0, 0.0, v0
    acc = lambda x: -force(x) / m
    xmax = 0.0
    while True:
        k1x, k1v = v, acc(x)
        k2x, k2v = v + 0.5 * dt * k1v, acc(x + 0.5 * dt * k1x)
        k3x, k3v = v + 0.5 * dt * k2v, acc(x + 0.5 * dt * k2x)
        k4x, k4v = v + dt * k3v, acc(x + dt * k3x)
        xn = x + dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
        vn = v + dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
        if v > 0 >= vn:  # turning point: largest approach from the cubic Hermite of this step
            xmax = max(x, xn)
            # refine with the energy balance: the work of F up to xmax equals 1/2 m v0^2
            xmax = turning_point(force, m, v0, xmax)
        if t > 0.5 * t_est and xn <= 0:
            tc = t + dt * x / (x - xn)
            return tc, xmax, force(xmax)
        t, x, v = t + dt, xn, vn


def work(force, d, n=4000):
    """Integral of F from 0 to d (Simpson on d = s^2, which removes the d^1/2 behaviour)."""
    s1 = math.sqrt(d)
    h = s1 / n
    tot = 0.0
    for i in range(n + 1):
        s = i * h
        w = 1 if i in (0, n) else (4 if i % 2 else 2)
        tot += w * force(s * s) * 2 * s
    return tot * h / 3


def turning_point(force, m, v0, guess):
    e = 0.5 * m * v0 * v0
    d = guess
    for _ in range(30):
        r = work(force, d) - e
        d_new = d - r / force(d)
        if abs(d_new - d) < 1e-15 * d:
            return d_new
        d = d_new
    return d


def impact_reference(law_points, K, m, v0, t_est):
    """Impact from a law given by points (delta, F): cubic and linear phi, two RK4 steps."""
    delta, force = law_points
    cub, lin = Law(K, delta, force, True), Law(K, delta, force, False)
    tc, dmax, fmax = impact(cub, m, v0, t_est)
    tc2, _, _ = impact(cub, m, v0, t_est, steps=40000)
    tcl, _, fmaxl = impact(lin, m, v0, t_est)
    return {"peak_force_n": fmax, "contact_time_s": tc, "delta_max_m": dmax,
            "interpolation_error_peak_rel": abs(fmaxl - fmax) / fmax,
            "interpolation_error_time_rel": abs(tcl - tc) / tc,
            "integration_error_time_rel": abs(tc2 - tc) / tc}


# ----------------------------------------------------------------------------- ccx model
def shape(xi, eta):
    """CAX8 (serendipity) shape functions and their derivatives, ccx node order."""
    c = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    N, dx, dy = [], [], []
    for a, b in c:
        N.append(0.25 * (1 + a * xi) * (1 + b * eta) * (a * xi + b * eta - 1))
        dx.append(0.25 * a * (1 + eta * b) * (2 * xi * a + eta * b))
        dy.append(0.25 * b * (1 + xi * a) * (xi * a + 2 * eta * b))
    N += [0.5 * (1 - xi * xi) * (1 - eta), 0.5 * (1 + xi) * (1 - eta * eta), 0.5 * (1 - xi * xi) * (1 + eta),
          0.5 * (1 - xi) * (1 - eta * eta)]
    dx += [-xi * (1 - eta), 0.5 * (1 - eta * eta), -xi * (1 + eta), -0.5 * (1 - eta * eta)]
    dy += [-0.5 * (1 - xi * xi), -eta * (1 + xi), 0.5 * (1 - xi * xi), -eta * (1 - xi)]
    return N, dx, dy


def volume_weights(nodes, elements):
    """w_i = integral of N_i 2 pi r dA (3 x 3 Gauss): the mass-weighted mean of a nodal field
    u is sum w_i u_i / sum w_i."""
    g = [(-math.sqrt(0.6), 5 / 9), (0.0, 8 / 9), (math.sqrt(0.6), 5 / 9)]
    tab = [(shape(a, b), wa * wb) for a, wa in g for b, wb in g]
    w = {}
    for e in elements:
        P = [nodes[i] for i in e]
        for (N, dx, dy), wg in tab:
            x = sum(n * p[0] for n, p in zip(N, P))
            J = (sum(a * p[0] for a, p in zip(dx, P)) * sum(b * p[1] for b, p in zip(dy, P))
                 - sum(b * p[0] for b, p in zip(dy, P)) * sum(a * p[1] for a, p in zip(dx, P)))
            f = wg * J * 2 * math.pi * x
            for i, n in zip(e, N):
                w[i] = w.get(i, 0.0) + n * f
    return w


class Model:
    def __init__(self, R, E, nu, rho, n_phi, rho_c, workdir):
        import finite_sphere_mesh as mesh
        self.R, self.E, self.nu, self.rho = R, E, nu, rho
        self.nodes, self.elements, self.info = mesh.build(R, rho_c, n_phi)
        self.axis = [i for i, p in self.nodes.items() if p[0] == 0.0]
        self.surface = sorted((i for i, p in self.nodes.items()
                               if abs(math.hypot(p[0], p[1] - R) - R) < 1e-9 * R and p[1] < 0.25 * R),
                              key=lambda i: self.nodes[i][0])
        assert self.surface[0] == self.info["pole"]
        self.w = volume_weights(self.nodes, self.elements)
        self.volume = sum(self.w.values())
        self.workdir = workdir
        self.ccx_seconds = 0.0
        self.solves = 0

    def deck(self, k):
        mm = 1e3
        L = ["** finite_sphere.py: sphere R=%g m on a rigid plane, active set = %d surface nodes" % (self.R, k),
             "*NODE"]
        L += ["%d,%.13e,%.13e,0." % (i, mm * p[0], mm * p[1]) for i, p in self.nodes.items()]
        L.append("*ELEMENT,TYPE=CAX8,ELSET=EALL")
        L += ["%d,%s" % (n + 1, ",".join(map(str, e))) for n, e in enumerate(self.elements)]
        act = self.surface[:k]
        L.append("*NSET,NSET=AXIS")
        L += [str(i) for i in self.axis]
        L += ["*NSET,NSET=NALL,GENERATE", "1,%d,1" % max(self.nodes)]
        L.append("*NSET,NSET=ACT")
        L += [str(i) for i in act]
        # N, mm, t, s units
        L += ["*MATERIAL,NAME=M", "*ELASTIC", "%.10e,%.10g" % (self.E * 1e-6, self.nu),
              "*DENSITY", "%.10e" % (self.rho * 1e-12), "*SOLID SECTION,ELSET=EALL,MATERIAL=M"]
        # step 1: gaps of the active nodes closed, no body force
        L += ["*STEP", "*STATIC", "*BOUNDARY", "AXIS,1,1"]
        L += ["%d,2,2,%.13e" % (i, -mm * self.nodes[i][1]) for i in act]
        L += ["*NODE PRINT,NSET=NALL", "U,RF", "*END STEP"]
        # step 2: unit body force (1 m/s^2 downward = 1000 mm/s^2), active nodes held at u_y = 0
        L += ["*STEP", "*STATIC", "*BOUNDARY,OP=NEW", "AXIS,1,1"]
        L += ["%d,2,2,0." % i for i in act]
        L += ["*DLOAD", "EALL,GRAV,1000.,0.,-1.,0."]
        L += ["*NODE PRINT,NSET=NALL", "U,RF", "*END STEP"]
        return "\n".join(L) + "\n"

    def run(self, k):
        job = "k%03d" % k
        with open(os.path.join(self.workdir, job + ".inp"), "w") as f:
            f.write(self.deck(k))
        t = time.time()
        r = subprocess.run(["ccx", "-i", job], cwd=self.workdir, capture_output=True, text=True,
                           env=dict(os.environ, OMP_NUM_THREADS="1"))
        self.ccx_seconds += time.time() - t
        self.solves += 1
        if r.returncode != 0 or "*ERROR" in r.stdout:
            raise RuntimeError("ccx failed for %s:\n%s" % (job, r.stdout[-2000:]))
        res = parse_dat(os.path.join(self.workdir, job + ".dat"))
        for ext in (".inp", ".dat", ".frd", ".sta", ".cvg", ".12d"):
            try:
                os.remove(os.path.join(self.workdir, job + ext))
            except OSError:
                pass
        return res

    def segment(self, k):
        """Exact segment of the discrete law for the active set of the k nodes nearest the axis:
        (s_lo, s_hi, F(s), delta(s), delta_centre(s)) with s the body-force level in m/s^2."""
        res = self.run(k)
        act, free = self.surface[:k], self.surface[k:]
        u0, r0 = res[1]
        u1, r1 = res[2]
        mm = 1e-3
        y = lambda i: self.nodes[i][1]
        lo, hi = 0.0, math.inf
        # reactions compressive: r0 + s r1 >= 0 (y component, whole ring)
        for i in act:
            a, b = r0[i][1], r1[i][1]
            lo, hi = bound(lo, hi, a, b)
        for i in free:
            a, b = y(i) + mm * u0[i][1], mm * u1[i][1]
            lo, hi = bound(lo, hi, a, b)
        ftot0 = SEGMENT * sum(r0[i][1] for i in act)
        ftot1 = SEGMENT * sum(r1[i][1] for i in act)
        mass = self.rho * self.volume
        mean = lambda u: -mm * sum(self.w[i] * u[i][1] for i in self.nodes) / self.volume
        c = self.info["centre"]
        return {"k": k, "s_lo": lo, "s_hi": hi, "F0": ftot0, "F1": ftot1, "mass": mass,
                "d0": mean(u0), "d1": mean(u1), "c0": -mm * u0[c][1], "c1": -mm * u1[c][1],
                "edge_lo_m": self.nodes[act[-1]][0], "edge_hi_m": self.nodes[free[0]][0]}


def bound(lo, hi, a, b):
    """Restrict [lo, hi] to the s with a + s b >= 0."""
    if b > 0:
        lo = max(lo, -a / b)
    elif b < 0:
        hi = min(hi, -a / b)
    elif a < 0:
        lo, hi = 1.0, 0.0
    return lo, hi


def parse_dat(path):
    """{step: (U {node: (ux, uy, uz)}, RF {node: (fx, fy, fz)})} from a ccx .dat file (step = time)."""
    out, cur = {}, None
    with open(path) as f:
        for line in f:
            m = re.match(r"\s*(displacements|forces) \S+ for set (\S+) and time\s+(\S+)", line)
            if m:
                step = int(round(float(m.group(3))))
                out.setdefault(step, ({}, {}))
                cur = out[step][0 if m.group(1) == "displacements" else 1]
                continue
            p = line.split()
            if cur is not None and len(p) == 4 and p[0].isdigit():
                cur[int(p[0])] = tuple(float(v) for v in p[1:])
            elif p and not p[0].isdigit():
                cur = None
    return out


# ------------------------------------------------------------------------------- driver
def mesh_law(R, E, nu, rho, n_phi, hz, levels, workdir, log):
    a_max = math.sqrt(R * hz["delta_max_m"]) * 1.3 ** (1 / 3)
    model = Model(R, E, nu, rho, n_phi, 0.05 * a_max, workdir)
    xs = [model.nodes[i][0] for i in model.surface]
    ks = []
    for j in range(1, levels + 1):
        f = 1.3 * hz["peak_force_n"] * (j / levels) ** 1.5        # uniform in the Hertz approach
        a = (3 * f * R / (4 * E / (1 - nu * nu))) ** (1 / 3)
        k = max(1, sum(1 for x in xs if x <= a))
        if k not in ks:
            ks.append(k)
    ks += [k for k in (ks[-1] + 1, ks[-1] + 2) if k <= len(xs) - 1]  # reach past 1.3 x the Hertz peak
    segs, empty = [], []
    for k in ks:
        s = model.segment(k)
        if s["s_lo"] <= s["s_hi"]:
            segs.append(s)
        else:
            empty.append(k)
    info = dict(model.info)
    info.update({"ccx_s": model.ccx_seconds, "solves": model.solves, "empty_sets": empty,
                 "surface_nodes_in_contact_at_peak": sum(1 for x in xs if x <= a_max / 1.3 ** (1 / 3)),
                 "mass_kg": model.rho * model.volume})
    log("mesh n_phi=%d: %d elements, %d nodes, smallest %.3g um, ring ratio %.4f, %d solves, ccx %.0f s, "
        "active sets never in equilibrium: %s" % (n_phi, info["elements"], info["nodes"], 1e6 * info["smallest_m"],
                                                  info["ring_ratio"], model.solves, model.ccx_seconds, empty or "none"))
    for s in segs:
        rel = abs(s["F1"] - s["mass"]) / s["mass"]
        if rel > 1e-3 or abs(s["F0"]) > 1e-6 * hz["peak_force_n"]:
            log("  warning: k=%d total reaction %.6g vs m=%.6g (unit body force), %.3g without" % (
                s["k"], s["F1"], s["mass"], s["F0"]))
    return segs, info


def points(segs):
    """Law points (F, delta, delta_centre) at the ends of every segment, sorted by force."""
    pts = []
    for s in segs:
        for sv in (s["s_lo"], s["s_hi"]):
            if math.isfinite(sv) and sv > 0:
                pts.append((s["F1"] * sv, s["d0"] + s["d1"] * sv, s["c0"] + s["c1"] * sv))
    return sorted(set(pts))


def approach_at(pts, f, K):
    """delta at force f: delta/delta_Hertz interpolated linearly in f between the points."""
    dh = lambda F: (F / K) ** (2 / 3)
    for (f0, d0, _), (f1, d1, _) in zip(pts, pts[1:]):
        if f0 <= f <= f1:
            r0, r1 = d0 / dh(f0), d1 / dh(f1)
            return dh(f) * (r0 + (r1 - r0) * (f - f0) / (f1 - f0))
    return float("nan")


def write_csv(path, name, args, hz, segs_info, pts, result, command):
    R, E, nu, rho, v0 = args.radius, args.E, args.nu, args.rho, args.v0
    with open(path, "w") as f:
        f.write("# finite_sphere.py: static force-approach law of a linear elastic sphere on a rigid frictionless\n")
        f.write("# plane, CalculiX CAX8, exact active-set contact, uniform body-force (d'Alembert) loading.\n")
        f.write("# name=%s radius_m=%r E_pa=%r nu=%r rho_kg_m3=%r v0_m_s=%r\n" % (name, R, E, nu, rho, v0))
        info = segs_info
        f.write("# mesh: n_phi=%d, %d CAX8 elements, %d nodes, smallest element %.4g m, core radius %.4g m, "
                "ring ratio %.5f\n" % (info["n_phi"], info["elements"], info["nodes"], info["smallest_m"],
                                       info["rho_c"], info["ring_ratio"]))
        f.write("# delta_m: mass-weighted mean displacement (centre of mass); delta_centre_m: centre node;\n")
        f.write("# delta_hertz_m: (F / (4/3 E/(1-nu^2) sqrt(R)))^(2/3). Points are the ends of exact segments.\n")
        f.write("# hertz: peak_force_n=%.8g contact_time_s=%.8g\n" % (hz["peak_force_n"], hz["contact_time_s"]))
        f.write("# impact: peak_force_n=%.8g contact_time_s=%.8g\n" % (result["peak_force_n"], result["contact_time_s"]))
        f.write("# regenerate: %s\n" % command)
        f.write("# mesh convergence: finite_sphere_%s.log (what the run printed)\n" % name)
        f.write("force_n,delta_m,delta_hertz_m,delta_centre_m\n")
        for F, d, dc in pts:
            f.write("%.10e,%.10e,%.10e,%.10e\n" % (F, d, (F / hz["K"]) ** (2 / 3), dc))


def read_csv(path):
    head, rows = {}, []
    with open(path) as f:
        for line in f:
            if line.startswith(("# name=", "# hertz:", "# impact:")):
                prefix = "" if line.startswith("# name=") else line[2:].split(":")[0] + "."
                for k, v in re.findall(r"(\w+)=([^\s,]+)", line):
                    head[prefix + k] = v
            elif line[0].isdigit() or line[0] == "-":
                rows.append([float(v) for v in line.split(",")])
    return head, rows


def evaluate(R, E, nu, rho, v0, pts):
    hz = hertz(R, E, nu, rho, v0)
    m = hz["mass_kg"]
    force = [p[0] for p in pts]
    res = impact_reference(([p[1] for p in pts], force), hz["K"], m, v0, hz["contact_time_s"])
    res_c = impact_reference(([p[2] for p in pts], force), hz["K"], m, v0, hz["contact_time_s"])
    kh = hz["K"]
    tch, dh, fh = impact(lambda d: kh * d ** 1.5 if d > 0 else 0.0, m, v0, hz["contact_time_s"])
    a = math.sqrt(R * res["delta_max_m"])
    out = {"hertz": {"peak_force_n": hz["peak_force_n"], "contact_time_s": hz["contact_time_s"],
                     "delta_max_m": hz["delta_max_m"], "contact_radius_m": hz["a_max_m"],
                     "integrator_error_peak_rel": fh / hz["peak_force_n"] - 1,
                     "integrator_error_time_rel": tch / hz["contact_time_s"] - 1},
           "finite_sphere": res,
           "finite_sphere_centre_node": {k: res_c[k] for k in ("peak_force_n", "contact_time_s", "delta_max_m")},
           "difference_from_hertz_percent": {
               "peak_force": 100 * (res["peak_force_n"] / hz["peak_force_n"] - 1),
               "contact_time": 100 * (res["contact_time_s"] / hz["contact_time_s"] - 1)},
           "half_a_over_R_percent": 50 * a / R,
           "approach_below_hertz_at_hertz_peak_percent": 100 * (1 - approach_at(
               pts, hz["peak_force_n"], hz["K"]) / hz["delta_max_m"]),
           "law_points": len(pts), "law_force_range_n": [min(force), max(force)]}
    return out


def check(paths):
    ok = True
    for path in paths:
        head, rows = read_csv(path)
        R, E, nu, rho, v0 = (float(head[k]) for k in ("radius_m", "E_pa", "nu", "rho_kg_m3", "v0_m_s"))
        out = evaluate(R, E, nu, rho, v0, [(r[0], r[1], r[3]) for r in rows])
        out["name"] = head["name"]
        for key in ("peak_force_n", "contact_time_s"):
            stored = float(head["impact." + key])
            rel = abs(out["finite_sphere"][key] / stored - 1)
            out["finite_sphere"][key + "_stored"] = stored
            if rel > 1e-4:
                ok = False
                out.setdefault("failures", []).append("%s %g vs stored %g" % (key, out["finite_sphere"][key], stored))
        print(json.dumps(out, indent=2))
    return ok


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--check":
        sys.exit(0 if check(sys.argv[2:]) else 1)
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("name")
    p.add_argument("--radius", type=float, required=True)
    p.add_argument("--E", type=float, required=True)
    p.add_argument("--nu", type=float, required=True)
    p.add_argument("--rho", type=float, required=True)
    p.add_argument("--v0", type=float, required=True)
    p.add_argument("--meshes", default="8,16,32")
    p.add_argument("--levels", type=int, default=20)
    p.add_argument("--out", default=None)
    args = p.parse_args()
    command = "bench/reference/finite_sphere.py " + " ".join(sys.argv[1:])
    lines = []

    def log(s):
        print(s, file=sys.stderr, flush=True)
        lines.append(s)

    hz = hertz(args.radius, args.E, args.nu, args.rho, args.v0)
    log("Hertz: peak %.4f N, contact time %.4f us, approach %.4f um, contact radius %.4f mm, mass %.6g kg"
        % (hz["peak_force_n"], 1e6 * hz["contact_time_s"], 1e6 * hz["delta_max_m"], 1e3 * hz["a_max_m"], hz["mass_kg"]))
    levels = [0.25, 0.5, 1.0, 1.3]
    table, last = [], None
    with tempfile.TemporaryDirectory(prefix="finite_sphere_") as work:
        for n in [int(v) for v in args.meshes.split(",")]:
            segs, info = mesh_law(args.radius, args.E, args.nu, args.rho, n, hz, args.levels, work, log)
            pts = points(segs)
            row = [approach_at(pts, lv * hz["peak_force_n"], hz["K"]) for lv in levels]
            res = evaluate(args.radius, args.E, args.nu, args.rho, args.v0, pts)
            table.append((n, info, row, res))
            line = "  n_phi=%3d approach/Hertz at F/Fh=%s:" % (n, ",".join(map(str, levels)))
            line += " ".join(" %.6f" % (d / (lv * hz["peak_force_n"] / hz["K"]) ** (2 / 3)) for d, lv in zip(row, levels))
            line += " | impact: peak %.5f N, contact %.5f us" % (res["finite_sphere"]["peak_force_n"],
                                                                 1e6 * res["finite_sphere"]["contact_time_s"])
            log(line)
            if last is not None:
                log("    change from previous mesh: approach %s %%, peak %+.4f %%, contact time %+.4f %%" % (
                    " ".join("%+.4f" % (100 * (d / dl - 1)) for d, dl in zip(row, last[2])),
                    100 * (res["finite_sphere"]["peak_force_n"] / last[3]["finite_sphere"]["peak_force_n"] - 1),
                    100 * (res["finite_sphere"]["contact_time_s"] / last[3]["finite_sphere"]["contact_time_s"] - 1)))
            last = table[-1]
            final_pts, final_info = pts, info
    res = table[-1][3]
    out = args.out or os.path.join(HERE, "finite_sphere_%s.csv" % args.name)
    write_csv(out, args.name, args, hz, final_info, final_pts, res["finite_sphere"], command)
    with open(os.path.splitext(out)[0] + ".log", "w") as f:  # the mesh convergence, as printed
        f.write("# %s\n" % command + "\n".join(lines) + "\n")
    summary = {"name": args.name, "result": res, "meshes": [
        {"n_phi": n, "elements": i["elements"], "nodes": i["nodes"], "smallest_m": i["smallest_m"],
         "ccx_s": round(i["ccx_s"], 1), "solves": i["solves"], "empty_sets": i["empty_sets"],
         "approach_m": dict(zip(map(str, levels), row)),
         "peak_force_n": r["finite_sphere"]["peak_force_n"], "contact_time_s": r["finite_sphere"]["contact_time_s"]}
        for n, i, row, r in table], "csv": out}
    print(json.dumps(summary, indent=2))


if __name__ == "__main__":
    main()
