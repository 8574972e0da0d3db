"""scripts/render draws a 3-D coupled run (issue 46): the shipped SPH + T10 hydrostatic plate
(data/scenes/hydrostatic_plate_3d.yaml) run for 0.02 s, its frame nearest 0.011 s drawn with the
fluid clipped. The picture must be the file's: the frame drawn is t = 0.01 s, the pressure and von
Mises colour maps span that frame's own minimum and maximum in fields.h5 exactly, the PNG has the
asked size, and it shows both (pixels of the pressure map's warm end and of the stress map's
yellow end, and 5-95 % of it not background). Then a TL-SPH solid (CANTILEVER, the 3-D cantilever
as TL-SPH, 0.02 s): its particles drawn as spheres, not one-pixel points: over 3 % of the picture
left of the colour bar drawn (spheres 6.8 %, points 1.1 %), its von Mises range fields.h5's.

Usage: python3 test_render_fields.py RENDER FSI SCENE CANTILEVER OUTDIR. Exit 77 without ParaView
or Xvfb.
"""
import json
import shutil
import subprocess
import sys

import h5py
import matplotlib.image
import numpy as np

render, fsi, scene, cantilever, out = sys.argv[1:6]
if shutil.which("pvpython") is None or shutil.which("Xvfb") is None:
    print("skipped: pvpython or Xvfb missing (python3-paraview, xvfb: scripts/setup)")
    sys.exit(77)
shutil.rmtree(out, ignore_errors=True)
subprocess.run([fsi, "run", scene, "--out", out, "--threads", "1", "--set", "time.end=0.02",
                "--set", "output.interval=0.01"], check=True, stdout=subprocess.DEVNULL)
png = out + "/picture.png"
drawn = subprocess.run([render, out, "--time", "0.011", "--png", png, "--size", "800", "450",
                        "--clip", "z"], capture_output=True, text=True)
if drawn.returncode != 0:
    print("FAIL: scripts/render exited %d:\n%s%s" % (drawn.returncode, drawn.stdout, drawn.stderr))
    sys.exit(1)
report = json.loads(drawn.stdout.strip().splitlines()[-1])

failures = []
if report["time"] != 0.01:
    failures.append("drew t = %g, not the frame nearest 0.011 (0.01)" % report["time"])
with h5py.File(out + "/fields.h5", "r") as h5:
    frame = h5["frames/1"]
    for field, grid in (("pressure", "particles"), ("von_mises", "plate")):
        data = frame[grid][field][...]
        want = [float(data.min()), float(data.max())]
        if report["ranges"].get(field) != want:
            failures.append("%s range %s, fields.h5 %s" % (field, report["ranges"].get(field),
                                                           want))
image = matplotlib.image.imread(png)[:, :, :3]
if image.shape[:2] != (450, 800):
    failures.append("PNG is %s, not 450 x 800" % (image.shape[:2],))
drawn_share = np.mean(np.any(image < 0.97, axis=2))
if not 0.05 < drawn_share < 0.95:
    failures.append("%.3f of the picture is not background" % drawn_share)
r, g, b = image[:, :, 0], image[:, :, 1], image[:, :, 2]
warm = np.sum((r > 0.6) & (g < 0.3) & (b < 0.3))  # Cool to Warm's red end: the deepest fluid
yellow = np.sum((r > 0.8) & (g > 0.8) & (b < 0.3))  # Viridis's yellow end: the clamped edges
if warm < 100 or yellow < 100:
    failures.append("pixels: %d of the pressure map's red end, %d of the stress map's yellow end"
                    % (warm, yellow))

solid = out + "/tlsph"
subprocess.run([fsi, "run", cantilever, "--out", solid, "--threads", "1", "--set",
                "structures[0].type=tlsph", "--set", "time.end=0.02", "--set",
                "output.interval=0.01"], check=True, stdout=subprocess.DEVNULL)
drawn = subprocess.run([render, solid, "--png", solid + "/picture.png", "--size", "800", "450"],
                       capture_output=True, text=True)
if drawn.returncode != 0:
    failures.append("scripts/render exited %d on the TL-SPH run:\n%s%s"
                    % (drawn.returncode, drawn.stdout, drawn.stderr))
else:
    report = json.loads(drawn.stdout.strip().splitlines()[-1])
    with h5py.File(solid + "/fields.h5", "r") as h5:
        data = h5["frames/2/beam/von_mises"][...]
        want = [float(data.min()), float(data.max())]
    if report["ranges"].get("von_mises") != want:
        failures.append("TL-SPH von_mises range %s, fields.h5 %s"
                        % (report["ranges"].get("von_mises"), want))
    image = matplotlib.image.imread(solid + "/picture.png")[:, :640, :3]
    spheres = np.mean(np.any(image < 0.97, axis=2))
    if spheres < 0.03:
        failures.append("the TL-SPH beam covers %.3f of the picture left of the bar" % spheres)
for f in failures:
    print("FAIL:", f)
print("ok: %.3f drawn, %d red, %d yellow pixels" % (drawn_share, warm, yellow)
      if not failures else "%d failures" % len(failures))
sys.exit(1 if failures else 0)
