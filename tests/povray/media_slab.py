"""POV-Ray media of povray/soak.inc against closed forms and against soak render.

1. Soak_Media_Raw slabs (index matched, unit thickness d = 1 mm, viewed along
   the normal, a sun of irradiance E = pi at 30 degrees from the normal behind
   or in front) against single scattering in closed form, which is all that
   POV-Ray's media compute:
       behind:   L = E p(mu)  sigma_s int_0^d exp(-sigma_t ((d - z)/mu + z)) dz
       in front: L = E p(-mu) sigma_s int_0^d exp(-sigma_t (z/mu + z)) dz
   (z the depth below the viewer's face, mu = cos 30 deg, p the two-term
   Henyey-Greenstein phase w HG(g1) + (1 - w) HG(g2), HG(g, c) =
   (1 - g^2) / (4 pi (1 + g^2 - 2 g c)^1.5)). Budget: the lobe split (w realised
   as k/N, N <= Soak_Media_Lobes_Max: |k/N - w| |p1 - p2| / p, computed here
   independently) + POV-Ray's quadrature bias + 0.002 (half-float EXR, 0.1 %,
   and the closed form's trapezoid rule). The bias: POV-Ray's method 3 with N
   samples over one interval overestimates the in-scattering integral by about
   0.7 dtau / N, dtau the change of the integrand's optical exponent across
   the slab, sigma_t d (1/mu - 1) behind and sigma_t d (1/mu + 1) in front
   (measured on a dtau = 1.08 slab: +2.55 % at N = 30, +1.13 % at 60, +0.38 %
   at 120); budget 1.25 dtau / N.
2. A sheet of the cotton preset's medium thin enough for single scattering
   (0.5 um: scattering optical depth 0.033) lit from behind, dry, at the pores'
   saturation and wet: Soak_Sheet_Material against soak render of the same
   medium (sigma_s, sigma_a, g1, g2, w of `soak export --target json`, ior 1).
   POV-Ray misses the multiple scattering that soak render traces; its share is
   at most the chance that a once-scattered photon collides again,
   omega (1 - (1/2 - E3(tau)) / tau) for a slab of optical depth tau (uniform
   isotropic source; E3 the exponential integral), which bounds the shortfall
   (a one-sided budget, + 4 standard errors of the reference, + 0.01 table and
   lobe split). Wet brighter than dry from behind in both ([JLD99] sec. 4.1:
   water makes the scattering more forward).
3. A 20 um sheet of cotton soaked with coffee (whose absorption changes the
   medium with wetness) with the wetness from a `soak bake volume --format df3`
   wetness volume through Soak_Df3_Fn and Soak_Sheet_Material_Fn equals the
   constant-wetness macro within 0.5 % (16-bit df3 + the bake's wetting profile,
   here 1 - 3 (d/D)^2 >= 0.9987), and differs from the dry sheet by more than
   ten times that: the wetness volume is read, placed and mapped through the
   tables' knots (w = 0.3 lies between knots: the colour map's linear
   interpolation against the constant macro's).

usage: media_slab.py SOAK ROOT TMPDIR"""
import json
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import export_json, fail, povray, read_image, setup_args  # noqa: E402

MU = math.cos(math.pi / 6)
E = math.pi  # sun irradiance: POV-Ray light colour E / pi = 1
RES = 8
LOBES_MAX = 20
SAMPLES = 30  # Soak_Media_Samples default
SHEET_UM = 0.5  # sheet thickness, um (scene unit of part 2 and 3)


def hg(g, c):
    return (1 - g * g) / (4 * math.pi * (1 + g * g - 2 * g * c) ** 1.5)


def split(w):
    """k/N closest to w with 2 <= N <= LOBES_MAX (what soak.inc must realise)."""
    best = min(((abs(round(w * n) / n - w), n) for n in range(2, LOBES_MAX + 1)))
    return round(w * best[1]) / best[1]


def single_scattering(ss, sa, g1, g2, w, d, behind):
    st = ss + sa
    c = MU if behind else -MU
    p = w * hg(g1, c) + (1 - w) * hg(g2, c)
    zs = np.linspace(0, d, 20001)
    path = (d - zs) / MU + zs if behind else zs / MU + zs
    return E * p * ss * np.trapz(np.exp(-st * path), zs), p


def E3(x):
    u = np.linspace(0, 1, 200001)[1:]
    return float(np.trapz(u * np.exp(-x / u), u))


def recollide(tau, omega):
    return omega * (1 - (0.5 - E3(tau)) / tau)


HEAD = """#version 3.7;
global_settings {{ assumed_gamma 1.0 max_trace_level 8 }}
#declare Soak_Mm_Per_Unit = {mmu};
#include "soak.inc"
camera {{ orthographic location <0,0,5> look_at <0,0,0> sky <0,1,0> right -x*{view} up y*{view} }}
light_source {{ <{lx},0,{lz}>*1e5 rgb 1 parallel point_at <0,0,0> }}
background {{ rgb 0 }}
"""


def pov_mean(tmp, lib, name, text):
    pov = os.path.join(tmp, name + ".pov")
    out = os.path.join(tmp, name + ".exr")
    with open(pov, "w") as f:
        f.write(text)
    rc, log = povray(pov, out, RES, RES, lib, cwd=tmp)
    if rc != 0:
        fail(f"povray {pov}: exit {rc}\n{log[-2000:]}")
    return read_image(out).reshape(-1, 3).mean(0)


def raw_slabs(tmp, lib):
    cases = [  # sigma_s (rgb, 1/mm), sigma_a, g1, g2, w, behind
        ([0.01] * 3, [0.09] * 3, 0.0, 0.0, 1.0, True),
        ([0.05, 0.1, 0.2], [0.05, 0.02, 0.01], 0.8, -0.3, 0.7, True),
        ([0.05, 0.1, 0.2], [0.05, 0.02, 0.01], 0.8, -0.3, 0.7, False),
        ([0.2] * 3, [0.3] * 3, 0.5, -0.2, 0.33, True),
        ([0.2] * 3, [0.3] * 3, 0.5, -0.2, 0.33, False),
        ([0.3] * 3, [0.0] * 3, 0.9, 0.0, 0.5, True),
    ]
    worst = 0.0
    for i, (ss, sa, g1, g2, w, behind) in enumerate(cases):
        lz = -MU if behind else MU
        text = HEAD.format(mmu=1, view=0.2, lx=0.5, lz=lz)
        text += (f"box {{ <-50,-50,-1>, <50,50,0> hollow Soak_Clear_Texture() interior {{ ior 1 "
                 f"Soak_Media_Raw(<{ss[0]},{ss[1]},{ss[2]}>, <{sa[0]},{sa[1]},{sa[2]}>, {g1}, {g2}, {w}) }} }}\n")
        got = pov_mean(tmp, lib, f"raw{i}", text)
        for ch in range(3):
            ref, p = single_scattering(ss[ch], sa[ch], g1, g2, w, 1.0, behind)
            c = MU if behind else -MU
            lobe = abs(split(w) - w) * abs(hg(g1, c) - hg(g2, c)) / p
            c_path = (1 / MU - 1) if behind else (1 / MU + 1)
            quad = 1.25 * (ss[ch] + sa[ch]) * c_path / SAMPLES
            budget = lobe + quad + 0.002
            rel = got[ch] / ref - 1
            worst = max(worst, abs(rel))
            ok = abs(rel) <= budget
            print(f"raw {i} {'behind' if behind else 'front '} ch {ch}: povray {got[ch]:.6f} single scattering "
                  f"{ref:.6f} rel {rel:+.4f} budget {budget:.4f} {'ok' if ok else 'FAIL'}")
            if not ok:
                fail(f"Soak_Media_Raw case {i} channel {ch}: {got[ch]} vs closed form {ref}")
    print(f"raw slabs: worst relative difference {worst:.4f}")


def soak_sheet(soak, tmp, name, m, i, spp):
    k = m["liquids"]["water"]["knots"]
    per_um = 1e-6  # sigma per m -> per um
    base = {"type": "medium", "sigma_s": [v * per_um for v in k["sigma_s_per_m"][i]],
            "sigma_a": [v * per_um for v in k["sigma_a_per_m"][i]], "g1": k["phase_g1"][i], "g2": k["phase_g2"][i],
            "w": k["phase_w"][i], "ior": 1.0}
    scene = {"render": {"width": RES, "height": RES, "spp": spp, "max_depth": 1000},
             "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 0.5},
             "lights": [{"type": "sun", "direction": [0.5, 0, -MU], "irradiance": E}],
             "materials": {"m": {"type": "wet", "film": {"coverage": 0}, "base": base}},
             "objects": [{"type": "box", "min": [-50, -50, -SHEET_UM], "max": [50, 50, 0], "material": "m"}]}
    js = os.path.join(tmp, name + ".json")
    out = os.path.join(tmp, name + ".exr")
    with open(js, "w") as f:
        json.dump(scene, f)
    r = subprocess.run([soak, "render", js, "-o", out, "--threads", "2", "--seed", "3"], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"soak render {js}: exit {r.returncode}\n{r.stderr}")
    px = read_image(out).reshape(-1, 3)
    return px.mean(0), px.std(0) / math.sqrt(len(px)), base


DF3_UM = 20.0


def bake_wetness(soak, tmp, w):
    prefix = os.path.join(tmp, f"vol{int(w * 1000)}")
    r = subprocess.run([soak, "bake", "volume", "--material", "cotton", "--liquid", "coffee", "--wetness", str(w),
                        "--unit", "mm", "--size", f"0.1,0.1,{DF3_UM / 1000}", "--depth", "1", "--dims", "4,4,2",
                        "--format", "df3", "--threads", "1", "-o", prefix], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"soak bake volume: exit {r.returncode}\n{r.stderr}")
    ident = os.path.basename(prefix)
    return prefix, ident


def df3_sheets(soak, tmp, lib):
    def sheet(w, body):
        text = HEAD.format(mmu=0.001, view=2, lx=0.5, lz=-MU) + body
        return pov_mean(tmp, lib, f"df3_{body.count('Fn')}_{int(w * 1000)}", text)

    def constant(w):
        return sheet(w, f'box {{ <-50,-50,-{DF3_UM}>, <50,50,0> hollow Soak_Sheet_Material("cotton", "coffee", {w}) }}\n')

    dry = constant(0.0)
    for w in (0.3, 1.0):
        prefix, ident = bake_wetness(soak, tmp, w)
        got_fn = sheet(w, f'#include "{os.path.basename(prefix)}.inc"\n'
                          f"#declare Wet = Soak_Df3_Fn({ident}_wetness_file, {ident}_dims, {ident}_wetness_scale)\n"
                          f'box {{ 0, 1 hollow Soak_Sheet_Material_Fn("cotton", "coffee", Wet, {w}) '
                          f"scale <100,100,{DF3_UM}> translate <-50,-50,-{DF3_UM}> }}\n")
        got = constant(w)
        for ch in range(3):
            rel = got_fn[ch] / got[ch] - 1
            change = abs(got[ch] / dry[ch] - 1)
            ok = abs(rel) <= 0.005 and change > 0.05
            print(f"df3 coffee sheet w {w} ch {ch}: wetness volume {got_fn[ch]:.5f} constant {got[ch]:.5f} "
                  f"rel {rel:+.5f} (budget 0.005; dry {dry[ch]:.5f}, change {change:.3f} > 0.05) {'ok' if ok else 'FAIL'}")
            if not ok:
                fail(f"Soak_Sheet_Material_Fn with Soak_Df3_Fn at w {w} channel {ch}")


def sheets(soak, tmp, lib, exp):
    m = next(m for m in exp["materials"] if m["name"] == "cotton")
    knots = m["liquids"]["water"]["knots"]["wetness"]
    levels = [0.0, min(knots, key=lambda k: abs(k - m["saturation_wetness"])), 1.0]
    res = {}
    for w in levels:
        i = knots.index(w)
        ref, se, base = soak_sheet(soak, tmp, f"sheet_soak_{i}", m, i, 4096)
        text = HEAD.format(mmu=0.001, view=2, lx=0.5, lz=-MU)
        text += (f'box {{ <-50,-50,-{SHEET_UM}>, <50,50,0> hollow Soak_Sheet_Material("cotton", "water", {w}) }}\n')
        got = pov_mean(tmp, lib, f"sheet_pov_{i}", text)
        st = [s + a for s, a in zip(base["sigma_s"], base["sigma_a"])]
        for ch in range(3):
            tau = st[ch] * SHEET_UM
            ms = recollide(tau, base["sigma_s"][ch] / st[ch])
            rel = got[ch] / ref[ch] - 1
            noise = 4 * se[ch] / ref[ch]
            ok = -(ms + noise + 0.01) <= rel <= noise + 0.01
            print(f"sheet cotton w {w:.3f} ch {ch}: soak render {ref[ch]:.5f} +- {se[ch]:.5f} povray {got[ch]:.5f} "
                  f"rel {rel:+.4f} budget [-{ms + noise + 0.01:.4f}, +{noise + 0.01:.4f}] (multiple scattering "
                  f"<= {ms:.4f}) {'ok' if ok else 'FAIL'}")
            if not ok:
                fail(f"cotton sheet w {w} channel {ch}: POV-Ray {got[ch]} vs soak render {ref[ch]}")
        res[w] = (float(np.mean(ref)), float(np.mean(got)))
    d, wet = res[0.0], res[1.0]
    print(f"back-lit cotton sheet wet/dry: soak render {wet[0] / d[0]:.3f}, povray {wet[1] / d[1]:.3f}")
    if not (wet[0] > d[0] and wet[1] > d[1]):
        fail("the wet sheet must be brighter than the dry one from behind in both renderers")


def main():
    if len(sys.argv) < 4:
        fail(__doc__)
    soak, root, tmp, lib = setup_args(__doc__)
    raw_slabs(tmp, lib)
    exp = export_json(soak, tmp)
    sheets(soak, tmp, lib, exp)
    df3_sheets(soak, tmp, lib)
    print("PASS")


if __name__ == "__main__":
    main()
