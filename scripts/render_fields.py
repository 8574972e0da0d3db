"""One frame of a run's fields.xmf rendered by ParaView to a PNG (issue 46): the fluid coloured by
pressure, each structure by von Mises stress, each with its own colour bar; a grid of particles
(vertex cells: a fluid, a TL-SPH solid) drawn as spheres, a mesh (FE) as its surface; seen obliquely (3-D) or face on (2-D); --clip cuts the fluid's upper half
along an axis away to show the inside (the colour range stays the whole fluid's).

The file is opened by ParaView's default reader for .xmf (Xdmf3ReaderS), as a user would open it;
its spatial collection holds the particles first, then one grid per structure (apps' FieldsFile).
Prints one JSON line: the time drawn, the PNG, and the range each colour map spans (the data's
own minimum and maximum at that time), so a caller can check the picture shows the file.

Usage (pvpython needs an X server: scripts/render runs it under Xvfb):
  pvpython render_fields.py RUN_DIR [--time T] [--png FILE] [--size W H] [--view iso|front]
                            [--clip x|y|z]
"""
import argparse
import json
import os
import sys

from paraview import servermanager
from paraview.simple import (Clip, ColorBy, CreateView, GetColorTransferFunction, GetScalarBar,
                             OpenDataFile, Render, SaveScreenshot, Show, TrivialProducer)


def frame_parser(doc, holds, png):
    """The arguments every picture of a run takes: RUN (holding the file `holds`), --time, --png
    (default `png` in RUN), --size."""
    p = argparse.ArgumentParser(description=doc.splitlines()[0])
    p.add_argument("run", help="a run's output folder (holds %s)" % holds)
    p.add_argument("--time", type=float, help="the frame nearest this time (default: the last)")
    p.add_argument("--png", help="output file (default RUN/%s)" % png)
    p.add_argument("--size", type=int, nargs=2, default=[1600, 900], metavar=("W", "H"))
    return p


def nearest_time(reader, wanted):
    """The reader's time nearest `wanted` (None: its last)."""
    times = list(reader.TimestepValues) or [0.0]
    return times[-1] if wanted is None else min(times, key=lambda t: abs(t - wanted))


def parse():
    p = frame_parser(__doc__, "fields.xmf", "fields_<time>.png")
    p.add_argument("--view", choices=["iso", "front"], help="camera (default: iso in 3-D)")
    p.add_argument("--clip", choices=["x", "y", "z"], help="cut the fluid's upper half along it")
    return p.parse_args()


def pieces(reader, time):
    """The frame's grids as VTK data sets, in the file's order (particles first)."""
    reader.UpdatePipeline(time)
    data = servermanager.Fetch(reader)
    out = []

    def walk(d):
        if d is None:
            return
        if d.IsA("vtkDataSet"):
            out.append(d)
        elif d.IsA("vtkMultiPieceDataSet"):
            for k in range(d.GetNumberOfPieces()):
                walk(d.GetPiece(k))
        else:
            for k in range(d.GetNumberOfBlocks()):
                walk(d.GetBlock(k))

    walk(data)
    return out


def white_view(size):
    """A render view of size [W, H] on white, with the orientation axes."""
    view = CreateView("RenderView")
    view.ViewSize = size
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 1
    return view


def iso_camera(view, azimuth=35.0):
    """The oblique view of a 3-D scene: from +z turned azimuth degrees round y (towards +x), 25
    up."""
    view.ResetCamera()
    camera = view.GetActiveCamera()
    camera.Azimuth(azimuth)
    camera.Elevation(25.0)
    view.ResetCamera()


def particles(data):
    """True for a grid of particles: no cells, or cells of dimension 0 (one XDMF topology a grid)."""
    return data.GetNumberOfCells() == 0 or data.GetCell(0).GetCellDimension() == 0


def colour(view, data, field, preset, title, clip=None):
    """data shown in view coloured by field over its own range; returns that range. clip: an axis
    (0, 1, 2) whose upper half of the data is cut away (to see inside a 3-D fluid)."""
    source = TrivialProducer()
    source.GetClientSideObject().SetOutput(data)
    if clip is not None:
        b = data.GetBounds()
        source = Clip(Input=source, ClipType="Plane")
        source.ClipType.Origin = [0.5 * (b[2 * k] + b[2 * k + 1]) for k in range(3)]
        source.ClipType.Normal = [1.0 if k == clip else 0.0 for k in range(3)]
    display = Show(source, view)
    if particles(data):  # spheres of the particles' mean spacing (volume per particle, or area in 2-D)
        b = data.GetBounds()
        extents = [e for e in (b[1] - b[0], b[3] - b[2], b[5] - b[4]) if e > 0.0]
        volume = 1.0
        for e in extents:
            volume *= e
        display.SetRepresentationType("Point Gaussian")
        display.ShaderPreset = "Sphere"
        display.GaussianRadius = 0.5 * (volume / data.GetNumberOfPoints()) ** (1.0 / len(extents))
    else:
        display.SetRepresentationType("Surface")
    ColorBy(display, ("POINTS", field))
    lut = GetColorTransferFunction(field)
    lut.ApplyPreset(preset, True)
    lo, hi = data.GetPointData().GetArray(field).GetRange()
    lut.RescaleTransferFunction(lo, hi)
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = title, ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    return [lo, hi]


def main():
    a = parse()
    xmf = os.path.join(a.run, "fields.xmf")
    if not os.path.isfile(xmf):
        sys.exit("%s: no fields.xmf (run with output.fields set)" % a.run)
    reader = OpenDataFile(xmf)
    time = nearest_time(reader, a.time)
    grids = pieces(reader, time)
    view = white_view(a.size)
    ranges, three_d = {}, False
    for g in grids:
        bounds = g.GetBounds()
        three_d = three_d or bounds[5] > bounds[4]
        point_data = g.GetPointData()
        names = [point_data.GetArrayName(k) for k in range(point_data.GetNumberOfArrays())]
        if "pressure" in names:
            clip = None if a.clip is None else "xyz".index(a.clip)
            ranges["pressure"] = colour(view, g, "pressure", "Cool to Warm", "pressure [Pa]", clip)
        elif "von_mises" in names:
            ranges["von_mises"] = colour(view, g, "von_mises", "Viridis (matplotlib)",
                                         "von Mises [Pa]")
    if not ranges:
        sys.exit("%s: the frame at t = %g holds neither pressure nor von_mises" % (xmf, time))
    view.ResetCamera()
    if (a.view or ("iso" if three_d else "front")) == "iso":
        iso_camera(view)
    png = a.png or os.path.join(a.run, "fields_%g.png" % time)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=a.size)
    print(json.dumps({"time": time, "png": png, "ranges": ranges}))


if __name__ == "__main__":
    main()
