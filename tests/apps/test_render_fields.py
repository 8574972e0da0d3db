"""scripts/render draws a 3-D coupled run (issue 46): the shipped SPH + T10 hydrostatic plate
(data/scenes/hydrostatic_plate_3d.yaml) run for 0.02 s, its frame nearest 0.011 s drawn with the
fluid clipped. The picture must be the file's: the frame drawn is t = 0.01 s, the pressure and von
Mises colour maps span that frame's own minimum and maximum in fields.h5 exactly, the PNG has the
asked size, and it shows both (pixels of the pressure map's warm end and of the stress map's
yellow end, and 5-95 % of it not background).

Usage: python3 test_render_fields.py RENDER FSI SCENE OUTDIR. Exit 77 without ParaView or Xvfb.
"""
import json
import shutil
import subprocess
import sys

import h5py
import matplotlib.image
import numpy as np

render, fsi, scene, out = sys.argv[1:5]
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
for f in failures:
    print("FAIL:", f)
print("ok: %.3f drawn, %d red, %d yellow pixels" % (drawn_share, warm, yellow)
      if not failures else "%d failures" % len(failures))
sys.exit(1 if failures else 0)
