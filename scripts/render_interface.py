"""A 3-D coupled run's interface at one recorded time drawn by ParaView to a PNG (issue 46): the
structure's wetted 6-node faces at that time's positions, coloured by the magnitude of the load
the structure took, with a colour bar, seen obliquely. By default the load per area (traction,
N/m^2): a T6 face's nodal loads are zero at its corners under a uniform pressure, so |load| per
node would draw the mesh's pattern, not the load (scripts/interface_vtk.py); --field load draws
the nodal loads (N) themselves.

Opens RUN/interface.pvd (written from interface.h5 by scripts/interface_vtk) with ParaView's
reader for it, as a user would. Prints one JSON line: the time drawn, the PNG, the field and the
range its colour map spans (the magnitude's own minimum and maximum at that time).

Usage (pvpython needs an X server: scripts/render --interface runs it under Xvfb):
  pvpython render_interface.py RUN_DIR [--time T] [--png FILE] [--size W H]
                               [--field traction|load] [--azimuth DEG]
"""
import json
import os
import sys

from paraview.simple import (ColorBy, GetColorTransferFunction, GetScalarBar, OpenDataFile, Render,
                             SaveScreenshot, Show)
from render_fields import frame_parser, iso_camera, nearest_time, pieces, white_view

UNITS = {"traction": "N/m^2", "load": "N"}


def parse():
    p = frame_parser(__doc__, "interface.pvd", "interface_<field>_<time>.png")
    p.add_argument("--field", choices=sorted(UNITS), default="traction")
    p.add_argument("--azimuth", type=float, default=35.0,
                   help="the camera's turn round y from +z, degrees (-55: from upstream, -x)")
    return p.parse_args()


def main():
    a = parse()
    pvd = os.path.join(a.run, "interface.pvd")
    if not os.path.isfile(pvd):
        sys.exit("%s: no interface.pvd (scripts/interface_vtk %s writes it from interface.h5)"
                 % (a.run, a.run))
    reader = OpenDataFile(pvd)
    time = nearest_time(reader, a.time)
    (surface,) = pieces(reader, time)
    lo, hi = surface.GetPointData().GetArray(a.field).GetRange(-1)  # -1: the magnitude's range
    view = white_view(a.size)
    view.ViewTime = time
    display = Show(reader, view)
    display.SetRepresentationType("Surface")
    ColorBy(display, ("POINTS", a.field, "Magnitude"))
    lut = GetColorTransferFunction(a.field)
    lut.ApplyPreset("Inferno (matplotlib)", True)
    lut.RescaleTransferFunction(lo, hi)
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = "|%s| [%s]" % (a.field, UNITS[a.field]), ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    iso_camera(view, a.azimuth)
    png = a.png or os.path.join(a.run, "interface_%s_%g.png" % (a.field, time))
    Render(view)
    SaveScreenshot(png, view, ImageResolution=a.size)
    print(json.dumps({"time": time, "png": png, "field": a.field, "range": [lo, hi]}))


if __name__ == "__main__":
    main()
