"""POV-Ray's own sample scenes (Debian's povray-examples), wetted by the three
steps of povray/README.md "Wet your own scene" and otherwise unchanged:
  1. dry = original: each scene with Soak's layer at wetness 0 (Soak_Wet_Layer)
     and with a varying wetness that is 0 everywhere (Soak_Wet_Existing_Fn)
     renders like the untouched scene within 1 % per channel (max over pixels,
     relative to the pixel, floor 0.01 absolute for near-black pixels);
  2. wet darker by the core's ratio: with the film's reflection and glint off
     (Soak_Film = 0, a setting for checks) the wet object over the dry one,
     the median over the object's pixels per channel, lies in the band of the
     core's ratio from the JSON export (`soak export --target json`: the
     base_colour table, bilinear, at the dry albedo given, times the preset's
     view factor at w over the one at 0, for view angles 0..80 deg), widened by
     2 % (half-float output, POV-Ray's aoi map lerped in angle);
  3. wet with film: darker than dry on the object's median, and not black.
  4. woods.inc's layered textures through Soak_Wet_Existing_Fn: wetness 0 = the
     texture (also as texture_map entries, in material { } and on a CSG union);
     Soak_Place_Fn lays a map on the y-up ground (its y along the scene's z).
Prints each scene's parse and trace CPU time (POV-Ray's statistics), original
against wet, for the README's table; the timings are not asserted.
Exits 77 (SKIPPED) when povray-examples is not installed.

usage: existing_scenes.py SOAK ROOT TMPDIR [--images DIR]"""
import os
import re
import shutil
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import export_json, fail, povray, read_image, setup_args  # noqa: E402

EXAMPLES = "/usr/share/doc/povray/examples"

# (name, scene file, where to add the layer (regex; the layer goes right after the match),
#  preset, dry albedo (the texture's pigment x its diffuse), wetness, gamma, what the ratio check
#  removes from both renders: the scene's own mirror reflection (POV-Ray does not filter a lower
#  layer's reflection: it stays as it was), fog (light the surface does not shade) and radiosity
#  (the wet floor's darker bounce changes the walls: the band holds for the floor's own pixels))
SCENES = [
    ("woodbox", "advanced/woodbox.pov",
     r"(translate z\*4\s*\n\s*\})", "oak", (0.30, 0.16, 0.07), 0.7, 1.2,
     [("reflection 0.25", "")]),
    ("patio", "radiosity/patio-radio_37.pov",
     r"(plane \{y,0 pigment \{color rgb <0\.776,0\.706,0\.706>\})", "concrete", (0.466, 0.424, 0.424), 0.8, 1.0,
     [("\nfog {", "\n#declare Soak_Test_No_Fog = fog {"), ("#declare Rad_Quality = 1;", "#declare Rad_Quality = 0;"), ("#declare Rad_Quality = 2;", "#declare Rad_Quality = 0;")]),
    ("brickwall", "advanced/wallstucco.pov",
     r"(object \{HF_Wall  translate <0,0,-0.8>)", "brick", (0.30, 0.18, 0.15), 0.8, 1.0,
     []),
]
STATS = re.compile(r"(Parse|Trace) Time:.*?with ([0-9.]+) CPU-seconds", re.S)


def skip(reason):
    print(f"SKIPPED: {reason}")
    sys.exit(77)


def stats(log):
    t = {k: float(v) for k, v in STATS.findall(log)}
    return t.get("Parse", float("nan")), t.get("Trace", float("nan"))


def scene_text(src, where, layer, gamma, fast):
    text = open(src).read()
    if fast:
        text = text.replace("#declare Rad_Quality = 2;", "#declare Rad_Quality = 1;")
    head = f'#include "soak.inc"\nSoak_Check_Gamma({gamma})\n'
    text, n = re.subn(where, lambda m: m.group(1) + "\n " + layer + "\n", text, count=1)
    if n != 1:
        fail(f"{src}: the object to wet ({where}) is not in the scene any more")
    # step 1 of the README: include soak.inc after the scene's #version line
    m = re.search(r"#version[^;]*;\n", text)
    pos = m.end() if m else 0
    return text[:pos] + head + text[pos:]


def render(tmp, tag, text, lib, w, h, extra=()):
    pov = os.path.join(tmp, f"{tag}.pov")
    with open(pov, "w") as f:
        f.write(text)
    out = os.path.join(tmp, f"{tag}.exr")
    rc, log = povray(pov, out, w, h, lib, extra=extra, cwd=tmp)
    if rc != 0:
        fail(f"{tag}: povray exit {rc}\n{log[-2000:]}")
    return read_image(out), stats(log), log


def core_band(exp, preset, w, dry):
    """min, max per channel over view angles 0..80 deg of the core's wet/dry ratio."""
    m = next(m for m in exp["materials"] if m["name"] == preset)
    liq = m["liquids"]["water"]
    t = liq["base_colour"]
    a, ws, tab = np.array(t["dry_albedo"]), np.array(t["wetness"]), np.array(t["albedo"])
    k = np.array([np.interp(w, ws, [np.interp(dry[c], a, tab[c][i]) for i in range(len(ws))]) / dry[c]
                  for c in range(3)])
    kn = liq["knots"]
    vf = np.array(kn["view_factor"])  # [knot][view][channel]
    out = []
    for j, cosv in enumerate(exp["view_cos"]):
        if cosv < np.cos(np.radians(80)):
            continue
        vw = np.array([np.interp(w, kn["wetness"], vf[:, j, c]) for c in range(3)])
        out.append(k * vw / vf[0, j])
    out = np.array(out)
    return out.min(0), out.max(0)


FN_SCENE = """#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "woods.inc"
#include "soak.inc"
camera { location <0, 2, -3> look_at 0 }
light_source { <3, 5, -2> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 1>] [1 rgb <0.1, 0.2, 0.6>] } } }
sphere { <0, 0.5, 1>, 0.5 pigment { rgb <1, 0, 0> } }
"""


def fn_check(tmp, lib):
    """Soak_Wet_Existing_Fn on woods.inc's layered T_Wood10 (y-up ground, Soak_Place_Fn): a
    wetness 0 everywhere renders as the texture itself within 1 %; a wet half (x > 0) is
    darker than the dry half's counterpart and the dry half unchanged."""
    d = os.path.join(tmp, "woods_fn")
    os.makedirs(d, exist_ok=True)
    orig, _, _ = render(d, "original", FN_SCENE + "plane { y, 0 texture { T_Wood10 } }\n", lib, 64, 48)
    zero, _, _ = render(d, "zero", FN_SCENE + 'plane { y, 0 Soak_Wet_Existing_Fn(T_Wood10, "oak", "water", '
                        'function { 0 }, <0.3, 0.2, 0.1>) }\n', lib, 64, 48)
    half, _, _ = render(d, "half", FN_SCENE + '#declare W = Soak_Place_Fn(function { x > 0.5 }, 4, '
                        'transform { translate <-2, 0, -2> })\n'
                        'plane { y, 0 Soak_Wet_Existing_Fn(T_Wood10, "oak", "water", W, <0.3, 0.2, 0.1>) }\n',
                        lib, 64, 48)
    # the map's y runs along the scene's z (y-up): the far ground (z > 0, upper rows) wet, the near one dry
    far, _, _ = render(d, "far", FN_SCENE + '#declare W = Soak_Place_Fn(function { y > 0.5 }, 4, '
                       'transform { translate <-2, 0, -2> })\n'
                       'plane { y, 0 Soak_Wet_Existing_Fn(T_Wood10, "oak", "water", W, <0.3, 0.2, 0.1>) }\n',
                       lib, 64, 48)
    # every syntax at wetness 0 renders as the original: a checker of two wetted woods (a patterned
    # texture: wet each entry), material { } with an interior, a CSG union with a layer after its texture
    syn_o = ('plane { y, 0 texture { checker texture { T_Wood10 } texture { T_Wood1 } scale 0.5 } }\n'
             'sphere { <-1, 0.4, 0>, 0.4 material { texture { T_Wood3 } interior { ior 1.5 } } }\n'
             'union { box { <0.6, 0, -0.5>, <1.2, 0.6, 0.1> } sphere { <0.9, 0.6, -0.2>, 0.3 } texture { T_Wood7 } }\n')
    syn_w = ('#declare Z = function { 0 }\n#declare D = <0.3, 0.2, 0.1>;\n'
             'plane { y, 0 texture { checker Soak_Wet_Existing_Fn(T_Wood10, "oak", "water", Z, D) '
             'Soak_Wet_Existing_Fn(T_Wood1, "oak", "water", Z, D) scale 0.5 } }\n'
             'sphere { <-1, 0.4, 0>, 0.4 material { Soak_Wet_Existing_Fn(T_Wood3, "oak", "water", Z, D) interior { ior 1.5 } } }\n'
             'union { box { <0.6, 0, -0.5>, <1.2, 0.6, 0.1> } sphere { <0.9, 0.6, -0.2>, 0.3 } texture { T_Wood7 } '
             'Soak_Wet_Layer("oak", "water", 0, D) }\n')
    so, _, _ = render(d, "syntax_original", FN_SCENE + syn_o, lib, 64, 48)
    sw, _, _ = render(d, "syntax_dry", FN_SCENE + syn_w, lib, 64, 48)
    bad = 0
    err = (np.abs(sw - so) / np.maximum(np.abs(so), 0.01)).max()
    ok = err <= 0.01
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} texture_map entries, material {{ }}, CSG at wetness 0: max relative error {err:.2e}")
    near_d = (np.abs(far[40:, :] - orig[40:, :]) / np.maximum(orig[40:, :], 0.01)).max()
    far_r = far[4:16, :12].mean() / orig[4:16, :12].mean()
    ok = near_d <= 0.01 and far_r < 0.9
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} Soak_Place_Fn y-up: map y along scene z: near ground unchanged "
          f"(max {near_d:.2e}), far ground {far_r:.3f} of dry")
    err = (np.abs(zero - orig) / np.maximum(np.abs(orig), 0.01)).max()
    ok = err <= 0.01
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} woods.inc T_Wood10 Soak_Wet_Existing_Fn at wetness 0: max relative error {err:.2e}")
    # bottom rows: the ground in front; left half (x < 0, scene x maps to map x - 0.5) dry, right half wet
    rows = slice(36, 48)
    dl = (np.abs(half[rows, :24] - orig[rows, :24]) / np.maximum(orig[rows, :24], 0.01)).max()
    rr = half[rows, 40:].mean() / orig[rows, 40:].mean()
    ok = dl <= 0.01 and rr < 0.9
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} Soak_Place_Fn y-up: dry half unchanged (max {dl:.2e}), wet half {rr:.3f} of dry")
    return bad


def main():
    soak, root, tmp, lib = setup_args(__doc__)
    images = sys.argv[sys.argv.index("--images") + 1] if "--images" in sys.argv else None
    if not os.path.isdir(EXAMPLES):
        skip(f"{EXAMPLES} missing: install Debian's povray-examples (scripts/install-deps.sh test tier)")
    exp = export_json(soak, tmp)
    size = (320, 240) if images else (96, 72)
    bad = 0
    for name, rel, where, preset, dry, w, gamma, strip in SCENES:
        src = os.path.join(EXAMPLES, rel)
        if not os.path.isfile(src):
            skip(f"{src} missing (povray-examples incomplete)")
        d = os.path.join(tmp, name)
        os.makedirs(d, exist_ok=True)
        orig_text = open(src).read()
        if not images:  # the checks compare like with like: the courtyard's fast radiosity settings
            orig_text = orig_text.replace("#declare Rad_Quality = 2;", "#declare Rad_Quality = 1;")
        dryc = f"<{dry[0]}, {dry[1]}, {dry[2]}>"
        orig, t_orig, _ = render(d, "original", orig_text, lib, *size)
        orig_full = orig
        cases = {
            "dry_layer": f'Soak_Wet_Layer("{preset}", "water", 0, {dryc})',
            "wet_nofilm": f'Soak_Wet_Layer("{preset}", "water", {w}, {dryc})',
            "wet": f'Soak_Wet_Layer("{preset}", "water", {w}, {dryc})',
        }
        res = {}
        for tag, layer in cases.items():
            text = scene_text(src, where, layer, gamma, not images)
            if tag == "wet_nofilm":
                text = "#declare Soak_Film = 0;\n" + text
                for a, b in strip:
                    text = text.replace(a, b)
            res[tag] = render(d, tag, text, lib, *size)
        # the gamma warning: printed for woodbox's assumed_gamma 1.2, not for the others' 1.0
        warned = "Soak_Check_Gamma: assumed_gamma" in re.sub(r"\s+", " ", res["dry_layer"][2])
        ok = warned == (gamma != 1.0)
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {name}: assumed_gamma {gamma}: Soak_Check_Gamma warned {warned}")
        # dry = original
        for tag in ("dry_layer",):
            img = res[tag][0]
            err = np.abs(img - orig) / np.maximum(np.abs(orig), 0.01)
            ok = err.max() <= 0.01
            bad += not ok
            print(f"{'ok  ' if ok else 'FAIL'} {name} {tag}: max relative error {err.max():.2e} (<= 1 %)")
        # wet darker by the core's ratio, on the pixels the layer changes
        if strip:
            for a, b in strip:
                orig_text = orig_text.replace(a, b)
            orig, _, _ = render(d, "original_stripped", orig_text, lib, *size)
        wimg = res["wet_nofilm"][0]
        mask = np.abs(wimg - orig).max(2) > 1e-3
        if mask.sum() < 20:
            bad += 1
            print(f"FAIL {name}: the wet layer changed only {mask.sum()} pixels")
            continue
        ratio = np.median(wimg[mask] / np.maximum(orig[mask], 1e-4), axis=0)
        lo, hi = core_band(exp, preset, w, dry)
        ok = np.all(ratio >= lo * 0.98) and np.all(ratio <= hi * 1.02)
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {name} wet/dry ratio {np.round(ratio, 4)} in core band "
              f"[{np.round(lo, 4)}, {np.round(hi, 4)}] (w={w}, {preset}, dry {dry}, {mask.sum()} px)")
        fimg = res["wet"][0]
        fr = np.median(fimg[mask].mean(1) / np.maximum(orig_full[mask].mean(1), 1e-4))
        ok = 0.05 < fr < 1
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {name} wet with film: median luminance ratio {fr:.3f} (darker, not black)")
        print(f"time {name}: parse CPU original {t_orig[0]:.3f} s wet {res['wet'][1][0]:.3f} s; "
              f"trace CPU original {t_orig[1]:.3f} s wet {res['wet'][1][1]:.3f} s "
              f"({res['wet'][1][1] / max(t_orig[1], 1e-3):.2f}x)")
        if images:
            for tag in ("original", "wet"):
                shutil.copy(os.path.join(d, f"{tag}.exr"), os.path.join(images, f"{name}_{tag}.exr"))
    bad += fn_check(tmp, lib)
    if bad:
        fail(f"{bad} checks failed")
    print("PASS")


if __name__ == "__main__":
    main()
