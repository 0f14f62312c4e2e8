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

With --images it renders instead the README's rain picture,
povray/images/rain_pair.png: the README's "Rain over time" set-up at its
camera, before (Soak_Wet_Material_Fn, the ripple normal with POV-Ray's default
finite-difference step), after (Soak_Wet_Drops_Material, the overlay through
Soak_Ripple_Normal_Far) and after with the ring slopes x 5 (a 1.5 mm
--amplitude), the middle of each at twice the scale below; the sky is blender-data's
courtyard HDRI (CC0).

usage: ripples_far.py SOAK ROOT TMPDIR [--images]"""
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


HDRI = "/usr/share/blender/datafiles/studiolights/world/courtyard.exr"
PICTURE = """#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
#include "soak.inc"
#declare Cam = <0.5, -0.6, 0.35>;
camera {{ location Cam look_at <0.5, 0.5, 0> sky z right -x*image_width/image_height }}
light_source {{ <3, -2, 5> rgb 1 }}
sky_sphere {{ pigment {{ image_map {{ exr "{hdri}" gamma 1.0 map_type 1 interpolate 2 }} }} rotate 90*x }}
box {{ <0.2, 0.8, 0>, <0.4, 1.0, 0.3> pigment {{ rgb <0.8, 0.2, 0.1> }} }}
#declare Wet = Soak_Drops_Fn("drops.", ".exr", 4, 0.6, 0, 3, 1)
#if ({after})
  plane {{ z, 0 Soak_Wet_Drops_Material("concrete", "water", Wet, 0.1) }}
  #declare Rip = Soak_Ripple_Normal_Far("rip.", "far.", ".exr", 4, 1, 0, {gain} * 4 * 0.0003 / 0.5, 0.5, Cam,
                                        Soak_Ripple_Far_Distance(0.01713, 67.38, image_width))
#else
  plane {{ z, 0 Soak_Wet_Material_Fn("concrete", "water", Wet) }}
  #declare H = Soak_Ripple_Height_Fn("rip.", ".exr", 4, 1, 0)
  #declare Rip = normal {{ function {{ H(x, y, z) }} 4 * 0.0003 / 0.5 scale 0.5 }}
#end
plane {{ z, 0.001 texture {{ pigment {{ rgbf 1 }} finish {{ reflection {{ 0.02, 1 fresnel on }} }} normal {{ Rip }} }}
  interior {{ ior 1.33 }} }}
"""


def images(soak, root, tmp, lib):
    """The README's before/after rain picture (not a test)."""
    if not os.path.exists(HDRI):
        fail(f"{HDRI} missing (Debian's blender-data)")
    for cmd in ([soak, "bake", "drops", "--rate", "10", "--map-size", "1", "--duration", "2", "--fps", "4",
                 "--frames", "0-3", "-o", "drops.%04d.exr"],
                [soak, "bake", "ripples", "--rate", "10", "--tile", "0.5", "--loop-frames", "4", "--period", "1",
                 "--frames", "0-0", "-o", "rip.%04d.exr", "--far", "far.%04d.exr"]):
        r = subprocess.run(cmd, capture_output=True, text=True, cwd=tmp)
        if r.returncode != 0:
            fail(f"{' '.join(cmd)}: exit {r.returncode}\n{r.stderr[-1500:]}")
    w, h = 600, 450
    tiles = []
    for name, after, gain in (("before", 0, 1), ("after", 1, 1), ("after_x5", 1, 5)):
        pov = os.path.join(tmp, f"pic_{name}.pov")
        with open(pov, "w") as f:
            f.write(PICTURE.format(hdri=HDRI, after=after, gain=gain))
        png = os.path.join(tmp, f"pic_{name}.png")
        r = subprocess.run(["povray", f"+I{pov}", f"+O{png}", f"+W{w}", f"+H{h}", "-D", "+WT2", f"+L{lib}",
                            "+A0.1", "+AM2", "+R2"], capture_output=True, text=True, cwd=tmp)
        if r.returncode != 0:
            fail(f"{pov}: exit {r.returncode}\n{r.stderr[-1500:]}")
        print(f"{name}:", " ".join(re.findall(r"Trace Time:.*", r.stdout + r.stderr)))
        small, crop = os.path.join(tmp, f"small_{name}.png"), os.path.join(tmp, f"crop_{name}.png")
        subprocess.run(["oiiotool", png, "--resize", f"{w // 2}x{h // 2}", "-o", small], check=True)
        # the middle of the frame at full resolution: twice the scale of the frame above it
        subprocess.run(["oiiotool", png, "--cut", f"{w // 2}x{h // 2}+{w // 4}+{h // 4}", "--origin", "+0+0",
                        "-o", crop], check=True)
        tiles.append((small, crop))
    out = os.path.join(root, "povray", "images", "rain_pair.png")
    mosaic = ["--mosaic", "3x2", "-d", "uint8", "--attrib", "png:compressionLevel", "9", "-o", out]
    subprocess.run(["oiiotool"] + [t[0] for t in tiles] + [t[1] for t in tiles] + mosaic, check=True)
    print("wrote", out)


def main():
    soak, _root, tmp, lib = setup_args(__doc__)
    if "--images" in sys.argv:
        images(soak, _root, tmp, lib)
        return
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
