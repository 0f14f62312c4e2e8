"""POV-Ray's subsurface scattering through soak.inc's Soak_Wet_Subsurface_Material,
measured against an independent reference: Jensen et al. 2001's dipole,
evaluated here in POV-Ray 3.7's conventions (read from its source,
backend/render/trace.cpp and backend/lighting/subsurface.cpp, v3.7.0.10):

- pigment x diffuse is the total diffuse reflectance Rd; POV-Ray inverts
  Jensen's closed form Rd(alpha') = alpha'/2 (1 + exp(-4/3 A s)) exp(-s),
  s = sqrt(3 (1 - alpha')), A = (1 + Fdr) / (1 - Fdr), on 101 nodes
  Rd = i/100 and interpolates alpha' linearly between them; its Fdr(eta) is
  its own fit ((1 - 1/eta) + 3 (1 - 1/eta)^4.5) / 4 (not Jensen's), eta the
  object's interior ior (the liquid's, from soak_materials.inc);
- translucency T (mm) is 1 / sigma'_s; sigma'_t = sigma'_s / alpha',
  sigma_a = sigma'_t - sigma'_s, sigma_tr = sqrt(3 sigma_a sigma'_t); scene
  distances are multiplied by mm_per_unit;
- the radiance is, with POV-Ray's convention (a light of colour C gives a
  white diffuse-1 surface the value C, i.e. pi folded in): multiple
  scattering Ft(in) Ft(out) integral Rd(r) E cos dA (the dipole profile
  Rd(r) = alpha'/(4 pi) sum z (sigma_tr d + 1) exp(-sigma_tr d) / d^3 over
  the real and virtual sources z_r = 1/sigma'_t, z_v = z_r (1 + 4A/3)), plus
  single scattering: Jensen's sigma_s F p / sigma_tc exp(-s'_i sigma_t)
  exp(-s'_o sigma_t) with p = 1/4 and s'_o drawn with density
  sigma_t exp(-sigma_t s), whose mean at normal light and view on a
  half-space is alpha' Ft(0)^2 / 24 (the exponential counted twice: Jensen's
  exact single scattering would be alpha' Ft(0)^2 / 8);
- the finish's own diffuse term is dropped, and below +Q9 all of it is
  ignored (the object is plain diffuse: the pigment).

Scenes: a 400 x 400 x 100 mm block (far from edges: the longest diffusion
length 1/sigma_tr here is 3.3 mm), lit straight down by a parallel light of
colour 1, seen from straight above (orthographic), highlights off, black
background. Checks:
(a) lit level, marble dry and wet: Ft(0)^2 (Rd(alpha') + alpha'/24) per
    channel. Rd(alpha') is Rd at POV-Ray's interpolated alpha' (replicated:
    within 2e-4 of the pigment);
(b) wet/dry ratio of (a);
(c) a shadow edge (an occluder with no_image covering half the block):
    radiance at distance d into the shadow Ft(0)^2 integral over the lit
    half-plane of Rd(r) (numerical, 2-D, here), no single scattering; in the
    lit part the same plus alpha'/24 Ft(0)^2. Marble dry at mm_per_unit 1
    (1 unit = 1 mm) and limestone wet with mm_per_unit 0.01 (its diffusion
    length is 0.05 mm: the same geometry in units of 10 um): the light
    bleeds into the shadow over a distance set by the table's translucency;
(d) at +Q8 the same block renders as plain diffuse (lit = pigment, no light
    past the shadow edge); there Soak_Wet_User_Subsurface_Material shows the
    same wet pigment as Soak_Wet_User_Material (an identity: 1e-3);
(e) the diffusion length: for every preset with a medium, liquid and knot,
    POV-Ray's 1/sigma_tr from the table's pigment and Soak_K_Translucency
    (through the conventions above, replicated here) equals the core's
    1/sqrt(3 sigma_a (sigma_a + (1 - g) sigma_s)) from the table's medium
    (g = w g1 + (1 - w) g2) within 1e-4 relative (7-digit numbers), unless
    the translucency sits at a clamp (counted, printed). This is what (c)'s
    rendered profiles then carry into the picture.

Tolerance per compared value: 4 standard errors of the rendered mean (the
BSSRDF is Monte Carlo; the error is estimated from the spread of 8 row
blocks, each an independent set of pixels) + 1e-3 relative (half-float
EXR) + 0.005 relative for the reference's numerical integration (checked
here: the plane integral of the profile reproduces Jensen's closed form to
better than that) + 1e-4 absolute.

usage: subsurface.py SOAK ROOT TMPDIR"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import export_json, fail, povray, read_image, setup_args  # noqa: E402

W_EDGE, H_EDGE = 64, 32  # pixels across / along the edge


def scene(preset, wet, mm_per_unit, half_width, shadow, samples=(400, 40)):
    """A block seen from above; the view spans 2 half_width (units) across x (columns)."""
    s = 1.0 / mm_per_unit  # 1 mm in scene units
    return f"""#version 3.7;
#declare Soak_Highlights = 0;
#declare Soak_Mm_Per_Unit = {mm_per_unit};
#declare Soak_Subsurface_Samples = <{samples[0]}, {samples[1]}>;
#include "soak.inc"
global_settings {{ assumed_gamma 1.0 Soak_Subsurface_Settings() }}
camera {{ orthographic location <0, 0, {50 * s}> look_at <0, 0, 0>
         right -x * {2 * half_width} up y * {2 * half_width * H_EDGE / W_EDGE} }}
background {{ rgb 0 }}
light_source {{ <0, 0, {1e5 * s}> rgb 1 parallel point_at 0 }}
box {{ <-200, -200, -100> * {s}, <200, 200, 0> * {s} Soak_Wet_Subsurface_Material("{preset}", "water", {wet}) }}
#if ({int(shadow)}) box {{ <-300, -300, 10> * {s}, <0, 300, 11> * {s} pigment {{ rgb 0 }} no_image }} #end
"""


def read_inc(root):
    src = open(os.path.join(root, "povray", "soak_materials.inc")).read()

    def arr(name):
        body = re.search(r"#declare " + name + r" = array\[\d+\] \{(.*?)\}", src, re.S).group(1)
        body = re.sub(r"//[^\n]*", "", body)
        if "<" in body:
            return np.array([[float(v) for v in t.split(",")] for t in re.findall(r"<([^>]*)>", body)])
        return np.array([float(v) for v in body.replace("\n", " ").split(",") if v.strip()])

    names = re.findall(r'"(\w+)"', re.search(r"Soak_Preset_Names = array\[\d+\] \{(.*?)\}", src, re.S).group(1))
    return {"names": names, "n_liq": int(re.search(r"Soak_N_Liquids = (\d+)", src).group(1)),
            **{k: arr("Soak_" + k) for k in ("K_Start", "K_Count", "K_W", "K_Pigment", "K_Translucency", "K_Sigma_S", "K_Sigma_A",
                                                 "K_G1", "K_G2", "K_Lobe_W", "Liquid_Ior")}}


def knot(tab, preset, wet):
    """Pigment and translucency of the table at a knot (the test uses wetness knots: no interpolation)."""
    t = tab["names"].index(preset) * tab["n_liq"]  # water = liquid 0
    s, c = int(tab["K_Start"][t]), int(tab["K_Count"][t])
    i = s + int(np.argmin(abs(tab["K_W"][s:s + c] - wet)))
    if abs(tab["K_W"][i] - wet) > 1e-9:
        raise RuntimeError(f"{preset}: {wet} is not a knot")
    return tab["K_Pigment"][i], tab["K_Translucency"][i]


# ---- the reference (Jensen 2001 in POV-Ray's conventions; see the docstring) ----

def fdr(eta):
    return ((1 - 1 / eta) + 3 * (1 - 1 / eta) ** 4.5) / 4


def rd_total(A, ap):
    s = np.sqrt(3 * (1 - ap))
    return ap / 2 * (1 + np.exp(-4 / 3 * A * s)) * np.exp(-s)


def alpha_prime(rd, A):
    """POV-Ray's table: alpha' at Rd = i/100 by bisection, linear in between."""
    nodes = []
    for i in range(101):
        lo, hi = 0.0, 1.0
        for _ in range(80):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if rd_total(A, mid) < i / 100 else (lo, mid)
        nodes.append((lo + hi) / 2)
    return np.interp(rd, np.arange(101) / 100, nodes)


def ft0(eta):
    return 1 - ((eta - 1) / (eta + 1)) ** 2


def profile(r, ap, T, A):
    """Dipole diffuse reflectance Rd(r) (1/mm^2) for alpha', translucency T (mm)."""
    sps = 1 / T
    spt = sps / ap
    sa = spt - sps
    tr = np.sqrt(3 * sa * spt)
    zr = 1 / spt
    zv = zr * (1 + 4 * A / 3)
    out = 0
    for z in (zr, zv):
        d = np.sqrt(z * z + r * r)
        out = out + z * (tr * d + 1) * np.exp(-tr * d) / d ** 3
    return ap / (4 * np.pi) * out, tr


def half_plane(d_mm, ap, T, A):
    """Integral of Rd over the half-plane u <= -d (the lit side) seen from a point d into the shadow
    (d < 0: in the light). Polar integration around the point, per channel."""
    _, tr = profile(0.0, ap, T, A)
    rmax = 40.0 / tr + 200 * T
    # log-spaced radii resolve the 1/r^3 core (z_r ~ T) and the exp tail
    r = np.concatenate([[0.0], np.geomspace(1e-4 * T, rmax, 6000)])
    f, _ = profile(r, ap, T, A)
    out = []
    for d in d_mm:
        # share of the circle of radius r around the point on the lit side x > 0: cos(phi) > d / r
        frac = np.arccos(np.clip(d / np.maximum(r, 1e-30), -1, 1)) / np.pi
        out.append(np.trapz(f * 2 * np.pi * r * frac, r))
    return np.array(out)


def reference(pig, T, eta, d_mm):
    """Expected radiance per channel at signed distances d_mm into the shadow (d < 0: lit)."""
    A = (1 + fdr(eta)) / (1 - fdr(eta))
    ap = alpha_prime(np.clip(pig, 0, 1), A)
    F2 = ft0(eta) ** 2
    res = np.zeros((len(d_mm), 3))
    for ch in range(3):
        ms = half_plane(d_mm, ap[ch], T[ch], A)
        res[:, ch] = F2 * (ms + np.where(np.asarray(d_mm) < 0, ap[ch] / 24, 0.0))
    lit = F2 * (rd_total(A, ap) + ap / 24)
    return res, lit, ap, A


def pov_sigma_tr(pig, T, eta):
    """POV-Ray's sigma_tr (1/mm) for a pigment (Rd) and translucency T (mm)."""
    A = (1 + fdr(eta)) / (1 - fdr(eta))
    ap = alpha_prime(np.clip(pig, 1e-3, 1), A)
    sps = 1 / T
    spt = sps / ap
    return np.sqrt(3 * (spt - sps) * spt)


def diffusion_lengths(tab):
    """(e): worst relative error of POV-Ray's sigma_tr vs the core's over every medium knot; clamped count."""
    worst, clamped, n = 0.0, 0, 0
    for p in range(len(tab["names"])):
        for liq in range(tab["n_liq"]):
            t = p * tab["n_liq"] + liq
            s0, c = int(tab["K_Start"][t]), int(tab["K_Count"][t])
            for i in range(s0, s0 + c):
                ss, sa, T = tab["K_Sigma_S"][i], tab["K_Sigma_A"][i], tab["K_Translucency"][i]
                if not ss.any():
                    continue
                g = tab["K_Lobe_W"][i] * tab["K_G1"][i] + (1 - tab["K_Lobe_W"][i]) * tab["K_G2"][i]
                core = np.sqrt(3 * sa * (sa + (1 - g) * ss))
                free = (T > 1e-3 * 1.0001) & (T < 1e3 * 0.9999) & (core > 0)
                clamped += int((~free).sum())
                n += 3
                if free.any():
                    pov = pov_sigma_tr(tab["K_Pigment"][i][free], T[free], float(tab["Liquid_Ior"][liq]))
                    worst = max(worst, float(np.max(abs(pov / core[free] - 1))))
    return worst, clamped, n


def self_check(pig, T, eta):
    """The reference's numerical plane integral against Jensen's closed form (an identity)."""
    A = (1 + fdr(eta)) / (1 - fdr(eta))
    ap = alpha_prime(pig, A)
    errs = []
    for ch in range(3):
        full = half_plane([-1e9], ap[ch], T[ch], A)[0]
        errs.append(abs(full / rd_total(A, ap[ch]) - 1))
    return max(errs), float(np.max(abs(rd_total(A, ap) - pig)))


# ---- rendering -----------------------------------------------------------------

def render(tmp, lib, name, body, w, h, extra=()):
    pov = os.path.join(tmp, name + ".pov")
    with open(pov, "w") as f:
        f.write(body)
    out = os.path.join(tmp, name + ".exr")
    rc, log = povray(pov, out, w, h, lib, extra)
    if rc != 0:
        fail(f"{name}: POV-Ray exit {rc}\n{log[-1200:]}")
    return read_image(out)


def block_stats(img):
    """Per-column mean over rows and its standard error from 8 row blocks."""
    blocks = np.array_split(img, 8, axis=0)
    bm = np.array([b.mean(0) for b in blocks])  # (8, cols, 3)
    return img.mean(0), bm.std(0, ddof=1) / np.sqrt(len(blocks))


def main():
    soak, root, tmp, lib = setup_args(__doc__)
    tab = read_inc(root)
    eta = float(tab["Liquid_Ior"][0])
    bad = 0

    def check(what, ok):
        nonlocal bad
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {what}")

    def tol(ref, se):
        return 4 * se + 1e-3 * abs(ref) + 5e-3 * abs(ref) + 1e-4

    # reference self-check (independent of POV-Ray): plane integral vs closed form
    pig_d, T_d = knot(tab, "marble", 0)
    e_int, e_inv = self_check(pig_d, T_d, eta)
    check(f"reference: plane integral of the dipole vs Jensen's closed form {e_int:.1e} (< 2e-3); "
          f"Rd(POV-Ray's interpolated alpha') vs pigment {e_inv:.1e}", e_int < 2e-3)

    # (e) diffusion lengths of the whole table (no rendering)
    worst, clamped, n = diffusion_lengths(tab)
    check(f"(e) POV-Ray's diffusion length from pigment + Soak_K_Translucency vs the core's sigma_tr: worst "
          f"{worst:.1e} relative over {n - clamped} channel knots (< 1e-4); {clamped} at a clamp", worst < 1e-4)

    # (a), (b): lit level, marble dry and wet
    lit = {}
    for wet in (0, 1):
        pig, T = knot(tab, "marble", wet)
        img = render(tmp, lib, f"marble_lit_{wet}", scene("marble", wet, 1, 4, False), 32, 16)
        bm = np.array([b.mean((0, 1)) for b in np.array_split(img, 8, axis=0)])
        mean, se = img.reshape(-1, 3).mean(0), bm.std(0, ddof=1) / np.sqrt(len(bm))
        _, ref, ap, A = reference(pig, T, eta, [])
        lit[wet] = (mean, ref, se)
        for ch, c in enumerate("rgb"):
            err = mean[ch] / ref[ch] - 1
            t = tol(ref[ch], se[ch]) / ref[ch]
            check(f"(a) marble w={wet} lit {c}: POV-Ray {mean[ch]:.4f} vs Ft0^2 (Rd + alpha'/24) {ref[ch]:.4f} "
                  f"(pigment {pig[ch]:.4f}, alpha' {ap[ch]:.4f}): {err:+.4f} (tol {t:.4f})", abs(err) <= t)
    r_pov = lit[1][0] / lit[0][0]
    r_ref = lit[1][1] / lit[0][1]
    se_r = r_pov * np.sqrt((lit[1][2] / lit[1][0]) ** 2 + (lit[0][2] / lit[0][0]) ** 2)
    for ch, c in enumerate("rgb"):
        t = 4 * se_r[ch] + 2e-3 * r_ref[ch]
        check(f"(b) marble wet/dry {c}: {r_pov[ch]:.4f} vs {r_ref[ch]:.4f} (tol {t:.4f})",
              abs(r_pov[ch] - r_ref[ch]) <= t)

    # (c) shadow edge: marble dry (1 unit = 1 mm), limestone wet (1 unit = 10 um)
    for preset, wet, mpu, half in (("marble", 0, 1.0, 16.0), ("limestone", 1, 0.01, 24.0)):
        pig, T = knot(tab, preset, wet)
        img = render(tmp, lib, f"{preset}_edge", scene(preset, wet, mpu, half, True), W_EDGE, H_EDGE)
        mean, se = block_stats(img)
        px = 2 * half / W_EDGE
        # column i's centre at x = -half + (i + 0.5) px (units); the shadow covers x < 0
        x = -half + (np.arange(W_EDGE) + 0.5) * px
        d_mm = -x * mpu
        ref, lit_ref, ap, A = reference(pig, T, eta, d_mm)
        _, tr = profile(0.0, ap, T, A)
        lum = np.array([0.2126, 0.7152, 0.0722])
        shadow_cols = np.where(x < 0)[0][::-1]  # from the edge into the shadow
        worst = 0.0
        rows = []
        for k, i in enumerate(shadow_cols[:12]):
            m, s, rf = mean[i] @ lum, np.sqrt((se[i] ** 2) @ lum ** 2), ref[i] @ lum
            t = tol(rf, s)
            worst = max(worst, abs(m - rf) / t)
            rows.append(f"d={d_mm[i]:.3f} mm: {m:.4f} vs {rf:.4f} (+-{t:.4f})")
        far = mean[shadow_cols[-4:]] @ lum
        litm = mean[np.where(x > 0)[0][-8:]].mean(0) @ lum
        print(f"     {preset} w={wet}: 1/sigma_tr = {1 / tr.max():.3f} .. {1 / tr.min():.3f} mm, "
              f"pixel {px * mpu:.3f} mm; lit {litm:.4f} vs {lit_ref @ lum:.4f}")
        print("     " + "\n     ".join(rows))
        check(f"(c) {preset} w={wet}: luminance over the 12 columns past the shadow edge within tolerance "
              f"(worst {worst:.2f} of the tolerance)", worst <= 1)
        check(f"(c) {preset} w={wet}: light bleeds into the shadow (first column {mean[shadow_cols[0]] @ lum:.4f} "
              f"> 0.1 x lit) and decays (far shadow {far.mean():.5f} < 0.02 x lit)",
              mean[shadow_cols[0]] @ lum > 0.1 * litm and far.mean() < 0.02 * litm)

    # (d) below +Q9 the subsurface block is ignored: plain diffuse (the pigment), a sharp shadow
    pig, T = knot(tab, "marble", 0)
    img = render(tmp, lib, "marble_q8", scene("marble", 0, 1, 16.0, True), W_EDGE, 8, extra=("+Q8",))
    x = -16.0 + (np.arange(W_EDGE) + 0.5) * 0.5
    litq = img[:, x > 0.5].reshape(-1, 3).mean(0)
    shq = img[:, x < -0.5].max()
    check(f"(d) +Q8: lit {litq.round(4)} = pigment {pig.round(4)} (plain diffuse, 2e-3) and no light past "
          f"the shadow edge (max {shq:.2e})", np.allclose(litq, pig, rtol=2e-3, atol=1e-4) and shq < 1e-4)
    body = scene("marble", 0, 1, 16.0, False).split("box {")[0] + """
box { <-200, -200, -100>, <0, 200, 0> Soak_Wet_User_Subsurface_Material("limestone", "water", 0.6, pigment { rgb <0.6, 0.5, 0.3> }) }
box { <0, -200, -100>, <200, 200, 0> Soak_Wet_User_Material("limestone", "water", 0.6, pigment { rgb <0.6, 0.5, 0.3> }) }
"""
    img = render(tmp, lib, "user_q8", body, 16, 8, extra=("+Q8",))
    a, b = img[:, :7].reshape(-1, 3).mean(0), img[:, 9:].reshape(-1, 3).mean(0)
    # Soak_Wet_User_Material's pigment is seen through the liquid (the preset's view factor,
    # here along the normal); the subsurface pigment is the albedo POV-Ray's BSSRDF reads
    k = next(m for m in export_json(soak, tmp)["materials"] if m["name"] == "limestone")["liquids"]["water"]["knots"]
    j = export_json(soak, tmp)["view_cos"].index(1.0)
    f = np.array([np.interp(0.6, k["wetness"], [v[j][c] for v in k["view_factor"]]) for c in range(3)])
    check(f"(d) +Q8: user-pigment subsurface material x the view factor {(a * f).round(4)} = Soak_Wet_User_Material "
          f"{b.round(4)}", np.allclose(a * f, b, rtol=1e-3, atol=1e-4) and a.min() > 0)
    if bad:
        fail(f"{bad} subsurface checks failed")
    print("PASS")


if __name__ == "__main__":
    main()
