"""ParaView as the real client (issue 17): a tiny coupled run's fields.xmf opened through
ParaView's Python with the default reader for .xmf (Xdmf3ReaderS in ParaView 5.11) and with the
legacy XDMFReader. For the last time step, every block's point and cell count (each particle a
vertex cell, each structure element a Triangle_6) and the range of the particles' pressure must
equal the HDF5 data in fields.h5.

Usage: pvpython test_output_paraview.py FSI SCENE OUTDIR. Exit 77 (skipped) without ParaView.
"""
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

try:
    from paraview import servermanager
    from paraview.simple import OpenDataFile, XDMFReader
    import h5py
except ImportError as e:  # no ParaView: skipped, never passed
    print("skipped: %s (install python3-paraview, scripts/setup)" % e)
    sys.exit(77)

fsi, scene, out = sys.argv[1:4]
shutil.rmtree(out, ignore_errors=True)  # a fresh folder each time
# 20 steps of the coupled scene, a frame every 5: particles and the structure's T6 mesh.
subprocess.run([fsi, "run", scene, "--out", out, "--threads", "1", "--set", "time.end=4e-4",
                "--set", "output.interval=1e-4"], check=True, stdout=subprocess.DEVNULL)
xmf = out + "/fields.xmf"

# The expected counts of the last frame, from the index's grid order and the HDF5 data.
frames = ET.parse(xmf).getroot().find("Domain").find("Grid").findall("Grid")
last = frames[-1]
expected = []
with h5py.File(out + "/fields.h5", "r") as h5:
    frame = "frames/%d" % (len(frames) - 1)
    for grid in last.findall("Grid"):
        name = grid.get("Name")
        points = h5[frame + "/" + name + "/position"].shape[0]
        topology = grid.find("Topology").get("TopologyType")
        cells = h5["meshes/" + name + "/t6"].shape[0] if topology == "Triangle_6" else points
        pressure = None
        if name == "particles":
            p = h5[frame + "/particles/pressure"][...]
            pressure = (float(p.min()), float(p.max()))
        expected.append((name, points, cells, pressure))
time = float(last.find("Time").get("Value"))
assert len(expected) == 2, expected
print("expected at t = %g s:" % time, expected)


def blocks(reader):
    """(points, cells, pressure range or None) of every leaf block at the last time step."""
    reader.UpdatePipeline(time)
    data = servermanager.Fetch(reader)
    it = data.NewIterator()
    it.InitTraversal()
    found = []
    while not it.IsDoneWithTraversal():
        b = it.GetCurrentDataObject()
        array = b.GetPointData().GetArray("pressure")
        found.append((b.GetNumberOfPoints(), b.GetNumberOfCells(),
                      tuple(array.GetRange()) if array is not None else None))
        it.GoToNextItem()
    return found


failures = 0
default = OpenDataFile(xmf)
for label, reader in (("default reader " + default.GetXMLName(), default),
                      ("legacy XDMFReader", XDMFReader(FileNames=[xmf]))):
    assert abs(reader.TimestepValues[-1] - time) < 1e-12 * max(1.0, time)
    found = blocks(reader)
    print(label, found)
    if len(found) != len(expected):
        print("FAIL: %s: %d blocks, fields.h5 has %d" % (label, len(found), len(expected)))
        failures += 1
        continue
    for (name, points, cells, pressure), (p, c, r) in zip(expected, found):
        if (p, c) != (points, cells):
            print("FAIL: %s: block %s: %d points, %d cells; fields.h5: %d, %d" %
                  (label, name, p, c, points, cells))
            failures += 1
        if pressure is not None and r != pressure:
            print("FAIL: %s: pressure range %s; fields.h5: %s" % (label, r, pressure))
            failures += 1
if default.GetXMLName() != "Xdmf3ReaderS":
    print("FAIL: the default reader is %s, not Xdmf3ReaderS" % default.GetXMLName())
    failures += 1
print("paraview: %d mismatches" % failures)
sys.exit(1 if failures else 0)
