"""Soak_Puddle_User_Material (the puddle with the user's own pigment) under
ambient light only (no light source, black sky: the film's reflection and the
glint add nothing), seen along the normal, against independent references:
dry (Wet_Fn = 0) = the user's pigment itself within 1 % per channel (the
identity of the wetness function at w = 0); the ground below the puddle's
Level at Wet_Fn / Level, and the standing water above it at wetness 1, = the
JSON export's base_colour table (`soak export --target json`, another writer of
the core's function) lerped over the base wetness rows, times the view factor
(user_colour.py's reference), within 0.1 % + 2e-5; and wet darker than dry.

usage: puddle_user.py SOAK ROOT TMPDIR"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import export_json, fail, povray, read_image, setup_args  # noqa: E402
from user_colour import HEAD, seen  # noqa: E402

LEVEL = 0.5
# (preset, Wet_Fn value, dry colour, what the point is)
CASES = [("brick", 0.0, (0.5, 0.3, 0.25), "dry"), ("brick", 0.2, (0.5, 0.3, 0.25), "ground"),
         ("sand", 0.45, (0.6, 0.5, 0.3), "ground"), ("brick", 0.9, (0.5, 0.3, 0.25), "water"),
         ("clay", 0.99, (0.9, 0.05, 0.6), "water")]


def main():
    soak, root, tmp, lib = setup_args(__doc__)
    exp = export_json(soak, tmp)
    bad = 0
    for i, (p, v, c, what) in enumerate(CASES):
        obj = (f"#declare W = function {{ {v} }}\n"
               f"box {{ <0,0,-1>, <1,1,0> Soak_Puddle_User_Material(\"{p}\", \"water\", W, {LEVEL}, "
               f"normal {{ bumps 0.3 scale 0.05 }}, pigment {{ rgb <{c[0]},{c[1]},{c[2]}> }}) }}")
        pov = os.path.join(tmp, f"p{i}.pov")
        with open(pov, "w") as f:
            f.write(HEAD + "background { rgb 0 }\n" + obj + "\n")
        out = os.path.join(tmp, f"p{i}.exr")
        rc, log = povray(pov, out, 4, 4, lib)
        if rc != 0:
            fail(f"{pov}: exit {rc}\n{log[-1500:]}")
        px = read_image(out).mean((0, 1))
        if what == "dry":
            ref = np.array(c)
            ok = np.all(np.abs(px - ref) <= 0.01 * ref)
        else:
            w = 1.0 if what == "water" else v / LEVEL
            ref = seen(exp, p, w, c, "fn")
            ok = np.all(np.abs(px - ref) <= 1e-3 * np.maximum(ref, 0.05) + 2e-5) and np.all(px < np.array(c))
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {what:6} {p} Wet_Fn={v} {c}: {px} vs {ref}")
    if bad:
        fail(f"{bad} checks failed")
    print("PASS")


if __name__ == "__main__":
    main()
