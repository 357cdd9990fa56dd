#!/usr/bin/python3
"""ParaView output read back with an independent reader (VTK's own XML reader, python3-vtk9)
and checked against the SID (h5py) and the run's results.h5:

1. isosid-info --paraview: the points are the SID's /visual/position, each mode array is its
   column of /visual/Phi, the frequencies are /refmod/frequencies_hz.
2. isosid-run with [output] paraview = true on an axisymmetric impact (quadrilaterals) and a
   spinning, vibrating 3D ball (hexahedra): scene.pvd lists every frame once per part in time
   order; each frame's points are r + R (X + Phi q) with r, R and q of results.h5 at that
   time; its displacement is R Phi q, its velocity v + R (w x (X + u) + Phi qdot); its von Mises stress is recomputed from /visual/S q; the
   contact points' forces sum to the contact force of results.h5.

usage: paraview_readback.py ISOSID_PREP ISOSID_RUN ISOSID_INFO GOLDEN_DIR"""
import math
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import h5py
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

# the scene and model fixtures the C++ tests share
SCENES = Path(__file__).resolve().parent.parent / "scenes"

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData()) if grid.GetNumberOfPoints() else np.zeros((0, 3))
    arrays = {grid.GetPointData().GetArrayName(i): vtk_to_numpy(grid.GetPointData().GetArray(i))
              for i in range(grid.GetPointData().GetNumberOfArrays())}
    fields = {grid.GetFieldData().GetArrayName(i): vtk_to_numpy(grid.GetFieldData().GetArray(i))
              for i in range(grid.GetFieldData().GetNumberOfArrays())}
    types = [grid.GetCellType(i) for i in range(grid.GetNumberOfCells())]
    cells = [[grid.GetCell(i).GetPointId(k) for k in range(grid.GetCell(i).GetNumberOfPoints())]
             for i in range(grid.GetNumberOfCells())]
    return points, arrays, fields, types, cells


def run(*args):
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(map(str, args))} exited {done.returncode}: {done.stderr}")
    return done


def rotation(quaternion):
    w, x, y, z = quaternion / np.linalg.norm(quaternion)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def von_mises(components, s, analysis, nu):
    """From the stress components, written here from the definition (not from isosid)."""
    c = dict(zip(components, s))
    if analysis == "axisymmetric":
        n, shear = [c["rr"], c["zz"], c["tt"]], [c["rz"]]
    elif len(components) == 6:
        n, shear = [c["xx"], c["yy"], c["zz"]], [c["xy"], c["yz"], c["xz"]]
    else:
        n = [c["xx"], c["yy"], nu * (c["xx"] + c["yy"]) if analysis == "plane_strain" else 0.0]
        shear = [c["xy"]]
    return math.sqrt(0.5 * ((n[0] - n[1]) ** 2 + (n[1] - n[2]) ** 2 + (n[2] - n[0]) ** 2) + 3 * sum(t * t for t in shear))


def sid_data(path):
    with h5py.File(path, "r") as f:
        v = f["visual"]
        return {
            "analysis": f["body/analysis_type"][()].decode(),
            "nu": float(f["body/poisson_ratio"][()]),
            "position": v["position"][()], "Phi": v["Phi"][()], "cells": v["cells"][()],
            "corners": int(v["corners_per_cell"][()]),
            "components": [c.decode() for c in v["stress_components"][()]] if "stress_components" in v else [],
            "S": v["S"][()] if "S" in v else None,
            "frequencies": f["refmod/frequencies_hz"][()],
        }


def check_modes(info, sid_path, out, name):
    run(info, sid_path, "--paraview", out)
    sid = sid_data(sid_path)
    points, arrays, fields, types, cells = read_vtu(Path(out) / f"{name}_modes.vtu")
    dim = sid["position"].shape[1]
    check(np.array_equal(points[:, :dim], sid["position"]) and not points[:, dim:].any(), f"{name}: mode-shape points are /visual/position")
    check(np.array_equal(np.array(cells).ravel(), sid["cells"]), f"{name}: cells are /visual/cells")
    nq = sid["Phi"].shape[1]
    same = all(np.array_equal(arrays[f"mode_{k + 1:03d}"][:, :dim], sid["Phi"][:, k].reshape(-1, dim)) for k in range(nq))
    check(same and len(arrays) == nq, f"{name}: {nq} mode arrays are the columns of /visual/Phi")
    check(np.array_equal(fields["frequency_hz"], sid["frequencies"]), f"{name}: frequency_hz is /refmod/frequencies_hz")


def check_run(out, sid_path, body, contact, cell_type):
    sid = sid_data(sid_path)
    dim = sid["position"].shape[1]
    pvd = ET.parse(Path(out) / "paraview" / "scene.pvd").getroot()
    entries = [(float(d.get("timestep")), int(d.get("part")), d.get("name"), d.get("file")) for d in pvd.iter("DataSet")]
    times = sorted({e[0] for e in entries})
    parts = sorted({(e[1], e[2]) for e in entries})
    check(len(entries) == len(times) * len(parts) and times == [e[0] for e in entries][::len(parts)],
          f"{body}: scene.pvd lists {len(times)} frames x {len(parts)} parts in time order")
    check(all((Path(out) / "paraview" / e[3]).is_file() for e in entries), f"{body}: every listed file exists")
    with h5py.File(Path(out) / "results.h5", "r") as f:
        t_all = f["time"][()]
        b = f["bodies"][body]
        r_all, quat_all, q_all = b["position"][()], b["quaternion"][()], b["q"][()]
        v_all, w_all, qdot_all = b["velocity"][()], b["angular_velocity"][()], b["qdot"][()]
        force_all = f["contacts"][contact]["force"][()] if contact else None
    size = np.abs(sid["position"]).max()
    worst_points = worst_disp = worst_velocity = worst_mises = worst_force = 0.0
    loaded_frames = 0
    check(all(np.any(t_all == t) for t in times), f"{body}: every frame time is a sample of results.h5")
    for t in times:
        k = int(np.argmin(np.abs(t_all - t)))
        R, r, q = rotation(quat_all[k]), r_all[k], q_all[k]
        files = {e[2]: Path(out) / "paraview" / e[3] for e in entries if e[0] == t}
        points, arrays, _, types, cells = read_vtu(files[body])
        X = np.zeros((len(sid["position"]), 3))
        X[:, :dim] = sid["position"]
        u = np.zeros_like(X)
        u[:, :dim] = (sid["Phi"] @ q).reshape(-1, dim)
        expected = r + (X + u) @ R.T
        worst_points = max(worst_points, np.abs(points - expected).max() / size)
        worst_disp = max(worst_disp, np.abs(arrays["displacement"] - u @ R.T).max() / max(np.abs(u).max(), 1e-300))
        # material velocity: frame velocity, rotation (angular velocity in the body frame), modes
        udot = np.zeros_like(X)
        udot[:, :dim] = (sid["Phi"] @ qdot_all[k]).reshape(-1, dim)
        velocity = v_all[k] + (np.cross(w_all[k], X + u) + udot) @ R.T
        worst_velocity = max(worst_velocity, np.abs(arrays["velocity"] - velocity).max() / np.abs(velocity).max())
        if sid["S"] is not None:
            nc = len(sid["components"])
            sigma = (sid["S"] @ q).reshape(-1, nc)
            mises = np.array([von_mises(sid["components"], s, sid["analysis"], sid["nu"]) for s in sigma])
            worst_mises = max(worst_mises, np.abs(arrays["von_mises"] - mises).max() / max(mises.max(), 1.0))
        if t == times[0]:
            check(set(types) == {cell_type} and np.array_equal(np.array(cells).ravel(), sid["cells"]),
                  f"{body}: cells of type {cell_type} as /visual/cells")
        if contact:
            cpoints, carrays, _, ctypes, _ = read_vtu(files[contact])
            total = carrays["force"].sum(axis=0) if len(cpoints) else np.zeros(3)
            worst_force = max(worst_force, np.abs(total - force_all[k]).max() / max(np.abs(force_all).max(), 1e-300))
            loaded_frames += len(cpoints) > 0
    # positions and displacements are the same products as the check's, in another order: 1e-12
    check(worst_points < 1e-12, f"{body}: points are r + R (X + Phi q) of results.h5 ({worst_points:.1e} of the body size)")
    check(worst_disp < 1e-12, f"{body}: displacement is R Phi q ({worst_disp:.1e} of the largest)")
    check(worst_velocity < 1e-12, f"{body}: velocity is v + R (w x (X + u) + Phi qdot) ({worst_velocity:.1e} of the largest)")
    if sid["S"] is not None:
        check(worst_mises < 1e-10, f"{body}: von Mises recomputed from /visual/S q ({worst_mises:.1e} of the peak)")
    if contact:
        check(loaded_frames > 0 and worst_force < 1e-12,
              f"{body}: contact points' forces sum to the contact force ({loaded_frames} loaded frames, {worst_force:.1e} of the peak)")


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    prep, isosid_run, info, golden = sys.argv[1:]
    work = Path(tempfile.mkdtemp(prefix="isosid-paraview-"))
    try:
        # an axisymmetric sphere: the golden model with a viewing mesh of 2 x 2 cells per element
        model = (Path(golden) / "sphere_small.model.toml").read_text() + "\n[visual]\nsubdivisions = 2\n"
        (work / "sphere.model.toml").write_text(model)
        run(prep, "-q", work / "sphere.model.toml", "-o", work / "sphere.sid.h5")
        check_modes(info, work / "sphere.sid.h5", work, "sphere_small")
        # the golden impact with ParaView frames every 3 us, for 60 us
        scene = (SCENES / "golden_impact.scene.toml").read_text().replace("@SID@", "sphere.sid.h5")
        assert "end_time = 100e-6" in scene
        scene = scene.replace("end_time = 100e-6", "end_time = 60e-6") + "[output]\nparaview = true\nparaview_interval = 3e-6\n"
        (work / "impact.scene.toml").write_text(scene)
        run(isosid_run, "-q", work / "impact.scene.toml", "-o", work / "impact")
        check_run(work / "impact", work / "sphere.sid.h5", "sphere", "impact", 9)

        # a 3D ball, spinning and vibrating freely (rotation, hexahedra, degenerate poles)
        (work / "ball.model.toml").write_text((SCENES / "paraview_ball.model.toml").read_text())
        run(prep, "-q", work / "ball.model.toml", "-o", work / "ball.sid.h5")
        (work / "spin.scene.toml").write_text((SCENES / "paraview_spin.scene.toml").read_text())
        run(isosid_run, "-q", work / "spin.scene.toml", "-o", work / "spin")
        check_run(work / "spin", work / "ball.sid.h5", "ball", None, 12)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")


if __name__ == "__main__":
    main()
