#!/usr/bin/python3
"""Headless renders of isosid-run's ParaView output (VTK offscreen; run under xvfb-run when
there is no display).

  bench/render_paraview.py sphere OUT_DIR PNG   # scene A: the contact zone at peak load
  bench/render_paraview.py rod OUT_DIR PNG      # scene B: the axial velocity wave in the rod

OUT_DIR is a results folder of `isosid-run --paraview`. The frames are read from
OUT_DIR/paraview/scene.pvd with VTK's own XML reader, independently of isosid."""
import json
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def frames(out_dir):
    """{time: {part name: vtu path}} from scene.pvd, in time order."""
    pvd = Path(out_dir) / "paraview" / "scene.pvd"
    by_time = {}
    for ds in ET.parse(pvd).getroot().iter("DataSet"):
        by_time.setdefault(float(ds.get("timestep")), {})[ds.get("name")] = pvd.parent / ds.get("file")
    return dict(sorted(by_time.items()))


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def surface_actor(grid, array, component, lut_range, transform=None, edges=False):
    """The grid (optionally transformed) coloured by one component of a point array (-1: the
    scalar itself)."""
    source = vtk.vtkPassThrough()
    source.SetInputData(grid)
    port = source.GetOutputPort()
    if transform is not None:
        t = vtk.vtkTransformFilter()
        t.SetInputConnection(port)
        t.SetTransform(transform)
        port = t.GetOutputPort()
    geometry = vtk.vtkDataSetSurfaceFilter()
    geometry.SetInputConnection(port)
    mapper = vtk.vtkDataSetMapper()
    mapper.SetInputConnection(geometry.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(array)
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.SetTableRange(*lut_range)
    lut.Build()
    if component >= 0:
        lut.SetVectorModeToComponent()
        lut.SetVectorComponent(component)
    mapper.SetLookupTable(lut)
    mapper.UseLookupTableScalarRangeOn()
    mapper.ScalarVisibilityOn()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    if edges:
        actor.GetProperty().EdgeVisibilityOn()
        actor.GetProperty().SetEdgeColor(0.25, 0.25, 0.25)
        actor.GetProperty().SetLineWidth(0.5)
    return actor, lut


def scalar_bar(lut, title, x, y, horizontal=False):
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle(title)
    bar.SetNumberOfLabels(5)
    bar.SetLabelFormat("%.3g")
    if horizontal:
        bar.SetOrientationToHorizontal()
        bar.SetWidth(0.5)
        bar.SetHeight(0.08)
    else:
        bar.SetWidth(0.08)
        bar.SetHeight(0.6)
    bar.SetPosition(x, y)
    for p in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        p.SetColor(0, 0, 0)
        p.SetFontSize(14)
        p.ItalicOff()
        p.ShadowOff()
    return bar


def text(message, x, y, size=18):
    t = vtk.vtkTextActor()
    t.SetInput(message)
    t.GetTextProperty().SetColor(0, 0, 0)
    t.GetTextProperty().SetFontSize(size)
    t.GetTextProperty().SetBackgroundColor(1, 1, 1)
    t.GetTextProperty().SetBackgroundOpacity(0.85)
    t.SetDisplayPosition(x, y)
    return t


def save(window, png):
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(str(png))
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def window(width, height):
    w = vtk.vtkRenderWindow()
    w.SetOffScreenRendering(1)
    w.SetSize(width, height)
    return w


def render_sphere(out_dir, png):
    """Scene A at the frame of largest total contact force: the meridian section near the
    contact at true scale, von Mises stress, and the contact pressure of every loaded Gauss
    point as an arrow from the plane (length proportional to the pressure)."""
    series = frames(out_dir)
    def total_force(parts):
        g = read(parts["impact"])
        return 0.0 if g.GetNumberOfPoints() == 0 else float(np.linalg.norm(vtk_to_numpy(g.GetPointData().GetArray("force")).sum(0)))
    t, parts = max(series.items(), key=lambda item: total_force(item[1]))
    body, contact = read(parts["sphere"]), read(parts["impact"])
    forces = vtk_to_numpy(contact.GetPointData().GetArray("force"))
    pressure = vtk_to_numpy(contact.GetPointData().GetArray("pressure"))
    points = vtk_to_numpy(contact.GetPoints().GetData())
    mises = vtk_to_numpy(body.GetPointData().GetArray("von_mises"))
    a = points[:, 0].max()  # the outermost loaded point: the contact radius as resolved
    w = window(1100, 800)
    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    w.AddRenderer(ren)
    actor, lut = surface_actor(body, "von_mises", -1, (0.0, float(mises.max())), edges=True)
    ren.AddActor(actor)
    # arrows ending at the loaded points, along their force, as long as 0.8 a at the peak pressure
    length = 0.8 * a / pressure.max()
    directions = forces / np.linalg.norm(forces, axis=1)[:, None]
    arrows = vtk.vtkAppendPolyData()
    for p, d, pr in zip(points, directions, pressure):
        line = vtk.vtkLineSource()
        line.SetPoint1(*(p - d * pr * length))
        line.SetPoint2(*p)
        arrows.AddInputConnection(line.GetOutputPort())
        tip = vtk.vtkConeSource()
        tip.SetCenter(*(p - d * 0.03 * a))
        tip.SetDirection(*d)
        tip.SetHeight(0.06 * a)
        tip.SetRadius(0.015 * a)
        arrows.AddInputConnection(tip.GetOutputPort())
    # Hertz's pressure at this frame's force, drawn with the same scale (a grows as F^(1/3))
    hertz = json.loads((Path(out_dir) / "summary.json").read_text())["contacts"][0]["hertz_estimate"]
    force = float(np.linalg.norm(forces.sum(0)))
    a_h = hertz["contact_radius_m"] * (force / hertz["peak_force_n"]) ** (1 / 3)
    p0 = 3 * force / (2 * np.pi * a_h**2)
    profile = vtk.vtkPolyData()
    profile_points = vtk.vtkPoints()
    r = np.linspace(0.0, a_h, 60)
    for x, pr in zip(r, p0 * np.sqrt(np.clip(1 - (r / a_h) ** 2, 0, None))):
        profile_points.InsertNextPoint(x, -pr * length, 0.0)
    profile.SetPoints(profile_points)
    polyline = vtk.vtkCellArray()
    polyline.InsertNextCell(len(r))
    for i in range(len(r)):
        polyline.InsertCellPoint(i)
    profile.SetLines(polyline)
    profile_mapper = vtk.vtkPolyDataMapper()
    profile_mapper.SetInputData(profile)
    profile_actor = vtk.vtkActor()
    profile_actor.SetMapper(profile_mapper)
    profile_actor.GetProperty().SetColor(0.85, 0.1, 0.1)
    profile_actor.GetProperty().SetLineWidth(3)
    ren.AddActor(profile_actor)
    plane = vtk.vtkLineSource()
    plane.SetPoint1(-0.1 * a, 0.0, 0.0)
    plane.SetPoint2(4.0 * a, 0.0, 0.0)
    arrows.AddInputConnection(plane.GetOutputPort())
    arrow_mapper = vtk.vtkPolyDataMapper()
    arrow_mapper.SetInputConnection(arrows.GetOutputPort())
    arrow_actor = vtk.vtkActor()
    arrow_actor.SetMapper(arrow_mapper)
    arrow_actor.GetProperty().SetColor(0.1, 0.1, 0.1)
    arrow_actor.GetProperty().SetLineWidth(2)
    ren.AddActor(arrow_actor)
    ren.AddActor2D(scalar_bar(lut, "von Mises [Pa]", 0.45, 0.03, horizontal=True))
    ren.AddActor2D(text(f"Scene A: sphere on its symmetry plane at t = {t * 1e6:.1f} us (largest contact force, "
                        f"{np.linalg.norm(forces.sum(0)):.1f} N)", 20, 765))
    ren.AddActor2D(text("meridian section near the contact, true scale: r to the right, the axis at the left edge", 20, 740, 14))
    ren.AddActor2D(text(f"arrows: pressure at the {len(points)} loaded Gauss points; red: Hertz's pressure at this force "
                        f"(p0 = {p0 / 1e6:.0f} MPa, a = {a_h * 1e6:.0f} um)", 20, 718, 14))
    cam = ren.GetActiveCamera()
    centre = (1.55 * a, 0.45 * a, 0.0)
    cam.SetFocalPoint(*centre)
    cam.SetPosition(centre[0], centre[1], 1.0)
    cam.SetViewUp(0, 1, 0)
    cam.ParallelProjectionOn()
    cam.SetParallelScale(1.5 * a)
    save(w, png)
    print(f"render_paraview: scene A frame t = {t:.4g} s, {len(points)} loaded points, peak von Mises {mises.max():.4g} Pa -> {png}")


def render_rod(out_dir, png, times=(0.05e-3, 0.10e-3, 0.15e-3, 0.25e-3, 0.35e-3)):
    """Scene B: the rod laid horizontally at several times, coloured by its axial velocity;
    the radius stretched so the strips can be seen."""
    series = frames(out_dir)
    stretch = 4.0
    w = window(1400, 700)
    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    w.AddRenderer(ren)
    lut = None
    spacing = 0.14  # m between the strips' axes
    for i, want in enumerate(times):
        t = min(series, key=lambda s: abs(s - want))
        grid = read(series[t]["rod"])
        for side in (1.0, -1.0):  # the meridian section and its mirror image: the whole rod's cut
            transform = vtk.vtkTransform()
            transform.Translate(0.0, -i * spacing, 0.0)
            transform.RotateZ(-90.0)  # the axis (y) along x, the pole on the left
            transform.Scale(side * stretch, 1.0, 1.0)
            actor, lut = surface_actor(grid, "velocity", 1, (-0.32, 0.32), transform=transform)
            ren.AddActor(actor)
        label = vtk.vtkBillboardTextActor3D()
        label.SetInput(f"t = {t * 1e6:.0f} us")
        label.SetPosition(1.03, -i * spacing - 0.01, 0.0)
        label.GetTextProperty().SetColor(0, 0, 0)
        label.GetTextProperty().SetFontSize(18)
        ren.AddActor(label)
    ren.AddActor2D(scalar_bar(lut, "axial velocity [m/s]", 0.25, 0.02, horizontal=True))
    ren.AddActor2D(text("Scene B: aluminium rod (1 m, r = 10 mm) landing on its spherical end at 0.3 m/s, "
                        "pole on the left; radius stretched x4", 20, 665))
    ren.AddActor2D(text("the compression front stops the rod (velocity -> 0) as it travels up at c = 5.1 km/s, "
                        "reflects at the free top at 196 us and returns as upward motion (yellow to red)", 20, 640, 14))
    cam = ren.GetActiveCamera()
    centre = (0.58, -(len(times) - 1) * spacing / 2 - 0.04, 0.0)
    cam.SetFocalPoint(*centre)
    cam.SetPosition(centre[0], centre[1], 5.0)
    cam.SetViewUp(0, 1, 0)
    cam.ParallelProjectionOn()
    cam.SetParallelScale(0.42)
    save(w, png)
    print(f"render_paraview: scene B frames at {', '.join(f'{min(series, key=lambda s: abs(s - x)) * 1e6:.0f}' for x in times)} us -> {png}")


if __name__ == "__main__":
    if len(sys.argv) != 4 or sys.argv[1] not in ("sphere", "rod"):
        sys.exit(__doc__)
    {"sphere": render_sphere, "rod": render_rod}[sys.argv[1]](sys.argv[2], sys.argv[3])
