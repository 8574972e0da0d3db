"""ParaView opens a 3-D fields.xmf (issue 42): write_fields_3d writes one frame with a 4 x 3 x 2
particle lattice at (0.1 i, 0.2 j, 0.3 k) with velocity (x + 1, 2 y, -3 z), and a 2 x 1 x 1-cell
T10 box mesh of 0.2 x 0.1 x 0.1 m (12 tetrahedra, 45 nodes) displaced by u(X) = (2 Y^2, 3 Z^2,
4 X^2), a quadratic field that bends its edges. Through ParaView's default reader for .xmf
(Xdmf3ReaderS) the test checks point and cell counts, bounds and the velocity at every particle;
each solid cell must be a VTK_QUADRATIC_TETRA whose edge nodes lie, in the reference
configuration (position - displacement), at the midpoints of VTK's edges, and the quadratic cell
evaluated by VTK at interior points must equal the exact deformed position X + u(X): both fail
for a wrong Gmsh-to-XDMF node order.

Usage: pvpython test_output_paraview_3d.py WRITE_FIELDS_3D OUTDIR. Exit 77 without ParaView.
"""
import shutil
import subprocess
import sys

try:
    from paraview import servermanager
    from paraview.simple import OpenDataFile
    from vtkmodules.vtkCommonCore import reference as vtk_reference
    from vtkmodules.vtkCommonDataModel import VTK_QUADRATIC_TETRA
except ImportError as e:  # no ParaView: skipped, never passed
    print("skipped: %s (install python3-paraview, scripts/setup)" % e)
    sys.exit(77)

writer, out = sys.argv[1:3]
shutil.rmtree(out, ignore_errors=True)
subprocess.run([writer, out], check=True)

failures = 0


def expect(ok, what):
    global failures
    if not ok:
        print("FAIL:", what)
        failures += 1


def close(a, b, tol):
    return all(abs(x - y) <= tol for x, y in zip(a, b))


def deformed(X):
    return (X[0] + 2 * X[1] ** 2, X[1] + 3 * X[2] ** 2, X[2] + 4 * X[0] ** 2)


reader = OpenDataFile(out + "/fields.xmf")
expect(reader.GetXMLName() == "Xdmf3ReaderS", "default reader %s" % reader.GetXMLName())
reader.UpdatePipeline(0.5)
data = servermanager.Fetch(reader)
it = data.NewIterator()
it.InitTraversal()
blocks = {}
while not it.IsDoneWithTraversal():
    b = it.GetCurrentDataObject()
    name = "particles" if b.GetPointData().GetArray("velocity") is not None else "solid"
    blocks[name] = b
    it.GoToNextItem()
expect(sorted(blocks) == ["particles", "solid"], "blocks %s" % sorted(blocks))

p = blocks["particles"]
print("particles: %d points, %d cells, bounds %s" % (p.GetNumberOfPoints(), p.GetNumberOfCells(),
                                                    p.GetBounds()))
expect((p.GetNumberOfPoints(), p.GetNumberOfCells()) == (24, 24), "particle counts")
expect(close(p.GetBounds(), (0, 0.3, 0, 0.4, 0, 0.3), 1e-15), "particle bounds")
v = p.GetPointData().GetArray("velocity")
expect(v.GetNumberOfComponents() == 3, "velocity components %d" % v.GetNumberOfComponents())
worst = max(max(abs(a - b) for a, b in zip(v.GetTuple3(i), (x + 1, 2 * y, -3 * z)))
            for i, (x, y, z) in ((i, p.GetPoint(i)) for i in range(24)))
print("velocity: largest error %.3g, last particle %s" % (worst, v.GetTuple3(23)))
expect(worst < 1e-15, "velocity off by %g" % worst)
expect(close(v.GetTuple3(23), (1.3, 0.8, -0.9), 1e-15), "velocity of the last particle")

s = blocks["solid"]
print("solid: %d points, %d cells, bounds %s" % (s.GetNumberOfPoints(), s.GetNumberOfCells(),
                                                s.GetBounds()))
expect((s.GetNumberOfPoints(), s.GetNumberOfCells()) == (45, 12), "solid counts")
expect(close(s.GetBounds(), (0, 0.22, 0, 0.13, 0, 0.26), 1e-15), "solid bounds")
u = s.GetPointData().GetArray("displacement")


def reference(i):
    return [a - b for a, b in zip(s.GetPoint(i), u.GetTuple3(i))]


mid_error = eval_error = 0.0
for c in range(s.GetNumberOfCells()):
    cell = s.GetCell(c)
    expect(cell.GetCellType() == VTK_QUADRATIC_TETRA, "cell %d type %d" % (c, cell.GetCellType()))
    for e in range(6):
        ids = cell.GetEdge(e).GetPointIds()  # ends, then the mid-edge node
        a, b, m = (reference(ids.GetId(k)) for k in range(3))
        mid_error = max(mid_error, max(abs(m[k] - 0.5 * (a[k] + b[k])) for k in range(3)))
    X = [reference(cell.GetPointId(k)) for k in range(4)]
    for r, t, w in ((0.2, 0.3, 0.1), (0.1, 0.1, 0.6), (0.25, 0.25, 0.25)):
        weights = [0.0] * 10
        x = [0.0] * 3
        cell.EvaluateLocation(vtk_reference(0), [r, t, w], x, weights)
        Xp = [X[0][k] + r * (X[1][k] - X[0][k]) + t * (X[2][k] - X[0][k]) + w * (X[3][k] - X[0][k])
              for k in range(3)]
        eval_error = max(eval_error, max(abs(a - b) for a, b in zip(x, deformed(Xp))))
print("solid: mid-edge nodes off their reference edges' midpoints by %.3g m, the quadratic cells"
      " off X + u(X) by %.3g m" % (mid_error, eval_error))
expect(mid_error < 1e-15, "mid-edge node off its edge's midpoint by %g" % mid_error)
expect(eval_error < 1e-14, "quadratic cell off X + u(X) by %g" % eval_error)
print("paraview 3-D: %d failures" % failures)
sys.exit(1 if failures else 0)
