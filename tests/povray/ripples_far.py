"""Soak_Ripple_Normal_Far: sharp rings near the camera, the `--far` flipbook
where a pixel cannot resolve them, and what a distant puddle then shows.

A mirror (reflection 1, nothing else) carries the rings of `soak bake ripples`
(2 mm texels, 0.25 m tile) under a sky whose radiance is linear in the
direction's x, seen straight down by an orthographic camera over four tiles
at 32 x 32 pixels: a pixel spans 3.1 cm, about two ring wavelengths (1.71 cm).
The reference is the same sharp rings supersampled 7 x 7 per pixel (the mean
over each pixel's footprint, a second method).
- Energy: the image means of the far rings and of the sharp rings (one ray
  per pixel) equal the reference's within 4 standard errors of the per-pixel
  differences + 1e-3 (half-float output).
- Noise: one ray per pixel through the sharp rings is far from the pixel's
  mean (aliasing: more than 4 half-float steps of the output); through the
  far flipbook it is at most half as far (RMS over the pixels).
- The blend's ends: nearer than Far / 2 the macro renders exactly as
  Soak_Ripple_Normal of the sharp flipbook, beyond Far exactly as that of the
  far one; Soak_Ripple_Far_Distance(0.01713, 67.38, 960) = 0.01713 / (2 p),
  p = 2 tan(33.69 deg) / 960, computed here.

usage: ripples_far.py SOAK ROOT TMPDIR"""
import math
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import fail, povray, read_image, setup_args  # noqa: E402

TILE, WIDTH, LOOP, PERIOD = 0.25, 128, 2, 0.5
AMOUNT = 4 * 0.0003 / TILE      # the README's 0.3 mm amplitude as slopes
PX = 32

SCENE = """#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
#include "soak.inc"
camera {{ orthographic location <0.5, 0.5, 5> look_at <0.5, 0.5, 0> right -x up y sky y }}
sky_sphere {{ pigment {{ function {{ 0.5 + 0.45 * x }} color_map {{ [0 rgb 0] [1 rgb 1] }} }} }}
#declare Near0 = Soak_Ripple_Normal("r.", ".exr", {loop}, {period}, 0, {amount})
#declare Far0 = Soak_Ripple_Normal("f.", ".exr", {loop}, {period}, 0, {amount})
#declare Near = normal {{ Near0 scale {tile} }}
#declare Far = normal {{ Far0 scale {tile} }}
#declare N = {normal}
plane {{ z, 0 texture {{ pigment {{ rgb 0 }} finish {{ ambient 0 diffuse 0 reflection 1 }} normal {{ N }} }} }}
"""


def render(tmp, lib, name, normal, extra=()):
    pov = os.path.join(tmp, name + ".pov")
    with open(pov, "w") as f:
        f.write(SCENE.format(loop=LOOP, period=PERIOD, amount=AMOUNT, tile=TILE, normal=normal))
    out = os.path.join(tmp, name + ".exr")
    rc, log = povray(pov, out, PX, PX, lib, extra=extra, cwd=tmp)
    if rc != 0:
        fail(f"{name}: povray exit {rc}\n{log[-1500:]}")
    return read_image(out)[:, :, 0]


def main():
    soak, _root, tmp, lib = setup_args(__doc__)
    r = subprocess.run([soak, "bake", "ripples", "--rate", "30", "--width", str(WIDTH), "--tile", str(TILE),
                        "--loop-frames", str(LOOP), "--period", str(PERIOD), "--frames", f"0-{LOOP - 1}",
                        "-o", "r.%04d.exr", "--far", "f.%04d.exr"], capture_output=True, text=True, cwd=tmp)
    if r.returncode != 0:
        fail(f"soak bake ripples: exit {r.returncode}\n{r.stderr[-1500:]}")
    macro = 'Soak_Ripple_Normal_Far("r.", "f.", ".exr", {l}, {p}, 0, {a}, {t}, <0.5, 0.5, 5>, {far})'
    ref = render(tmp, lib, "ref", "normal { Near }", extra=["+A0.0", "+AM1", "+R7"])
    near = render(tmp, lib, "near", "normal { Near }")
    far = render(tmp, lib, "far", macro.format(l=LOOP, p=PERIOD, a=AMOUNT, t=TILE, far=1))
    bad = 0
    for what, img in (("far rings", far), ("sharp rings", near)):
        d = img - ref
        tol = 4 * d.std() / math.sqrt(d.size) + 1e-3
        ok = abs(d.mean()) <= tol
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} energy, {what}: image mean {img.mean():.5f} vs supersampled "
              f"{ref.mean():.5f} (|diff| {abs(d.mean()):.2e}, tol {tol:.2e})")
    rms_near = math.sqrt(((near - ref) ** 2).mean())
    rms_far = math.sqrt(((far - ref) ** 2).mean())
    half_step = 0.5 * 2 ** -11          # a half-float step at the image's level 0.5
    ok = rms_far <= 0.5 * rms_near and rms_near > 4 * half_step
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} noise: RMS from the pixel's mean, far {rms_far:.4f} <= half the sharp "
          f"{rms_near:.4f} (and the sharp one aliases: > 4 half-float steps, {4 * half_step:.1e})")
    # the blend's ends: every point is 5 units from the camera
    far_only = render(tmp, lib, "far_only", "normal { Far }")
    near_end = render(tmp, lib, "near_end", macro.format(l=LOOP, p=PERIOD, a=AMOUNT, t=TILE, far=100))
    for what, got, want in (("beyond Far = the far flipbook", far, far_only),
                            ("nearer than Far / 2 = the sharp flipbook", near_end, near)):
        ok = np.array_equal(got, want)
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {what} (max diff {np.abs(got - want).max():.2e})")
    pov = os.path.join(tmp, "dist.pov")
    with open(pov, "w") as f:
        f.write('#version 3.7;\n#include "soak.inc"\n'
                '#debug concat("FAR ", str(Soak_Ripple_Far_Distance(0.01713, 67.38, 960), 0, 9), "\\n")\n')
    rc, log = povray(pov, os.path.join(tmp, "dist.exr"), 2, 2, lib, cwd=tmp)
    m = re.search(r"FAR ([0-9.]+)", log)
    want = 0.01713 / (2 * (2 * math.tan(math.radians(67.38 / 2)) / 960))
    ok = rc == 0 and m is not None and abs(float(m.group(1)) - want) <= 1e-6 * want
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} Soak_Ripple_Far_Distance(0.01713, 67.38, 960) = "
          f"{m.group(1) if m else '?'} vs {want:.6f}")
    if bad:
        fail(f"{bad} checks failed")
    print("PASS")


if __name__ == "__main__":
    main()
