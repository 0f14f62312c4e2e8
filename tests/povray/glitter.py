"""No glitter: a rough wet ground under a low sun looks the same at two antialias
settings. Sparkles (a highlight narrower than the surface's bumps, hit by one
pixel-centre ray in a hundred) make the image mean and its pixel variance depend
on how many rays a pixel takes; a highlight as wide as the wet surface's GGX
alpha (soak.inc's one `specular albedo` lobe) does not.

Scene: concrete + water at wetness 0.25 and 0.6 (Soak_Wet_Material_Bumped with
sub-pixel bumps), the sun 10 degrees above the horizon in front of the camera so
that its reflection lies in the picture, black sky, 64 x 64. Rendered once with
one ray per pixel (-A) and once with 9 rays per pixel (+AM1 +A0 +R3, no jitter).
Glitter-free means:
  - the means agree within 4 standard errors of the per-pixel difference
    (independent pixels: SE = std(diff) / sqrt(N)) plus 1 % (the half-float EXR
    and the supersampling's own bias on the bumps' geometry);
  - std(1 ray) / std(9 rays) <= 1.5: sub-pixel sparkles, independent between the
    9 rays, would give up to sqrt(9) = 3; the smooth image's own variation gives 1.
A control with the old sun glint (phong_size 1000, same albedo) must fail the
second criterion (shows that the test can see glitter).

usage: glitter.py SOAK ROOT TMPDIR"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import fail, povray, read_image, setup_args  # noqa: E402

RES = 64
BUMPS = "normal { bumps 0.4 scale 0.03 }"


def scene(material):
    el = np.radians(10.0)
    return f"""#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
#include "soak.inc"
camera {{ location <0, -1, 0.6> look_at <0, 2, 0> sky z up z right -x angle 40 }}
light_source {{ <0, {np.cos(el)}, {np.sin(el)}>*1e5 rgb 1 parallel point_at 0 }}
background {{ rgb 0 }}
plane {{ z, 0 {material} }}
"""


def luminance(img):
    return img @ np.array([0.2126, 0.7152, 0.0722])


def main():
    soak, root, tmp, lib = setup_args(__doc__)
    cases = [(f"wet{w}", f'#declare W = function {{ {w} }}\n'
              f'Soak_Wet_Material_Bumped("concrete", "water", W, {BUMPS})', True) for w in (0.25, 0.6)]
    # control: the pinpoint glint soak.inc used before (phong_size 1000), albedo of water's R F0
    cases.append(("phong_dot", f"#declare Soak_Phong = 0.0204;\ntexture {{ pigment {{ rgb 0.3 }} finish {{ diffuse 1 "
                               f"phong albedo Soak_Phong * Soak_Highlights phong_size 1000 }} {BUMPS} }}", False))
    bad = 0
    for tag, mat, expect_clean in cases:
        decl, _, obj = mat.rpartition("\n")  # declarations go before the plane
        imgs = {}
        for hl in (0, 1):
            pov = os.path.join(tmp, f"{tag}_h{hl}.pov")
            with open(pov, "w") as f:
                f.write(scene(obj).replace("plane {", decl + "\nplane {")
                        .replace('#include "soak.inc"', f"#declare Soak_Highlights = {hl};\n#include \"soak.inc\""))
            for aa, extra in (("1ray", ["-A"]), ("9ray", ["+AM1", "+A0.0", "+R3", "-J"])):
                out = os.path.join(tmp, f"{tag}_h{hl}_{aa}.exr")
                rc, log = povray(pov, out, RES, RES, lib, extra=extra)
                if rc != 0:
                    fail(f"povray {pov}: exit {rc}\n{log[-1500:]}")
                imgs[hl, aa] = luminance(read_image(out))
        # the highlight alone: highlights on minus off, at each setting
        a = imgs[1, "1ray"] - imgs[0, "1ray"]
        b = imgs[1, "9ray"] - imgs[0, "9ray"]
        diff = a - b
        se = diff.std() / np.sqrt(diff.size)
        mean_tol = 4 * se + 0.01 * b.mean() + 1e-4
        mean_ok = abs(a.mean() - b.mean()) <= mean_tol
        ratio = a.std() / max(b.std(), 1e-12)
        ratio_ok = ratio <= 1.5
        clean = mean_ok and ratio_ok
        print(f"{tag:10} highlight mean 1 ray {a.mean():.5f} 9 rays {b.mean():.5f} (|diff| {abs(a.mean() - b.mean()):.5f},"
              f" tol {mean_tol:.5f}); std 1 ray {a.std():.5f} 9 rays {b.std():.5f}, ratio {ratio:.2f} (<= 1.5); "
              f"brightest pixel 1 ray {a.max():.3f}: {'glitter-free' if clean else 'GLITTER'}")
        if clean != expect_clean:
            bad += 1
            print(f"FAIL {tag}: expected {'no glitter' if expect_clean else 'glitter (control)'}")
    if bad:
        fail(f"{bad} glitter checks failed")
    print("PASS")


if __name__ == "__main__":
    main()
