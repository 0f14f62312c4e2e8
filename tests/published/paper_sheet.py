"""Published office paper as a sheet (Kubelka's two-flux closed forms with
Saunderson's face corrections): the independent reference of the back-lit
paper checks in POV-Ray (tests/povray/scenes_check.py) and Blender
(tests/blender/test_render_compare.py). Plain Python: Blender's and the
host's interpreters both import it."""
import math

# The published sheet (as tests/c/render/test_render_sheet_map.c): Kubelka's closed forms (Kubelka 1948) from the
# preset's R_inf per channel (its albedo: measured, blue without brightener fluorescence) and the published opacity
# R0/R_inf = 0.90 of 80 g/m^2 copier paper (U.S. GPO JCP O-63), one S d for the three channels (from green), the
# sheet's two faces of index n (Saunderson 1942: r_e the cosine-weighted Fresnel average from air, r_i = 1 - (1 - r_e)
# / n^2 inside). Returns the transmittance per channel; with wet=True, water index-matching every fibre surface
# (S scaled by the fibres' hemispherical reflectance in water over that in air, K unchanged): the upper bound of the
# wet sheet's transmittance.
JCP_OPACITY = 0.90
RGB_PROJECTION = 0.003    # a band's mean R_inf in place of its spectrum: 1/2 T''/T var(R_inf) (test_render_sheet_map.c)
TWO_FLUX_COLOUR = 0.02    # two-flux colour against the traced sheet (measured 1.1 %, test_render_sheet_map.c)


def hemispherical_fresnel(n, steps=4000):
    total = 0.0
    for i in range(steps):
        mu = (i + 0.5) / steps
        s2 = (1 - mu * mu) / (n * n)
        if s2 >= 1:
            f = 1.0
        else:
            mt = math.sqrt(1 - s2)
            rs, rp = (mu - n * mt) / (mu + n * mt), (n * mu - mt) / (n * mu + mt)
            f = 0.5 * (rs * rs + rp * rp)
        total += 2 * mu * f / steps
    return total


def published_sheet(albedo, ior, water_ior=1.333, wet=False):
    r_e = hemispherical_fresnel(ior)
    r_i = 1 - (1 - r_e) / ior ** 2
    rg = albedo[1]
    a, b = 0.5 * (1 / rg + rg), 0.5 * (1 / rg - rg)
    sd = math.atanh(b / (1 / (JCP_OPACITY * rg) - a)) / b
    s_scale = hemispherical_fresnel(ior / water_ior) / r_e if wet else 1.0
    out = []
    for r in albedo:
        ks = (1 - r) ** 2 / (2 * r) / s_scale
        a = 1 + ks
        b = math.sqrt(a * a - 1)
        den = a * math.sinh(b * sd * s_scale) + b * math.cosh(b * sd * s_scale)
        rr, t = math.sinh(b * sd * s_scale) / den, b / den
        out.append((1 - r_e) * (1 - r_i) * t / ((1 - r_i * rr) ** 2 - (r_i * t) ** 2))
    return out
