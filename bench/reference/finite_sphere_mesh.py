"""Structured CAX8 mesh of the meridian half disc of a sphere, graded toward its contact pole.

Coordinates as CalculiX axisymmetric elements want them: x radial (x >= 0), y axial. The pole
touching the plane is the origin, the centre is (0, R). Around the pole the mesh is polar:
rings at distances rho from the pole (rho_c <= rho <= rho_o = R/2), growing geometrically so that
every element is about as long as it is wide (d rho / rho = d phi), the n_phi angular
divisions of each ring spanning the section from the axis (phi = 0) to the sphere surface
(phi = acos(rho / 2R)). The elements at the contact are thus a fixed fraction (about
1.6 / n_phi) of their distance from the pole, i.e. of the contact radius, at every load.
Inside rho_c (the "core") and beyond rho_o (the rest of the sphere) the three-cornered
regions are each split into three transfinite (Coons) quadrilateral blocks. One integer,
n_phi, sets the whole mesh; doubling it halves every element (a nested refinement).
Midside nodes of boundary edges lie on the exact sphere."""
import math


def polar(R, rho, t):
    """Point at distance rho from the pole, at fraction t of the angle from the axis (t = 0)
    to the sphere surface (t = 1)."""
    phi = t * math.acos(min(1.0, rho / (2.0 * R)))
    return (rho * math.sin(phi), rho * math.cos(phi))


def surface(R, theta):
    """Point of the sphere at angle theta from the downward axis, measured at the centre."""
    return (R * math.sin(theta), R - R * math.cos(theta))


def line(p, q, n):
    return [(p[0] + (q[0] - p[0]) * i / n, p[1] + (q[1] - p[1]) * i / n) for i in range(n + 1)]


def coons(bottom, right, top, left):
    """Transfinite interpolation; bottom/top run from the left edge to the right edge, left/right
    from the bottom edge to the top edge. Returns grid[i][j]; boundary points are exact copies."""
    n, m = len(bottom) - 1, len(left) - 1
    assert len(top) == n + 1 and len(right) == m + 1
    c00, cn0, c0m, cnm = bottom[0], bottom[n], top[0], top[n]
    g = []
    for i in range(n + 1):
        s = i / n
        col = []
        for j in range(m + 1):
            t = j / m
            if j == 0:
                col.append(bottom[i]); continue
            if j == m:
                col.append(top[i]); continue
            if i == 0:
                col.append(left[j]); continue
            if i == n:
                col.append(right[j]); continue
            p = []
            for k in range(2):
                p.append((1 - t) * bottom[i][k] + t * top[i][k] + (1 - s) * left[j][k] + s * right[j][k]
                         - ((1 - s) * (1 - t) * c00[k] + s * (1 - t) * cn0[k] + (1 - s) * t * c0m[k] + s * t * cnm[k]))
            col.append(tuple(p))
        g.append(col)
    return g


def build(R, rho_c, n_phi):
    """Returns (nodes {id: (x, y)}, elements [(n1..n8)], info). n_phi even: angular divisions."""
    assert n_phi % 2 == 0
    h = n_phi // 2          # divisions of every block edge of the core and of the outer part
    rho_o = 0.5 * R
    n_rho = max(1, round(math.log(rho_o / rho_c) * n_phi / (0.5 * math.pi)))
    grids = []
    # ring region: i along rho (double resolution for the midside nodes), j along t
    rhos = [rho_c * (rho_o / rho_c) ** (k / (2 * n_rho)) for k in range(2 * n_rho + 1)]
    rhos[0], rhos[-1] = rho_c, rho_o
    grids.append([[polar(R, r, j / (2 * n_phi)) for j in range(2 * n_phi + 1)] for r in rhos])
    # core: pole O, axis point Qa, surface point Qs at rho_c, split from an interior point P
    arc = [polar(R, rho_c, j / (2 * n_phi)) for j in range(2 * n_phi + 1)]     # axis -> surface
    O, Qa, Qs, Marc = (0.0, 0.0), arc[0], arc[-1], arc[n_phi]
    Max = (0.0, 0.5 * rho_c)
    # surface points of the core from the pole to Qs (angle at the centre)
    th_s = math.atan2(Qs[0], R - Qs[1])
    srf = [surface(R, th_s * k / (4 * h)) for k in range(4 * h + 1)]
    srf[0], srf[-1] = O, Qs
    Msf = srf[2 * h]
    P = ((Marc[0] + Max[0] + Msf[0]) / 3, (Marc[1] + Max[1] + Msf[1]) / 3)
    axis = [(0.0, rho_c * k / (4 * h)) for k in range(4 * h + 1)]
    e_sp, e_ap, e_pm = line(Msf, P, 2 * h), line(Max, P, 2 * h), line(P, Marc, 2 * h)
    grids.append(coons(srf[:2 * h + 1], e_sp, e_ap, axis[:2 * h + 1]))           # O, Msf, P, Max
    grids.append(coons(srf[2 * h:], list(reversed(arc[n_phi:])), e_pm, e_sp))    # Msf, Qs, Marc, P
    grids.append(coons(e_pm, list(reversed(arc[:n_phi + 1])), axis[2 * h:], list(reversed(e_ap))))  # P, Marc, Qa, Max
    # outer part: A (axis, rho_o), B (surface, rho_o), D (top); split at Mab, Mbd, centre C, P2
    outer = grids[0][-1]                                                       # axis -> surface at rho_o
    A, B, Mab = outer[0], outer[-1], outer[n_phi]
    th_b = math.atan2(B[0], R - B[1])
    srf2 = [surface(R, th_b + (math.pi - th_b) * k / (4 * h)) for k in range(4 * h + 1)]
    srf2[0], srf2[-1] = B, (0.0, 2 * R)
    Mbd, D, C = srf2[2 * h], srf2[-1], (0.0, R)
    P2 = ((Mab[0] + Mbd[0] + C[0]) / 3, (Mab[1] + Mbd[1] + C[1]) / 3)
    ax_lo = [(0.0, A[1] + (C[1] - A[1]) * k / (2 * h)) for k in range(2 * h + 1)]
    ax_hi = [(0.0, C[1] + (D[1] - C[1]) * k / (2 * h)) for k in range(2 * h + 1)]
    e_mp, e_pb, e_cp = line(Mab, P2, 2 * h), line(P2, Mbd, 2 * h), line(C, P2, 2 * h)
    grids.append(coons(outer[:n_phi + 1], e_mp, e_cp, ax_lo))                 # A, Mab, P2, C
    grids.append(coons(outer[n_phi:], srf2[:2 * h + 1], e_pb, e_mp))  # Mab, B, Mbd, P2
    grids.append(coons(e_pb, srf2[2 * h:], ax_hi, list(reversed(e_cp))))     # P2, Mbd, D, C
    # merge nodes (shared edges are identical copies), make elements
    ids, nodes, elements = {}, {}, []

    def nid(p):
        if p not in ids:
            ids[p] = len(ids) + 1
            nodes[ids[p]] = p
        return ids[p]

    for g in grids:
        a, b = (len(g) - 1) // 2, (len(g[0]) - 1) // 2
        for I in range(a):
            for J in range(b):
                i, j = 2 * I, 2 * J
                c = [g[i][j], g[i + 2][j], g[i + 2][j + 2], g[i][j + 2]]
                mid = [g[i + 1][j], g[i + 2][j + 1], g[i + 1][j + 2], g[i][j + 1]]
                area = sum(c[k][0] * c[(k + 1) % 4][1] - c[(k + 1) % 4][0] * c[k][1] for k in range(4))
                if area < 0:
                    c = [c[0], c[3], c[2], c[1]]
                    mid = [mid[3], mid[2], mid[1], mid[0]]
                # a CAX8 side on the axis must be the side 4-1 (CalculiX 2.20 rejects, with "nonpositive
                # jacobian", the expanded element of one whose side 3-4 lies on the axis): rotate
                for _ in range(4):
                    if not (c[2][0] == 0.0 and c[3][0] == 0.0) and not (c[1][0] == 0.0 and c[2][0] == 0.0) \
                            and not (c[0][0] == 0.0 and c[1][0] == 0.0):
                        break
                    c, mid = c[1:] + c[:1], mid[1:] + mid[:1]
                elements.append(tuple(nid(p) for p in c + mid))
    info = {"n_phi": n_phi, "n_rho": n_rho, "rho_c": rho_c, "rho_o": rho_o, "elements": len(elements),
            "nodes": len(nodes), "pole": ids[O], "centre": ids[C],
            "smallest_m": rho_c / n_phi, "ring_ratio": (rho_o / rho_c) ** (1 / n_rho)}
    return nodes, elements, info
