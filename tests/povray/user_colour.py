"""The wetness function for any base colour, evaluated by soak.inc at parse
time (Soak_Wet_Colour) and at render time (Soak_Wet_User_Material: a per-channel
colour_map over the user's pigment; Soak_Wet_User_Texture_Fn: a texture_map over
wetness), against an independent bilinear interpolation of the JSON export's
base_colour table (`soak export --target json`, another writer of the same core
function). Rendered, the colour is seen along the normal: times the preset's view
factor at cos 1 (the JSON's knots.view_factor, lerped in wetness); the _Fn texture
lerps the base table's wetness rows, each with its own factor.

usage: user_colour.py SOAK ROOT TMPDIR"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import export_json, fail, povray, read_image, setup_args  # noqa: E402

CASES = [("sand", 0.0, (0.5, 0.3, 0.2)), ("sand", 0.6, (0.5, 0.3, 0.2)), ("clay", 0.37, (0.9, 0.05, 0.61)),
         ("brick", 1.0, (1.0, 0.0, 0.333)), ("oak", 0.81, (0.12, 0.77, 0.45)), ("copper", 0.5, (0.95, 0.64, 0.54)),
         ("paper", 0.93, (0.8, 0.8, 0.8))]

HEAD = """#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 1;
#declare Soak_Highlights = 0;
#include "soak.inc"
camera { orthographic location <0.5,0.5,5> look_at <0.5,0.5,0> up y right -x sky y }
"""


def bilinear(exp, name, w, rgb):
    m = next(m for m in exp["materials"] if m["name"] == name)
    t = m["liquids"]["water"]["base_colour"]
    a, ws, tab = np.array(t["dry_albedo"]), np.array(t["wetness"]), np.array(t["albedo"])
    out = []
    for c in range(3):
        rows = [np.interp(rgb[c], a, tab[c][i]) for i in range(len(ws))]
        out.append(np.interp(w, ws, rows))
    return np.array(out)


def view_factor(exp, name, w):
    """The preset's view factor seen along the normal (view_cos 1), lerped in wetness."""
    m = next(m for m in exp["materials"] if m["name"] == name)
    k = m["liquids"]["water"]["knots"]
    j = exp["view_cos"].index(1.0)
    return np.array([np.interp(w, k["wetness"], [v[j][c] for v in k["view_factor"]]) for c in range(3)])


def seen(exp, name, w, rgb, kind):
    """The colour rendered along the normal: const, the wet colour times the factor at w;
    fn, the texture_map's lerp over the base table's wetness rows of the same product."""
    if kind == "const":
        return bilinear(exp, name, w, rgb) * view_factor(exp, name, w)
    m = next(m for m in exp["materials"] if m["name"] == name)
    ws = m["liquids"]["water"]["base_colour"]["wetness"]
    rows = np.array([bilinear(exp, name, wi, rgb) * view_factor(exp, name, wi) for wi in ws])
    return np.array([np.interp(w, ws, rows[:, c]) for c in range(3)])


def main():
    soak, root, tmp, lib = setup_args(__doc__)
    exp = export_json(soak, tmp)
    bad = 0
    # parse time
    body = ""
    for i, (p, w, c) in enumerate(CASES):
        body += (f'#declare C{i} = Soak_Wet_Colour("{p}", "water", {w}, <{c[0]},{c[1]},{c[2]}>);\n'
                 f'#debug concat("CASE {i} ", vstr(3, C{i}, " ", 0, 7), "\\n")\n')
    pov = os.path.join(tmp, "parse.pov")
    with open(pov, "w") as f:
        f.write(HEAD + "background { rgb 0 }\n" + body)
    rc, log = povray(pov, os.path.join(tmp, "parse.exr"), 2, 2, lib)
    if rc != 0:
        fail(f"parse-time scene: exit {rc}\n{log[-1500:]}")
    got = {int(m.group(1)): np.array([float(v) for v in m.group(2).split()])
           for m in re.finditer(r"CASE (\d+) ([-0-9. e]+)", log)}
    for i, (p, w, c) in enumerate(CASES):
        ref = bilinear(exp, p, w, c)
        err = np.abs(got[i] - ref).max() if i in got else np.inf
        ok = err <= 2e-6
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} parse time {p} w={w} {c}: {got.get(i)} vs {ref} (err {err:.2e})")
    # render time: ambient-only light shows the pigment itself
    for i, (p, w, c) in enumerate(CASES):
        for kind in ("const", "fn"):
            if kind == "const":
                obj = (f'box {{ <0,0,-1>, <1,1,0> Soak_Wet_User_Material("{p}", "water", {w}, '
                       f'pigment {{ rgb <{c[0]},{c[1]},{c[2]}> }}) }}')
            else:
                obj = (f'#declare W = function {{ {w} }}\nbox {{ <0,0,-1>, <1,1,0> material {{ '
                       f'Soak_Wet_User_Texture_Fn("{p}", "water", W, pigment {{ rgb <{c[0]},{c[1]},{c[2]}> }}) '
                       f'Soak_Wet_Interior("water") }} }}')
            pov = os.path.join(tmp, f"r{i}{kind}.pov")
            with open(pov, "w") as f:
                # metals show their pigment through reflection { 1 metallic } of a white sky
                f.write(HEAD + f"background {{ rgb {1 if p == 'copper' else 0} }}\n" + obj + "\n")
            out = os.path.join(tmp, f"r{i}{kind}.exr")
            rc, log = povray(pov, out, 4, 4, lib)
            if rc != 0:
                fail(f"{pov}: exit {rc}\n{log[-1500:]}")
            px = read_image(out).mean((0, 1))
            ref = seen(exp, p, w, c, kind)
            # half-float output: 2^-11 relative; the clamp of channel 1.0 to 1 - 1e-6
            ok = np.all(np.abs(px - ref) <= 1e-3 * np.maximum(ref, 0.05) + 2e-5)
            bad += not ok
            print(f"{'ok  ' if ok else 'FAIL'} render {kind:5} {p} w={w} {c}: {px} vs {ref}")
    if bad:
        fail(f"{bad} checks failed")
    print("PASS")


if __name__ == "__main__":
    main()
