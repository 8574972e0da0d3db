"""A 3-D coupled run's interface opened by ParaView, time by time (issue 46): the shipped SPH + T10
hydrostatic plate (data/scenes/hydrostatic_plate_3d.yaml) run for 4 steps with
coupling.record_interface, interface.h5 written as interface.pvd by scripts/interface_vtk, read by
pvbatch (ParaView's own reader for .pvd) under Xvfb. For every recorded time: the times are the
record's, the cells are the /faces as quadratic triangles, the points are the row's positions and
the velocities and accelerations the row's, bit for bit, the loads ParaView reads sum to the row's
sum (h5py) within 1e-12 relative, and sum_i a_i traction_i = sum_i load_i (a_i = int N_i dA, the
projection's conservation) within 1e-12 of sum_i |load_i|. The rows' load sums differ from each
other, and the same check run on a series listing each time with the row before (a layout that
reads the wrong row, as the dropped XDMF index did) must fail at every time after t = 0. Then
scripts/render --interface draws t = 0.003 s: its colour range is the traction magnitude's there,
and the plate is drawn (15 % of the picture not background, 41 pixels of Inferno's top fifth).

Usage: python3 test_interface_vtk.py FSI SCENE SCRIPTS READER OUTDIR. Exit 77 without pvbatch,
pvpython or Xvfb.
"""
import json
import os
import shutil
import subprocess
import sys

import h5py
import matplotlib.image
import numpy as np

fsi, scene, scripts, reader, out = sys.argv[1:6]
if any(shutil.which(p) is None for p in ("pvbatch", "pvpython", "Xvfb")):
    print("skipped: pvbatch, pvpython or Xvfb missing (paraview, python3-paraview, xvfb: "
          "scripts/setup)")
    sys.exit(77)
sys.path.insert(0, scripts)
import interface_vtk  # noqa: E402

shutil.rmtree(out, ignore_errors=True)
subprocess.run([fsi, "run", scene, "--out", out, "--threads", "1", "--set", "time.end=0.004",
                "--set", "output.interval=0.002", "--set", "coupling.record_interface=true"],
               check=True, stdout=subprocess.DEVNULL)
subprocess.run([scripts + "/interface_vtk", out], check=True, stdout=subprocess.DEVNULL)
with h5py.File(out + "/interface.h5", "r") as h5:
    record = {name: h5[name][...] for name in ("time", "position", "velocity", "acceleration",
                                                "load", "faces")}
rows = len(record["time"])
sums = record["load"].sum(axis=1)
failures = []
for i in range(rows):
    for j in range(i):
        if np.linalg.norm(sums[i] - sums[j]) <= 1e-9 * np.linalg.norm(sums[i]):
            failures.append("rows %d and %d: equal load sums, a wrong row would pass" % (j, i))


def read(pvd):
    """What pvbatch reads from pvd, as a dict of arrays."""
    npz = os.path.splitext(pvd)[0] + "_read.npz"
    subprocess.run([scripts + "/xvfb", "pvbatch", reader, pvd, npz], check=True,
                   stdout=subprocess.DEVNULL)
    with np.load(npz) as d:
        return {k: d[k] for k in d.files}


def check(seen):
    """The rows at which what ParaView read differs from the record, with what differs."""
    if seen["times"].tolist() != record["time"].tolist():
        return {-1: "times %s, recorded %s" % (seen["times"], record["time"])}
    weights = np.zeros(len(record["position"][0]))  # a_i = int N_i dA = sum_j M_ij
    np.add.at(weights, record["faces"], interface_vtk.face_mass(record["position"][0],
                                                                record["faces"]).sum(axis=2))
    bad = {}
    for k in range(rows):
        why = []
        if (seen["types_%d" % k] != 22).any() or not np.array_equal(
                seen["connectivity_%d" % k].reshape(-1, 6), record["faces"]):
            why.append("cells are not /faces as quadratic triangles")
        for name, key in (("points", "position"), ("velocity", "velocity"),
                          ("acceleration", "acceleration")):
            if not np.array_equal(seen["%s_%d" % (name, k)], record[key][k]):
                why.append("%s differ from the row's" % name)
        load = seen["load_%d" % k]
        if np.linalg.norm(load.sum(axis=0) - sums[k]) > 1e-12 * np.linalg.norm(sums[k]):
            why.append("load sum %s, the row's %s" % (load.sum(axis=0), sums[k]))
        balance = (weights[:, None] * seen["traction_%d" % k]).sum(axis=0) - load.sum(axis=0)
        if np.linalg.norm(balance) > 1e-12 * np.abs(load).sum():
            why.append("int traction dA - sum load = %s" % balance)
        if why:
            bad[k] = "; ".join(why)
    return bad


seen = read(out + "/interface.pvd")
if seen["reader"] != "PVDReader":
    failures.append("opened with %s, not ParaView's PVDReader" % seen["reader"])
for k, why in check(seen).items():
    failures.append("t = %g: %s" % (record["time"][k] if k >= 0 else -1, why))

# The wrong-row layout: each time shows the row before (row 0 at t = 0).
with open(out + "/interface.pvd") as f:
    lines = f.read().splitlines()
entries = [i for i, line in enumerate(lines) if line.startswith("<DataSet")]
for i, j in zip(entries[:0:-1], entries[-2::-1]):
    lines[i] = lines[i].split(" file=")[0] + " file=" + lines[j].split(" file=")[1]
with open(out + "/shifted.pvd", "w") as f:
    f.write("\n".join(lines) + "\n")
caught = sorted(check(read(out + "/shifted.pvd")))
if caught != list(range(1, rows)):
    failures.append("the wrong-row series fails at rows %s, not at every row after 0" % caught)

png = out + "/interface.png"
drawn = subprocess.run([scripts + "/render", out, "--interface", "--time", "0.0031", "--png", png,
                        "--size", "800", "450"], capture_output=True, text=True)
if drawn.returncode != 0:
    failures.append("scripts/render --interface exited %d:\n%s%s"
                    % (drawn.returncode, drawn.stdout, drawn.stderr))
else:
    report = json.loads(drawn.stdout.strip().splitlines()[-1])
    magnitude = np.linalg.norm(seen["traction_3"], axis=1)
    want = [magnitude.min(), magnitude.max()]
    if report["time"] != 0.003 or not np.allclose(report["range"], want, rtol=1e-12, atol=0.0):
        failures.append("drew t = %g over %s, want 0.003 over %s"
                        % (report["time"], report["range"], want))
    image = matplotlib.image.imread(png)[:, :640, :3]  # left of the colour bar
    drawn_share = np.mean(np.any(image < 0.97, axis=2))
    r, g, b = image[:, :, 0], image[:, :, 1], image[:, :, 2]
    bright = np.sum((r > 0.9) & (g > 0.6) & (b < 0.7))  # Inferno's top fifth: the peaks (41)
    if drawn_share < 0.05 or bright < 20:
        failures.append("the plate covers %.3f of the picture, %d bright pixels"
                        % (drawn_share, bright))
for f in failures:
    print("FAIL:", f)
print("ok: %d times read as recorded, the shifted series caught at %d" % (rows, len(caught))
      if not failures else "%d failures" % len(failures))
sys.exit(1 if failures else 0)
