"""POV-Ray reads `soak bake beads` as baked and draws the beads.

1. Soak_Bead_Height_Fn shows the map's height (alpha) flat (ambient 1,
   orthographic over the unit square, pixel centres on texel centres): every
   pixel within 1/255 of the baked file read by oiiotool (the reference).
2. A y-up ground (the map laid on x-z by `rotate 90*x scale L`) lit from the
   side with Soak_Bead_Normal: the luminance standard deviation over the
   beaded map is above 0.02 and above 10x that of the same scene with the map
   of a film surface (contact angle 30 deg, below --bead-above: flat), whose
   spread is rounding only (a parallel light); the beaded render's mean luminance differs from
   the film's only by what the beads' tilted normals add (within 25 %).
3. Bad input (a PNG map) stops the parse with the macro's message.

usage: beads.py SOAK ROOT TMPDIR"""
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import fail, povray, read_image, setup_args  # noqa: E402

N = 128
TEXEL = 0.0005
L = N * TEXEL
H = 0.006

FLAT = """#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#include "soak.inc"
camera { orthographic location <0.5, 0.5, 5> look_at <0.5, 0.5, 0> right -x up y sky y }
#declare F = Soak_Bead_Height_Fn("b.exr", transform { }, 0)
plane { z, 0 pigment { function { min(max(F(x, y, z), 0), 1 - 1e-6) } color_map { [0 rgb 0] [1 rgb 1] } }
  finish { ambient 1 diffuse 0 } }
"""

LIT = """#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
#include "soak.inc"
camera {{ orthographic location <{c}, 1, {c}> look_at <{c}, 0, {c}> right x * {L} up z * {L} }}
light_source {{ <-100, 60, 30> rgb 1 parallel point_at <0, 0, 0> }}
#declare F = Soak_Bead_Height_Fn("{map}", transform {{ rotate 90*x scale {L} }}, 1)
plane {{ y, 0 pigment {{ rgb 0.5 }} finish {{ diffuse 1 ambient 0 }} Soak_Bead_Normal(F, {H}, {L}) }}
"""


def run(cmd, cwd):
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=cwd)
    if r.returncode != 0:
        fail(f"{' '.join(cmd)}: exit {r.returncode}\n{r.stderr[-1500:]}")
    return r


def render(tmp, lib, name, text, size):
    pov = os.path.join(tmp, name + ".pov")
    with open(pov, "w") as f:
        f.write(text)
    out = os.path.join(tmp, name + ".exr")
    code, log = povray(pov, out, size, size, lib, cwd=tmp)
    if code != 0:
        fail(f"{name}: povray exit {code}\n{log[-1500:]}")
    return read_image(out)


def alpha(path):
    out = subprocess.run(["oiiotool", "--dumpdata", path], check=True, capture_output=True, text=True).stdout
    vals = {}
    for line in out.splitlines():
        if line.strip().startswith("Pixel ("):
            xy, v = line.split(":", 1)
            x, y = (int(t) for t in xy.strip()[7:-1].split(","))
            vals[(x, y)] = float(v.split()[3])
    img = np.zeros((N, N))
    for (x, y), v in vals.items():
        img[y, x] = v
    return img


def main():
    soak, root, tmp, lib = setup_args("usage: beads.py SOAK ROOT TMPDIR")
    common = ["bake", "beads", "--rate", "25", "--duration", "60", "--width", str(N), "--height", str(N),
              "--texel", str(TEXEL), "--height-range", str(H), "--float"]
    r = run([soak] + common + ["--contact-angle", "90", "-o", "b.exr"], tmp)
    print(r.stderr.strip())
    r = run([soak] + common + ["--contact-angle", "30", "-o", "film.exr"], tmp)
    print(r.stderr.strip())

    got = render(tmp, lib, "height", FLAT, N).mean(axis=2)
    want = alpha(os.path.join(tmp, "b.exr"))
    err = np.abs(got - np.minimum(want, 1 - 1e-6)).max()
    print(f"height function vs the baked alpha: worst {err:.2e} over {N}x{N} pixels, map max {want.max():.3f}")
    if not (want.max() > 0.05):
        fail("the bead map holds no beads (max height under 5 % of the range)")
    if not err <= 1 / 255:
        fail(f"Soak_Bead_Height_Fn differs from the baked height by {err:.4f} > 1/255")

    lum = {}
    for name in ("b", "film"):
        img = render(tmp, lib, "lit_" + name, LIT.format(c=L / 2, L=L, H=H, map=name + ".exr"), N)
        lum[name] = img @ np.array([0.2126, 0.7152, 0.0722])
    sb, sf = lum["b"].std(), lum["film"].std()
    mb, mf = lum["b"].mean(), lum["film"].mean()
    print(f"luminance std: beads {sb:.4f}, film {sf:.5f}; mean beads {mb:.4f}, film {mf:.4f}")
    if not (sb > 0.02 and sb > 10 * sf):
        fail(f"beads do not show: luminance std {sb:.4f} (film {sf:.5f}); want > 0.02 and > 10x the film's")
    if not abs(mb / mf - 1) < 0.25:
        fail(f"mean luminance beads {mb:.4f} vs film {mf:.4f}: more than 25 % apart")

    bad = os.path.join(tmp, "bad.pov")
    with open(bad, "w") as f:
        f.write(FLAT.replace("b.exr", "b.png"))
    code, log = povray(bad, os.path.join(tmp, "bad.exr"), 8, 8, lib, cwd=tmp)
    if code == 0 or "must be the .exr" not in log:
        fail(f"a PNG bead map: want the macro's parse error, got exit {code}\n{log[-800:]}")
    print("PASS")


main()
