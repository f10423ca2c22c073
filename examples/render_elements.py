#!/usr/bin/env python3
"""Renders the output of examples/double_torus_elements.tfd.json with VTK (an independent
reader of tfd's .obj, .ply and .vtp): sticks brown, leaves green, degenerate curves in their
Fig. 5 colours. Checks on the way that the points .ply has one vertex per element with the
orient_* and pscale properties and that it accounts for every vertex of the mesh.

    xvfb-run -a /usr/bin/python3 examples/render_elements.py OUT_DIR PICTURE.png
"""
import struct
import sys

import vtk

out, picture = sys.argv[1], sys.argv[2]
stem = out + "/double_torus_elements"

obj = vtk.vtkOBJReader()
obj.SetFileName(stem + ".obj")
obj.Update()
mesh = obj.GetOutput()

ply = vtk.vtkPLYReader()
ply.SetFileName(stem + "_points.ply")
ply.Update()
points = ply.GetOutput()
# vtkPLYReader (VTK 9.1) keeps only positions; the attributes are read here from the PLY
# header and the binary body with struct.
def read_points_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    assert header[1] == "format binary_little_endian 1.0", header[1]
    count = next(int(l.split()[2]) for l in header if l.startswith("element vertex"))
    props = [l.split()[1:] for l in header if l.startswith("property")]
    codes = {"double": "d", "float": "f", "uchar": "B"}
    fmt = "<" + "".join(codes[t] for t, _ in props)
    size = struct.calcsize(fmt)
    assert len(data) == end + count * size, "file size"
    rows = [struct.unpack_from(fmt, data, end + i * size) for i in range(count)]
    return [name for _, name in props], rows


names, rows = read_points_ply(stem + "_points.ply")
print("points:", points.GetNumberOfPoints(), "(vtkPLYReader),", len(rows), "rows, properties:",
      " ".join(names))
assert points.GetNumberOfPoints() == len(rows)
col = {n: i for i, n in enumerate(names)}
for name in ("orient_x", "orient_y", "orient_z", "orient_w", "pscale", "kind"):
    assert name in col, name
worst = max(abs(points.GetPoint(i)[k] - rows[i][k]) for i in range(len(rows)) for k in range(3))
print("largest position difference between the two readers:", worst)
norms = [sum(r[col["orient_" + c]] ** 2 for c in "xyzw") ** 0.5 for r in rows]
print("quaternion norms in [%.6f, %.6f]" % (min(norms), max(norms)))
print("pscale values:", sorted(set(round(r[col["pscale"]], 6) for r in rows)))
kind = [r[col["kind"]] for r in rows]

# Built-in stick: 18 vertices; built-in leaf: 50 (core/synth/element_shapes.cpp).
per_kind = {0: 18, 1: 50}
colours = vtk.vtkUnsignedCharArray()
colours.SetNumberOfComponents(3)
colours.SetName("colour")
for k in kind:
    rgb = (150, 95, 45) if k == 0 else (70, 160, 60)
    for _ in range(per_kind[int(k)]):
        colours.InsertNextTuple3(*rgb)
print("mesh:", mesh.GetNumberOfPoints(), "vertices,", mesh.GetNumberOfCells(), "triangles;",
      kind.count(0), "sticks,", kind.count(1), "leaves")
assert colours.GetNumberOfTuples() == mesh.GetNumberOfPoints()
mesh.GetPointData().SetScalars(colours)

normals = vtk.vtkPolyDataNormals()
normals.SetInputData(mesh)
mapper = vtk.vtkPolyDataMapper()
mapper.SetInputConnection(normals.GetOutputPort())
mapper.SetColorModeToDirectScalars()
actor = vtk.vtkActor()
actor.SetMapper(mapper)

curves = vtk.vtkXMLPolyDataReader()
curves.SetFileName(out + "/double_torus_curves.vtp")
curves.Update()
curves.GetOutput().GetPointData().SetActiveScalars("colour")
tubes = vtk.vtkTubeFilter()
tubes.SetInputConnection(curves.GetOutputPort())
tubes.SetRadius(0.015)
tubes.SetNumberOfSides(8)
curve_mapper = vtk.vtkPolyDataMapper()
curve_mapper.SetInputConnection(tubes.GetOutputPort())
curve_mapper.SetColorModeToDirectScalars()
curve_actor = vtk.vtkActor()
curve_actor.SetMapper(curve_mapper)

renderer = vtk.vtkRenderer()
renderer.AddActor(actor)
renderer.AddActor(curve_actor)
renderer.SetBackground(1, 1, 1)
window = vtk.vtkRenderWindow()
window.SetOffScreenRendering(1)
window.AddRenderer(renderer)
window.SetSize(1400, 800)
camera = renderer.GetActiveCamera()
camera.SetPosition(0, -5, 6)
camera.SetFocalPoint(0, 0, 0)
camera.SetViewUp(0, 0, 1)
renderer.ResetCamera()
camera.Zoom(1.45)
window.Render()
grab = vtk.vtkWindowToImageFilter()
grab.SetInput(window)
writer = vtk.vtkPNGWriter()
writer.SetFileName(picture)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print("wrote", picture)
