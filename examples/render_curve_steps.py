"""Draws the degenerate curves exported after each step of an edit sequence (ExportCurves .vtp
files, e.g. examples/edit_sequence.tfd.json's) side by side with ParaView, as tubes in the
paper's Fig. 5 colours (the files' `colour` array), each step shifted along x, with a grey
outline of the solid when one is given (.vtu or .obj, drawn as its surface at low opacity).

    xvfb-run -a pvbatch render_curve_steps.py OUT.png STEP1.vtp STEP2.vtp ... [--outline FILE]
                                              [--view x|y|z] [--gap G]

Run it with ParaView's pvbatch (Debian: package paraview, /usr/bin/pvbatch3.11) or pvpython.
"""
import os
import sys

from paraview.simple import (  # noqa: F401 (paraview.simple is ParaView's scripting API)
    ExtractSurface, GetActiveViewOrCreate, OpenDataFile, Render, SaveScreenshot, Show, Text,
    Transform, Tube)

args = sys.argv[1:]


def option(name, default):
    if name in args:
        i = args.index(name)
        value = args[i + 1]
        del args[i:i + 2]
        return value
    return default


outline = option("--outline", "")
view_axis = option("--view", "y")
gap = float(option("--gap", "2.3"))
png, steps = args[0], args[1:]
if not steps:
    sys.exit("usage: render_curve_steps.py OUT.png STEP.vtp ... [--outline FILE] [--view x|y|z]")

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [480 * len(steps), 520]
view.UseColorPaletteForBackground = 0
view.Background = [1, 1, 1]
view.OrientationAxesVisibility = 0

for k, path in enumerate(steps):
    shift = [k * gap, 0, 0]
    curves = Transform(Input=OpenDataFile(path))
    curves.Transform.Translate = shift
    tubes = Tube(Input=curves)
    tubes.Radius = 0.012
    tubes.NumberofSides = 12
    d = Show(tubes, view)
    d.ColorArrayName = ["POINTS", "colour"]
    d.MapScalars = 0  # the RGB bytes are the colours
    if outline:
        solid = Transform(Input=ExtractSurface(Input=OpenDataFile(outline)))
        solid.Transform.Translate = shift
        s = Show(solid, view)
        s.ColorArrayName = ["POINTS", ""]
        s.DiffuseColor = [0.6, 0.6, 0.65]
        s.Opacity = 0.12
    label = Text(Text=os.path.basename(path).replace(".vtp", ""))
    t = Show(label, view)
    t.Color = [0, 0, 0]
    t.FontSize = 14
    t.WindowLocation = "Any Location"
    t.Position = [(k + 0.05) / len(steps), 0.92]

Render(view)  # the first render resets the camera: frame it after
camera = view.GetActiveCamera()
direction = {"x": (1, 0, 0), "y": (0, -1, 0), "z": (0, 0, 1)}[view_axis]
up = (0, 1, 0) if view_axis == "z" else (0, 0, 1)
# Parallel projection framing the row of steps: the solid is about 2 units across (gap apart).
view.CameraParallelProjection = 1
view.ResetCamera()
focal = camera.GetFocalPoint()
camera.SetPosition(*[f + 10 * d for f, d in zip(focal, direction)])
camera.SetViewUp(*up)
view.ResetCamera()
width = gap * len(steps)
camera.SetParallelScale(0.5 * max(width * view.ViewSize[1] / view.ViewSize[0], gap) * 1.05)
SaveScreenshot(png, view, ImageResolution=view.ViewSize)
print("wrote", png)
