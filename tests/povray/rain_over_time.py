"""POV-Ray reads the rain-over-time bakes as baked: Soak_Drops_Fn picks the
frame of `soak bake drops` at clock (t = f / fps) and interpolates linearly
between frames; Soak_Ripple_Height_Fn reads the loop frame of `soak bake
ripples` nearest to clock from its alpha and wraps at the period. The
references are the baked files themselves (read by oiiotool); POV-Ray shows
each function flat (ambient 1, orthographic over the unit square, pixel
centres on texel centres). Pass: every pixel within 1/255 (half-float
frames; the bilinear look-up at a texel centre is the texel). Then a lit
plane with Soak_Ripple_Normal renders, shows the rings (pixel spread above
Amount 0's), and the loop: clock = period renders as clock = 0.
Soak_Wet_Material_Rippled (rings only on knots of wetness >= From) renders its
dry half as Soak_Wet_Material_Fn and its wet half as Soak_Wet_Material_Bumped.
Bad input (fps 0) stops the parse with the macro's message.

usage: rain_over_time.py SOAK ROOT TMPDIR"""
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import fail, povray, read_image, setup_args  # noqa: E402

N = 32          # drops map texels
FPS = 2
RN = 48         # ripple tile texels
LOOP, PERIOD = 8, 0.8

FLAT = """#version 3.7;
global_settings {{ assumed_gamma 1.0 ambient_light 1 }}
#include "soak.inc"
camera {{ orthographic location <0.5, 0.5, 5> look_at <0.5, 0.5, 0> right -x up y sky y }}
#declare F = {fn}
plane {{ z, 0 pigment {{ function {{ min(max(F(x, y, z), 0), 1 - 1e-6) }} color_map {{ [0 rgb 0] [1 rgb 1] }} }}
  finish {{ ambient 1 diffuse 0 }} }}
"""

LIT = """#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
#include "soak.inc"
camera {{ orthographic location <0.5, 0.5, 5> look_at <0.5, 0.5, 0> right -x up y sky y }}
light_source {{ <-3, 2, 4> rgb 1 }}
plane {{ z, 0 pigment {{ rgb 0.5 }} finish {{ diffuse 1 }}
  Soak_Ripple_Normal("r.", ".exr", {loop}, {period}, clock, {amount}) }}
"""

# the bottom half (y < 0.5) dry, the top half wet (1): Soak_Wet_Material_Rippled
# against Soak_Wet_Material_Fn (no normal) and Soak_Wet_Material_Bumped (the normal everywhere)
RIPPLED = """#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
#include "soak.inc"
camera {{ orthographic location <0.5, 0.5, 5> look_at <0.5, 0.5, 0> right -x up y sky y }}
light_source {{ <-3, 2, 4> rgb 1 }}
#declare W = function {{ select(y - 0.5, 0, 1) }}
#declare Rip = Soak_Ripple_Normal("r.", ".exr", {loop}, {period}, clock, 0.2)
plane {{ z, 0 {mat} }}
"""
MATS = {"plain": 'Soak_Wet_Material_Fn("concrete", "water", W)',
        "bumped": 'Soak_Wet_Material_Bumped("concrete", "water", W, normal { Rip })',
        "rippled": 'Soak_Wet_Material_Rippled("concrete", "water", W, normal { Rip }, 0.5)'}


def rippled_checks(tmp, lib):
    """Soak_Wet_Material_Rippled: the dry half renders as the unbumped material
    (no rings on dry ground), the wet half as the bumped one. Returns the failures."""
    img = {k: render(tmp, lib, "rip_" + k, RIPPLED.format(loop=LOOP, period=PERIOD, mat=m), 0, RN)
           for k, m in MATS.items()}
    wet, dry = slice(0, RN // 2 - 2), slice(RN // 2 + 2, RN)   # image rows top down: y > 0.5 first
    checks = [("bumped dry half differs from the unbumped (the check can fail)",
               np.abs(img["bumped"][dry] - img["plain"][dry]).max() > 0.01),
              ("rippled dry half = the unbumped material (within 1e-4)",
               np.abs(img["rippled"][dry] - img["plain"][dry]).max() <= 1e-4),
              ("rippled wet half = the bumped material (within 1e-4)",
               np.abs(img["rippled"][wet] - img["bumped"][wet]).max() <= 1e-4)]
    for what, ok in checks:
        print(f"{'ok  ' if ok else 'FAIL'} {what}")
    return sum(not ok for _, ok in checks)


def run(cmd, cwd):
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=cwd)
    if r.returncode != 0:
        fail(f"{' '.join(cmd)}: exit {r.returncode}\n{r.stderr[-1500:]}")


def render(tmp, lib, name, text, clock, size):
    pov = os.path.join(tmp, name + ".pov")
    with open(pov, "w") as f:
        f.write(text)
    out = os.path.join(tmp, name + ".exr")
    code, log = povray(pov, out, size, size, lib, extra=[f"+K{clock}"], cwd=tmp)
    if code != 0:
        fail(f"{name}: povray exit {code}\n{log[-1500:]}")
    return read_image(out)[:, :, 0]


def channel(path, c):
    out = subprocess.run(["oiiotool", "--dumpdata", path], check=True, capture_output=True, text=True).stdout
    vals = [line.split(":", 1)[1].split() for line in out.splitlines() if line.strip().startswith("Pixel (")]
    return np.array([float(v[c]) for v in vals])


def compare(what, got, want, failures):
    err = np.abs(got.ravel() - want.ravel()).max()
    ok = err <= 1 / 255
    print(f"{'ok  ' if ok else 'FAIL'} {what}: max |POV-Ray - baked| = {err:.2e} (tol {1 / 255:.2e})")
    failures += 0 if ok else 1
    return failures


def main():
    soak, _root, tmp, lib = setup_args(__doc__)
    run([soak, "bake", "drops", "--rate", "60", "--map-size", "0.05", "--width", str(N), "--height", str(N),
         "--duration", "2", "--dry-time", "2", "--fps", str(FPS), "--frames", "0-6", "-o", "d.%04d.exr"], tmp)
    run([soak, "bake", "ripples", "--rate", "30", "--width", str(RN), "--tile", "0.25", "--loop-frames", str(LOOP),
         "--period", str(PERIOD), "--frames", f"0-{LOOP - 1}", "-o", "r.%04d.exr"], tmp)
    frame = {f: channel(os.path.join(tmp, f"d.{f:04d}.exr"), 0) for f in (2, 3)}
    failures = 0
    if frame[2].max() <= 0 or np.array_equal(frame[2], frame[3]):
        fail("drops frames 2 and 3 are empty or equal: nothing to compare")
    drops = FLAT.format(fn=f'Soak_Drops_Fn("d.", ".exr", {FPS}, clock, 0, 6, 0)')
    failures = compare("drops at t = 1 s = baked frame 2", render(tmp, lib, "drops_a", drops, 1.0, N), frame[2],
                       failures)
    failures = compare("drops at t = 1.25 s = (frame 2 + frame 3) / 2",
                       render(tmp, lib, "drops_b", drops, 1.25, N), 0.5 * (frame[2] + frame[3]), failures)
    if np.array_equal(channel(os.path.join(tmp, "r.0000.exr"), 3), channel(os.path.join(tmp, "r.0003.exr"), 3)):
        fail("ripple frames 0 and 3 are equal: nothing to tell them apart")
    height = FLAT.format(fn=f'Soak_Ripple_Height_Fn("r.", ".exr", {LOOP}, {PERIOD}, clock)')
    for clock, f in ((0.0, 0), (3 * PERIOD / LOOP, 3), (PERIOD, 0), (PERIOD + 3 * PERIOD / LOOP + 0.01, 3)):
        failures = compare(f"ripple height at t = {clock:.3f} s = alpha of loop frame {f}",
                           render(tmp, lib, "height", height, clock, RN),
                           channel(os.path.join(tmp, f"r.{f:04d}.exr"), 3), failures)
    flat = render(tmp, lib, "lit0", LIT.format(loop=LOOP, period=PERIOD, amount=0), 0, RN)
    lit = render(tmp, lib, "lit1", LIT.format(loop=LOOP, period=PERIOD, amount=0.2), 0, RN)
    looped = render(tmp, lib, "lit2", LIT.format(loop=LOOP, period=PERIOD, amount=0.2), PERIOD, RN)
    ok = (lit - flat).std() > 0.01
    print(f"{'ok  ' if ok else 'FAIL'} lit ripples differ from the unbumped plane: spread {(lit - flat).std():.4f} > 0.01")
    failures += 0 if ok else 1
    ok = np.array_equal(lit, looped)
    print(f"{'ok  ' if ok else 'FAIL'} lit ripples at t = period render as at t = 0")
    failures += 0 if ok else 1
    failures += rippled_checks(tmp, lib)
    pov = os.path.join(tmp, "bad.pov")
    with open(pov, "w") as f:
        f.write(FLAT.format(fn='Soak_Drops_Fn("d.", ".exr", 0, clock, 0, 6, 0)'))
    code, log = povray(pov, os.path.join(tmp, "bad.exr"), 8, 8, lib, cwd=tmp)
    ok = code != 0 and "Soak_Drops_Fn: Fps = " in log
    print(f"{'ok  ' if ok else 'FAIL'} Soak_Drops_Fn with Fps 0 stops the parse with its message (exit {code})")
    failures += 0 if ok else 1
    print(f"{'all passed' if not failures else f'{failures} failed'}")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
