"""Soak_Wet_Drops_Material shows a raindrop as water: the texels a drop covers
take the table's last entry (wetness 1: the darkest pigment and the film's
mirror reflection), the rest of the ground the core's reading of the map.

A drops frame with one known drop (a 6 x 6 texel square at w = 0.24, the
median of the drop texels of the README's `soak bake drops --rate 10` bake;
0 elsewhere) is read through Soak_Drops_Fn and seen straight down
(orthographic, pixel centres on texel centres) under ambient light only.
References, from the JSON export (`soak export --target json`, another writer
of the core's tables) and Fresnel's equation written here:
- inside the drop: albedo(w = 1) x view factor(w = 1, view along the normal);
- dry ground: albedo(0) x view factor(0);
- Spot between 0.24 and the next knot above it: the map's stated law, the
  knots' albedo x factor below Spot and the water's at Spot, lerped in the
  wet-map value (0.24 then lies on the stretch blending into the water);
- gloss: a white sky (radiance 1) minus a black one gives inside the drop the
  film's reflection at w = 1 times Fresnel at normal incidence,
  ((n - 1)/(n + 1))^2 with the liquid's n, and 0 on the dry ground.
Tolerance per value: exr 1e-3 relative (half-float output; for the gloss,
of the two renders' sum) + tables 1e-5 (the two writers' printed digits). Control: Soak_Wet_Material_Fn (the map
read as pore water, the former way) renders the drop more than 10 x the
tolerance away from the water's colour, so the check can fail.

usage: drops_spots.py SOAK ROOT TMPDIR"""
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import export_json, fail, povray, read_image, setup_args  # noqa: E402

N = 16                       # texels and pixels
DROP = (5, 5, 6)             # x0, y0, size in texels
W_DROP = 0.24
EXR_REL, TABLES = 1e-3, 1e-5

SCENE = """#version 3.7;
global_settings {{ assumed_gamma 1.0 ambient_light 1 }}
#declare Soak_Ambient = 1;
#declare Soak_Highlights = 0;
#include "soak.inc"
camera {{ orthographic location <0.5, 0.5, 5> look_at <0.5, 0.5, 0> right -x up y sky y }}
background {{ rgb {sky} }}
#declare Wet = Soak_Drops_Fn("d.", ".exr", 1, 0, 0, 0, 0)
plane {{ z, 0 {material} }}
"""


def knots(exp, preset, liquid="water"):
    m = next(m for m in exp["materials"] if m["name"] == preset)
    return m["liquids"][liquid]["knots"]


def seen(exp, preset, w):
    """albedo x view factor along the normal, lerped over the knots in wetness (texture_map)."""
    k = knots(exp, preset)
    j = exp["view_cos"].index(1.0)
    rows = np.array([np.array(a) * np.array(v[j]) for a, v in zip(k["albedo"], k["view_factor"])])
    return np.array([np.interp(w, k["wetness"], rows[:, c]) for c in range(3)])


def drops_law(exp, preset, w, spot):
    """Soak_Wet_Drops_Material's map as its comment states it: the knots below Spot,
    then the last knot (wetness 1) at Spot, lerped at w."""
    k = knots(exp, preset)
    xs = [x for x in k["wetness"][:-1] if x < spot] + [spot]
    rows = np.array([seen(exp, preset, x) for x in xs[:-1]] + [seen(exp, preset, 1.0)])
    return np.array([np.interp(w, xs, rows[:, c]) for c in range(3)])


def render(tmp, lib, name, material, sky):
    pov = os.path.join(tmp, name + ".pov")
    with open(pov, "w") as f:
        f.write(SCENE.format(sky=sky, material=material))
    out = os.path.join(tmp, name + ".exr")
    rc, log = povray(pov, out, N, N, lib, cwd=tmp)
    if rc != 0:
        fail(f"{name}: povray exit {rc}\n{log[-1500:]}")
    return read_image(out)


def masks():
    """Image rows run top down (y = 1 first); inside: the drop's texels away from its
    bilinear edge; dry: two texels or more from the drop."""
    x0, y0, s = DROP
    col = np.arange(N)[None, :]
    row = (N - 1 - np.arange(N))[:, None]          # texel row of each image row
    inside = (col >= x0 + 1) & (col < x0 + s - 1) & (row >= y0 + 1) & (row < y0 + s - 1)
    near = (col >= x0 - 2) & (col < x0 + s + 2) & (row >= y0 - 2) & (row < y0 + s + 2)
    return inside, ~near


def check(what, got, ref, bad, magnitude=None):
    """magnitude: the size of the rendered values a difference was taken of (each half-float rounded)."""
    tol = EXR_REL * (np.abs(ref) if magnitude is None else magnitude) + TABLES
    err = np.abs(got - ref).max(axis=0)
    ok = bool(np.all(err <= tol))
    print(f"{'ok  ' if ok else 'FAIL'} {what}: worst pixel {got[np.abs(got - ref).sum(1).argmax()]} vs {ref}"
          f" (max error {err.max():.2e}, tol {tol.max():.2e})")
    return bad + (not ok)


def main():
    soak, _root, tmp, lib = setup_args(__doc__)
    exp = export_json(soak, tmp)
    x0, y0, s = DROP
    # the texel rows of an EXR run top down: texel row y (from the bottom) is image row N-1-y
    r = subprocess.run(["oiiotool", "--create", f"{N}x{N}", "3", "--fill:color={0},{0},{0}".format(W_DROP),
                        f"{s}x{s}+{x0}+{N - y0 - s}", "-d", "half", "-o", os.path.join(tmp, "d.0000.exr")],
                       capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"oiiotool --create: {r.stderr}")
    inside, dry = masks()
    n_ior = next(lq for lq in exp["liquids"] if lq["name"] == "water")["ior"]
    fresnel0 = ((n_ior - 1) / (n_ior + 1)) ** 2
    bad = 0
    for preset in ("brick", "concrete"):
        k = knots(exp, preset)
        wet, dry_ref = seen(exp, preset, 1.0), seen(exp, preset, 0.0)
        mat = f'Soak_Wet_Drops_Material("{preset}", "water", Wet, {{spot}})'
        black = render(tmp, lib, f"{preset}_black", mat.format(spot=0.1), 0)
        bad = check(f"{preset}: drop = the wet entry, albedo(1) x factor(1)", black[inside], wet, bad)
        bad = check(f"{preset}: dry ground = albedo(0) x factor(0)", black[dry], dry_ref, bad)
        spot = 0.5 * (W_DROP + min(x for x in k["wetness"] if x > W_DROP))
        below = max(x for x in k["wetness"] if x < W_DROP)
        edge = render(tmp, lib, f"{preset}_edge", mat.format(spot=spot), 0)
        share = (W_DROP - below) / (spot - below)
        bad = check(f"{preset}: Spot = {spot:.4f}: {share:.3f} water over the knot at {below}",
                    edge[inside], drops_law(exp, preset, W_DROP, spot), bad)
        if not np.all(np.abs(drops_law(exp, preset, W_DROP, spot) - wet) > 0.01 * wet):
            fail(f"{preset}: the edge case does not differ from the water: nothing checked")
        white = render(tmp, lib, f"{preset}_white", mat.format(spot=0.1), 1)
        if k["wetness"][-1] != 1 or k["film_coverage"][-1] != 1:
            fail(f"{preset}: the last knot is not a full film "
                 f"(wetness {k['wetness'][-1]}, cover {k['film_coverage'][-1]})")
        film_r = 1.0 * fresnel0   # film reflection c + (1 - c) a = 1 at full cover
        bad = check(f"{preset}: drop's gloss = film reflection x F(0) = {film_r:.5f}",
                    (white - black)[inside], np.full(3, film_r), bad,
                    magnitude=(white + black)[inside].max(0))
        bad = check(f"{preset}: dry ground has no gloss", (white - black)[dry], np.zeros(3), bad,
                    magnitude=(white + black)[dry].max(0))
        ctrl = render(tmp, lib, f"{preset}_ctrl", f'Soak_Wet_Material_Fn("{preset}", "water", Wet)', 0)
        off = np.abs(ctrl[inside] - wet).max()
        ok = off > 10 * (EXR_REL * wet.max() + TABLES)
        print(f"{'ok  ' if ok else 'FAIL'} control: Soak_Wet_Material_Fn's drop is {off:.4f} from the water's colour"
              f" (the check above can fail)")
        bad += not ok
    if bad:
        fail(f"{bad} checks failed")
    print("PASS")


if __name__ == "__main__":
    main()
