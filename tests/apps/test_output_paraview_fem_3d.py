"""ParaView opens a 3-D FE run's fields.xmf (issue 44): the shipped 3-D cantilever
(data/scenes/cantilever_3d.yaml, 20 x 2 x 2 box cells) run for 5 steps through fsi, its last frame
read by ParaView's default reader for .xmf. The beam must come back as 1025 points and 480
VTK_QUADRATIC_TETRA cells with the 3-component displacement and velocity and the von Mises
field, each equal to fields.h5 at every point.

Usage: pvpython test_output_paraview_fem_3d.py FSI SCENE OUTDIR. Exit 77 without ParaView.
"""
import shutil
import subprocess
import sys

try:
    from paraview import servermanager
    from paraview.simple import OpenDataFile
    from vtkmodules.vtkCommonDataModel import VTK_QUADRATIC_TETRA
    import h5py
except ImportError as e:  # no ParaView: skipped, never passed
    print("skipped: %s (install python3-paraview, scripts/setup)" % e)
    sys.exit(77)

fsi, scene, out = sys.argv[1:4]
shutil.rmtree(out, ignore_errors=True)
subprocess.run([fsi, "run", scene, "--out", out, "--threads", "1", "--set", "time.end=0.01",
                "--set", "output.interval=0.01"], check=True, stdout=subprocess.DEVNULL)
reader = OpenDataFile(out + "/fields.xmf")
reader.UpdatePipeline(reader.TimestepValues[-1])
grid = servermanager.Fetch(reader)
while not grid.IsA("vtkDataSet"):  # the beam's block
    grid = grid.GetBlock(0) if grid.IsA("vtkMultiBlockDataSet") else grid.GetPiece(0)

failures = []
if (grid.GetNumberOfPoints(), grid.GetNumberOfCells()) != (1025, 480):
    failures.append("counts %d points, %d cells" % (grid.GetNumberOfPoints(),
                                                    grid.GetNumberOfCells()))
if any(grid.GetCellType(c) != VTK_QUADRATIC_TETRA for c in range(grid.GetNumberOfCells())):
    failures.append("a cell is not VTK_QUADRATIC_TETRA")
with h5py.File(out + "/fields.h5", "r") as h5:
    frame = h5["frames/%d/beam" % (len(h5["frames"]) - 1)]
    for name, components in (("displacement", 3), ("velocity", 3), ("von_mises", 1)):
        array = grid.GetPointData().GetArray(name)
        if array is None or array.GetNumberOfComponents() != components:
            failures.append("%s missing or not %d components" % (name, components))
            continue
        data = frame[name][...].reshape(-1, components)
        worst = max(abs(array.GetComponent(k, c) - data[k, c])
                    for k in range(grid.GetNumberOfPoints()) for c in range(components))
        if worst != 0.0:
            failures.append("%s differs from fields.h5 by %g" % (name, worst))
        if name == "displacement" and not data[:, 1].min() < 0.0:
            failures.append("the beam does not sag (displacement y min %g)" % data[:, 1].min())
for f in failures:
    print("FAIL:", f)
print("ok" if not failures else "%d failures" % len(failures))
sys.exit(1 if failures else 0)
