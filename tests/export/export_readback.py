#!/usr/bin/python3
"""isosid-export read back by readers written here from the published layouts, and every
term compared entry by entry with the SID (h5py), to 1e-12 of the term's largest entry.

- sid-fem: parsed as the Modelica EMBS library's C reader does (vwaurich/EMBS_ModelicaLib,
  ReadSID_C.h; docs/references.md [R12]): the first two runs of digits of line
  1 are the node and mode counts; blocks by keyword; Taylor headers order/nrow/ncol/nq/nqn/
  structure; m0(row, col) and m1(row, q, col), 1-based; D exponents; missing entries are 0;
  J is 6 x 1 (xx yy zz xy xz yz).
- mbsim-h5: MBSim's datasets at the root, whose root group must track link creation order;
  the SID terms rebuilt from its volume integrals with the formulas of Schwertassek &
  Wallrapp as MBSim assembles them (docs/references.md [R8]).

usage: export_readback.py ISOSID_EXPORT ISOSID_PREP REPO_DIR
Exports the golden SIDs (an axisymmetric Craig-Bampton sphere, a 3D beam) and checks that a
massless-boundary SID (models/bar_drop_macneal) is refused."""
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

TERMS = ["mdCM", "J", "Ct", "Cr", "Me", "Gr", "Ge", "Oe", "ksigma", "Ke", "De"]
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def close(a, b, tol=1e-12):
    a, b = np.asarray(a, float), np.asarray(b, float)
    if a.shape != b.shape:
        return False
    scale = max(np.abs(b).max() if b.size else 0.0, 1e-300)
    return np.abs(a - b).max() / scale <= tol if b.size else True


# ---------------------------------------------------------------- the SID, with h5py
def sid_taylor(group, nq):
    m0 = group["M0"][()]
    m1 = group["M1"][()] if "M1" in group else np.zeros((nq,) + m0.shape)
    return m0, m1  # m1[k] is the coefficient of q_k


def read_sid(path):
    with h5py.File(path, "r") as f:
        nq = int(f["refmod/nq"][()])
        sid = {"nq": nq, "mass": float(f["refmod/mass"][()]), "method": f["refmod/reduction_method"][()].decode()}
        sid["terms"] = {t: sid_taylor(f["terms"][t], nq) for t in TERMS}
        sid["nodes"] = []
        nodes, order = f["nodes"], []  # in the order written: h5py lists by name, so ask the creation-order index
        nodes.id.links.iterate(lambda n: order.append(n.decode()) or None, idx_type=h5py.h5.INDEX_CRT_ORDER)
        for name in order:
            g = nodes[name]
            sid["nodes"].append({"origin": sid_taylor(g["origin"], nq), "phi": g["phi"][()], "psi": g["psi"][()],
                                 "AP": sid_taylor(g["AP"], nq)})
        return sid


# ---------------------------------------------------------------- SID_FEM, as EMBS reads it
def embs_real(text):
    """A value as EMBS's getNextReal reads it: mantissa, then an uppercase D exponent."""
    m = re.match(r"\s*(-?[0-9.]+)(?:D([+-]?[0-9]+))?\s*$", text)
    if not m:
        raise ValueError(f"not an EMBS number: {text!r}")
    return float(m.group(1)) * (10.0 ** int(m.group(2)) if m.group(2) else 1.0)


def read_taylor_block(lines, i, name):
    """The Taylor block whose name line is lines[i]; returns (M0, M1 as nq x nrow x ncol), next i."""
    header = {}
    i += 1
    for key in ("order", "nrow", "ncol", "nq", "nqn", "structure"):
        k, v = lines[i].split("=")
        if k.strip() != key:
            raise ValueError(f"{name}: expected '{key}', got {lines[i]!r}")
        header[key] = int(v)
        i += 1
    nrow, ncol, nq = header["nrow"], header["ncol"], header["nq"]
    m0, m1 = np.zeros((nrow, ncol)), np.zeros((nq, nrow, ncol))
    while lines[i].strip() != f"end {name}":
        key, value = lines[i].split("=")
        idx = [int(x) for x in re.findall(r"\d+", key.split("(")[1])]
        if key.strip().startswith("m0"):
            m0[idx[0] - 1, idx[1] - 1] = embs_real(value)
        elif key.strip().startswith("m1"):  # m1(row, q, col)
            m1[idx[1] - 1, idx[0] - 1, idx[2] - 1] = embs_real(value)
        else:
            raise ValueError(f"{name}: unexpected line {lines[i]!r}")
        i += 1
    if header["order"] == 0 and m1.any():
        raise ValueError(f"{name}: order 0 with m1 entries")
    return (m0, m1), i + 1


def read_sid_fem(path):
    lines = Path(path).read_text().splitlines()
    counts = re.findall(r"\d+", lines[0])
    out = {"nodes_declared": int(counts[0]), "nq": int(counts[1]), "nodes": [], "terms": {}}
    i = 1
    while i < len(lines):
        word = lines[i].strip()
        if word.startswith("mass"):
            out["mass"] = embs_real(lines[i].split("=")[1])
        elif word.startswith("new node"):
            node = {}
            i += 1
            while lines[i].strip() != "end node":
                w = lines[i].strip()
                if w in ("origin", "phi", "psi", "AP"):
                    node[w], i = read_taylor_block(lines, i, w)
                    continue
                i += 1
            out["nodes"].append(node)
        elif word in TERMS:
            out["terms"][word], i = read_taylor_block(lines, i, word)
            continue
        i += 1
    return out


def j_matrix(column):
    xx, yy, zz, xy, xz, yz = column[:, 0]
    return np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])


def check_sid_fem(exe, sid_path, work):
    out = work / (sid_path.stem + ".SID_FEM")
    subprocess.run([exe, sid_path, "--format", "sid-fem", "-o", out], check=True, capture_output=True)
    sid, fem = read_sid(sid_path), read_sid_fem(out)
    name = sid_path.name
    check(fem["nq"] == sid["nq"] and fem["nodes_declared"] == len(sid["nodes"]) == len(fem["nodes"]),
          f"{name} sid-fem: line 1 gives {len(sid['nodes'])} nodes and nq = {sid['nq']}")
    check(close(fem["mass"], sid["mass"]), f"{name} sid-fem: refmod mass")
    for t in TERMS:
        m0, m1 = fem["terms"][t]
        s0, s1 = sid["terms"][t]
        if t == "J":  # EMBS's 6 x 1 column
            m0 = j_matrix(m0)
            m1 = np.array([j_matrix(x) for x in m1])
        check(close(m0, s0) and close(m1, s1), f"{name} sid-fem: {t} M0 {s0.shape} and M1 entry by entry")
    for n, (fn, sn) in enumerate(zip(fem["nodes"], sid["nodes"])):
        ok = close(fn["origin"][0], sn["origin"][0]) and close(fn["origin"][1], sn["origin"][1])
        ok &= close(fn["phi"][0], sn["phi"]) and close(fn["psi"][0], sn["psi"])
        ok &= close(fn["AP"][0], sn["AP"][0]) and close(fn["AP"][1], sn["AP"][1])
        check(ok, f"{name} sid-fem: node {n + 1}: origin, phi, psi, AP")


# ---------------------------------------------------------------- MBSim, rebuilt into SID terms
def check_mbsim(exe, sid_path, work):
    out = work / (sid_path.stem + ".mbsim.h5")
    subprocess.run([exe, sid_path, "--format", "mbsim-h5", "-o", out], check=True, capture_output=True)
    sid = read_sid(sid_path)
    nq = sid["nq"]
    name = sid_path.name
    with h5py.File(out, "r") as f:
        root = f["/"]
        check((root.id.get_create_plist().get_link_creation_order() & h5py.h5p.CRT_ORDER_TRACKED) != 0,
              f"{name} mbsim-h5: the root group tracks link creation order")
        check(not any(len(f[k].attrs) for k in f), f"{name} mbsim-h5: datasets only, no attributes")
        m, rdm, rrdm = f["mass"][()], f["position integral"][()], f["position position integral"][()]
        Pdm, rPdm, PPdm = f["shape function integral"][()], f["position shape function integral"][()], \
            f["shape function shape function integral"][()]
        K, D = f["stiffness matrix"][()], f["damping matrix"][()]
        nodes = {k: f[k][()] for k in ("nodal relative position", "nodal shape matrix of translation",
                                       "nodal shape matrix of rotation") if k in f}
    check(Pdm.shape == (3, nq) and rPdm.shape == (9, nq) and PPdm.shape == (6 * nq, nq),
          f"{name} mbsim-h5: shapes 3 x nq, 9 x nq, 6nq x nq")
    check(np.abs(rrdm - rrdm.T).max() <= 1e-13 * np.abs(rrdm).max(), f"{name} mbsim-h5: position position integral symmetric")
    R = [rPdm[:, k].reshape(3, 3) for k in range(nq)]  # R[k][a, b] = int c_a Phi_bk dm
    blocks = {}
    for n, (a, b) in enumerate([(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]):
        blocks[a, b] = PPdm[n * nq:(n + 1) * nq]
        blocks[b, a] = blocks[a, b].T
    P = lambda a, b: blocks[a, b]  # P(a, b)[j, k] = int Phi_aj Phi_bk dm
    I3 = np.eye(3)
    mdCM0, mdCM1 = rdm.reshape(3, 1), np.array([Pdm[:, [k]] for k in range(nq)])
    J0 = np.trace(rrdm) * I3 - rrdm
    J1 = np.array([2 * np.trace(r) * I3 - r - r.T for r in R])
    Ct0 = Pdm.T
    Cr0 = np.array([[r[1, 2] - r[2, 1], r[2, 0] - r[0, 2], r[0, 1] - r[1, 0]] for r in R])
    Cr1 = np.array([np.stack([P(2, 1)[:, j] - P(1, 2)[:, j], P(0, 2)[:, j] - P(2, 0)[:, j], P(1, 0)[:, j] - P(0, 1)[:, j]], 1)
                    for j in range(nq)])
    Me = P(0, 0) + P(1, 1) + P(2, 2)
    Oe0 = np.array([[-(r[1, 1] + r[2, 2]), -(r[0, 0] + r[2, 2]), -(r[0, 0] + r[1, 1]), r[0, 1] + r[1, 0], r[1, 2] + r[2, 1],
                     r[2, 0] + r[0, 2]] for r in R])
    Oe1 = np.array([np.stack([-(P(1, 1)[:, j] + P(2, 2)[:, j]), -(P(0, 0)[:, j] + P(2, 2)[:, j]), -(P(0, 0)[:, j] + P(1, 1)[:, j]),
                              P(0, 1)[:, j] + P(1, 0)[:, j], P(1, 2)[:, j] + P(2, 1)[:, j], P(2, 0)[:, j] + P(0, 2)[:, j]], 1)
                    for j in range(nq)])
    Gr0 = np.hstack([2 * (np.trace(r) * I3 - r.T) for r in R])
    Pjk = lambda j, k: np.array([[P(a, b)[j, k] for b in range(3)] for a in range(3)])
    Gr1 = np.array([np.hstack([2 * (np.trace(Pjk(j, k)) * I3 - Pjk(j, k).T) for k in range(nq)]) for j in range(nq)])
    Ge0 = np.zeros((nq, 3 * nq))
    for j in range(nq):
        for k in range(nq):
            p = Pjk(j, k)
            Ge0[k, 3 * j:3 * j + 3] = 2 * np.array([p[1, 2] - p[2, 1], p[2, 0] - p[0, 2], p[0, 1] - p[1, 0]])
    t = sid["terms"]
    check(close(m, sid["mass"]), f"{name} mbsim-h5: mass")
    for label, (a0, a1) in {"mdCM": (mdCM0, mdCM1), "J": (J0, J1), "Cr": (Cr0, Cr1), "Oe": (Oe0, Oe1), "Gr": (Gr0, Gr1)}.items():
        check(close(a0, t[label][0]) and close(a1, t[label][1]),
              f"{name} mbsim-h5: {label} M0 and M1 rebuilt from the integrals")
    for label, a0 in {"Ct": Ct0, "Me": Me, "Ge": Ge0, "Ke": K, "De": D}.items():
        check(close(a0, t[label][0]), f"{name} mbsim-h5: {label} rebuilt from the integrals")
    if sid["nodes"]:
        pos = np.concatenate([n["origin"][0][:, 0] for n in sid["nodes"]])
        phi = np.vstack([n["phi"] for n in sid["nodes"]])
        psi = np.vstack([n["psi"] for n in sid["nodes"]])
        check(close(nodes["nodal relative position"], pos) and close(nodes["nodal shape matrix of translation"], phi)
              and close(nodes["nodal shape matrix of rotation"], psi), f"{name} mbsim-h5: nodal positions and shapes")


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    exe, prep, repo = sys.argv[1], sys.argv[2], Path(sys.argv[3])
    with tempfile.TemporaryDirectory(prefix="isosid-export-") as tmp:
        work = Path(tmp)
        for sid_path in (repo / "tests/golden/sphere_small.sid.h5", repo / "tests/golden/beam_small.sid.h5"):
            check_sid_fem(exe, sid_path, work)
            check_mbsim(exe, sid_path, work)
        massless = work / "bar.sid.h5"
        subprocess.run([prep, "-q", repo / "models/bar_drop_macneal.model.toml", "-o", massless], check=True, capture_output=True)
        for fmt in ("sid-fem", "mbsim-h5"):
            r = subprocess.run([exe, massless, "--format", fmt, "-o", work / "x"], capture_output=True, text=True)
            check(r.returncode == 2 and r.stderr.count("\n") == 1 and "/refmod/reduction_method" in r.stderr and not (work / "x").exists(),
                  f"{fmt}: a massless-boundary SID is refused (exit 2, one line, no file)")
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")


if __name__ == "__main__":
    main()
