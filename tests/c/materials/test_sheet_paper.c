/* The paper preset as a measured sheet (soak/sheet.h, c_core/data/materials.json):
 *  1. thickness from grammage and density, 80 g/m^2 / 800 kg/m^3 = 0.1 mm,
 *     against the U.S. GPO's JCP O-63 plain copier paper specification
 *     (2007): 3.8 mil = 0.0965 mm for its 21/22 lb (79-83 g/m^2) grade, within
 *     the specification's tolerance 0.3 mil;
 *  2. opacity R0 / R_inf of the chain's two-flux sheet (Kubelka 1948 with the
 *     chain's K, S) against JCP O-63's "opacity, average not less than 90 %"
 *     for that grade (and below 95 %, the top of copier papers' range);
 *  3. transmittance and its colour against the same two published numbers
 *     by a second route: Kubelka's closed forms from the measured R_inf (the
 *     preset's albedo: the green of pb.info 'Office Paper' with the chromaticity
 *     of an unbrightened cellulose sheet, c_core/data/materials.json) and the
 *     opacity 0.90 alone, with one S for the three channels (fibres much
 *     wider than the wavelength): the chain's T per channel within 10 %, its
 *     blue/red ratio within 5 %, and warm or neutral: red/blue >= 1 in both
 *     (cellulose absorbs more blue than red without UV excitation; the sheet
 *     of issue 39 passed 20 times more blue than red at 0.8 mm, the
 *     brightened albedo 1.14 times more at 0.1 mm);
 *  4. wet/dry transmittance: brighter wet, and no brighter than the
 *     index-matching bound -- water replacing the air at every fibre surface,
 *     S scaled by the fibres' hemispherical Fresnel reflectance in water over
 *     that in air (the assumption: all of the sheet's scattering is
 *     reflection at fibre-pore interfaces), K unchanged. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "soak/fresnel.h"
#include "soak/preset.h"
#include "soak/sheet.h"
#include "soak/wetness.h"

#define JCP_THICKNESS_M (3.8 * 25.4e-6)
#define JCP_TOL_M (0.3 * 25.4e-6)
#define JCP_OPACITY 0.90

static void km_coeffs(const soak_wet_params *w, int ch, double *K, double *S)
{
    double sa = soak_rgb_at(w->sigma_a_per_m, ch), ss = soak_rgb_at(w->sigma_s_per_m, ch);
    *K = 2 * sa;
    *S = 0.75 * ss * (1 - w->mean_cosine) - 0.25 * sa; /* van Gemert & Star 1987, as soak/sheet.h */
}

static double km_r_inf(double K, double S)
{
    double a = (S + K) / S;
    return a - sqrt(a * a - 1);
}

/* Kubelka 1948: T of a sheet of reflectance R0 over black and R_inf. */
static double km_t_from(double r0, double r_inf, double *bsx)
{
    double a = 0.5 * (1 / r_inf + r_inf), b = 0.5 * (1 / r_inf - r_inf);
    *bsx = atanh(b / (1 / r0 - a));
    return b / (a * sinh(*bsx) + b * cosh(*bsx));
}

static void check_dry(const soak_preset *p, const soak_wet_params *w, soak_rgb *T)
{
    *T = soak_rgb3(0, 0, 0);
    double K, S, R0, T0;
    char what[200];
    snprintf(what, sizeof what, "paper thickness %.4f mm = JCP O-63's 3.8 mil within 0.3 mil", p->thickness_m * 1e3);
    check_close(what, p->thickness_m, JCP_THICKNESS_M, JCP_TOL_M);
    km_coeffs(w, 1, &K, &S);
    soak_km_slab(K, S, p->thickness_m, &R0, &T0);
    double opacity = R0 / km_r_inf(K, S);
    snprintf(what, sizeof what, "opacity R0/R_inf %.4f (green) in [0.90, 0.95] (JCP O-63: >= 0.90)", opacity);
    check_true(what, opacity >= JCP_OPACITY && opacity <= 0.95);
    /* S d from the published opacity at green, then each channel's R_inf */
    double bsx, b_g = 0.5 * (1 / p->albedo.g - p->albedo.g);
    km_t_from(JCP_OPACITY * p->albedo.g, p->albedo.g, &bsx);
    double sd = bsx / b_g, pub[3];
    for (int ch = 0; ch < 3; ++ch) {
        double r = soak_rgb_at(p->albedo, ch), a = 0.5 * (1 / r + r), b = 0.5 * (1 / r - r);
        pub[ch] = b / (a * sinh(b * sd) + b * cosh(b * sd));
        km_coeffs(w, ch, &K, &S);
        soak_km_slab(K, S, p->thickness_m, &R0, &T0);
        soak_rgb_set(T, ch, T0);
        snprintf(what, sizeof what, "channel %d: chain T %.4f = T from R_inf and the opacity %.4f within 10 %%", ch, T0,
                 pub[ch]);
        check_rel(what, T0, pub[ch], 0.10);
    }
    double ratio = T->b / T->r, pub_ratio = pub[2] / pub[0];
    snprintf(what, sizeof what, "transmitted blue/red %.3f = published route's %.3f within 5 %%", ratio, pub_ratio);
    check_rel(what, ratio, pub_ratio, 0.05);
    snprintf(what, sizeof what, "transmitted light warm or neutral: red/blue %.3f (published route %.3f) >= 1", 1 / ratio,
             1 / pub_ratio);
    check_true(what, ratio <= 1.0 && pub_ratio <= 1.0);
}

static void check_wet(const soak_preset *p, const soak_liquid *water, const soak_wet_params *dry, soak_rgb T_dry)
{
    soak_wet_input in = soak_wet_input_steady(p, 1.0);
    soak_wet_params w;
    double K, S, R0, T_wet, r_air = 0, r_water = 0, Kd, Sd, T_bound;
    if (!check_status("paper wet state", soak_wetness_eval(p, water, &in, &w), SOAK_OK)) return;
    km_coeffs(&w, 1, &K, &S);
    soak_km_slab(K, S, p->thickness_m, &R0, &T_wet);
    soak_fresnel_dielectric_avg(p->ior, &r_air);
    soak_fresnel_dielectric_avg(p->ior / water->ior, &r_water);
    km_coeffs(dry, 1, &Kd, &Sd);
    soak_km_slab(Kd, Sd * r_water / r_air, p->thickness_m, &R0, &T_bound);
    double ratio = T_wet / T_dry.g, bound = T_bound / T_dry.g;
    printf("  wet/dry transmittance (green): chain %.3f, index-matching bound %.3f (S x %.3f)\n", ratio, bound,
           r_water / r_air);
    char what[200];
    snprintf(what, sizeof what, "wet paper transmits more: wet/dry %.3f in (1, index-matching bound %.3f]", ratio, bound);
    check_true(what, ratio > 1.0 && ratio <= bound);
}

int main(void)
{
    soak_preset_db *db = NULL;
    char err[512];
    if (!check_status("presets load", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return check_finish();
    const soak_preset *p = soak_presets_find(db, "paper");
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    soak_wet_params dry;
    soak_wet_input in = p ? soak_wet_input_steady(p, 0.0) : (soak_wet_input){0};
    if (check_true("paper and water presets exist", p && water) &&
        check_status("paper dry state", soak_wetness_eval(p, water, &in, &dry), SOAK_OK)) {
        soak_rgb T = soak_rgb3(0, 0, 0);
        check_dry(p, &dry, &T);
        check_wet(p, water, &dry, T);
    }
    soak_presets_free(db);
    return check_finish();
}
