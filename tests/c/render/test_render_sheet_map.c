/* A thin sheet (the paper preset) lit from behind takes its medium from the
 * object's wetness, not only from the material's: where a wetness plane
 * says dry, the sheet must transmit as the preset at wetness 0, where it
 * says wet as the preset at the material's wetness. The references are
 * separate renders of the preset at those two wetness values with no map
 * (the chain evaluated for each, one medium throughout), so the map's
 * per-point choice is checked against a second path through the chain.
 *
 *  1. Half-wet sheet (wetness plane x < 0 wet): the dry half's pixel equals
 *     the dry preset's, the wet half's the wet preset's, each within four
 *     combined standard errors (per channel).
 *  2. A uniform object wetness 0.5 is the mean of the two (the walk picks the
 *     wet medium with probability 0.5 at each entry).
 *  3. [JLD99] sec. 4.1 and issue 39: back-lit paper's wet spot is brighter
 *     than the dry sheet (wet/dry luminance > 1 by more than 4 sigma), and no
 *     brighter than the index-matching model allows: water replacing the air
 *     at every fibre surface scales Kubelka's S by the fibres' hemispherical
 *     Fresnel reflectance in water over that in air, K unchanged (the
 *     assumption: all of the sheet's scattering is reflection at fibre-pore
 *     interfaces; the wet sheet's film is not in the bound).
 *  4. White light through the dry sheet has the colour of the published data:
 *     red/blue against Kubelka's closed forms (Kubelka 1948) from the preset's
 *     R_inf per channel (its albedo: measured green, the chromaticity of an
 *     unbrightened cellulose sheet, c_core/data/materials.json) and the published opacity
 *     R0/R_inf = 0.90 (JCP O-63), one S for the three channels, with the
 *     sheet's two faces of index n (Saunderson 1942). The tolerance is the sum
 *     of named terms: Monte Carlo (4 sigma of the ratio), the two-flux form's
 *     colour error against transport (TWO_FLUX_COLOUR) and the RGB projection
 *     of the spectrum (RGB_PROJECTION). And not blue: red/blue >= 1, which the
 *     issue-39 sheets (0.05 at 0.8 mm; 0.80 with the brightened albedo) fail.
 *     The wet spot is warm or neutral and no more coloured than the dry sheet
 *     (index matching shortens the paths). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "check.h"
#include "render_harness.h"
#include "soak/fresnel.h"
#include "soak/image.h"
#include "soak/preset.h"
#include "soak/render.h"
#include "soak/scene.h"

#define REPS 8
#define SPP 1024
#define JCP_OPACITY 0.90 /* R0 / R_inf of 80 g/m^2 copier paper, JCP O-63 (as test_sheet_paper) */
/* Per channel the RGB albedo stands for a band of wavelengths; Kubelka's T of
 * the band's mean R_inf differs from the band's mean T by 1/2 T''/T var(R_inf):
 * 0.2 % for R_inf spread uniformly over 0.10 within a band (twice the measured
 * blue-green difference), relative. */
#define RGB_PROJECTION 0.003
/* The reference is a two-flux sheet, the render a traced one: the chain's
 * two-flux sheet with faces (soak/sheet.h, exported) against this render of
 * the same medium differs in red/blue by -1.1 % (1.162 against 1.149; 0.4 %
 * with the brightened albedo), while its level is off by -2 % to -13 %
 * (tests/c/export/test_export.c) with red and blue sharing most of it: 0.02. */
#define TWO_FLUX_COLOUR 0.02

/* One pixel of a sheet of paper (thickness t mm, units mm) at x = x0, seen
 * along its normal, a sun behind it; material at preset wetness `mat_w`,
 * object wetness `object_w` (JSON). */
static int sheet(const char *what, double t, double x0, double mat_w, const char *object_w, uint64_t seed, rh_rgb *e)
{
    char text[2048];
    snprintf(text, sizeof text,
             "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 1000},"
             " \"camera\": {\"position\": [%g, 0, 5], \"look_at\": [%g, 0, 0], \"up\": [0, 1, 0], \"fov\": 0.5},"
             " \"lights\": [{\"type\": \"sun\", \"direction\": [0.3, 0, -0.9539392014169456], \"irradiance\": 1}],"
             " \"materials\": {\"m\": {\"type\": \"preset\", \"name\": \"paper\", \"wetness\": %g, \"unit_mm\": 1}},"
             " \"objects\": [{\"type\": \"box\", \"min\": [-60, -60, %.17g], \"max\": [60, 60, 0], \"material\": \"m\","
             " \"wetness\": %s}]}",
             x0, x0, mat_w, -t, object_w);
    return rh_render_rgb(what, text, REPS, SPP, seed, e);
}

/* The published sheet's numbers the renders are checked against. */
typedef struct published_sheet {
    double rb_dry;    /* red/blue of the dry sheet's transmittance under white light */
    double wet_bound; /* wet/dry luminance when water index-matches every fibre surface */
} published_sheet;

/* Kubelka 1948: reflectance R and transmittance T of a sheet of Kubelka
 * thickness S d and K/S (a stack reflecting r: K/S = (1 - r)^2 / (2 r),
 * a = 1 + K/S = (1/r + r)/2, b = sqrt(a^2 - 1) = (1/r - r)/2). */
static void kubelka_sheet(double k_over_s, double sd, double *R, double *T)
{
    double a = 1 + k_over_s, b = sqrt(a * a - 1);
    double den = a * sinh(b * sd) + b * cosh(b * sd);
    *R = sinh(b * sd) / den;
    *T = b / den;
}

/* Saunderson 1942: the two faces of index n (hemispherical Fresnel averages r_e outside, r_i inside). */
static double with_faces(double R, double T, double r_e, double r_i)
{
    return (1 - r_e) * (1 - r_i) * T / ((1 - r_i * R) * (1 - r_i * R) - r_i * T * r_i * T);
}

/* From the preset's R_inf per channel, the published opacity (one S d for the three channels, from green) and its
 * index: the dry red/blue and the index-matching bound of the wet/dry luminance. */
static int published(const soak_preset *p, const soak_liquid *water, published_sheet *out)
{
    double r_e = 0, r_i = 0, f_air = 0, f_water = 0;
    if (soak_fresnel_dielectric_avg(p->ior, &r_e) != SOAK_OK || soak_fresnel_dielectric_avg(1 / p->ior, &r_i) != SOAK_OK ||
        soak_fresnel_dielectric_avg(p->ior, &f_air) != SOAK_OK ||
        soak_fresnel_dielectric_avg(p->ior / water->ior, &f_water) != SOAK_OK)
        return 0;
    double rg = p->albedo.g, a = 0.5 * (1 / rg + rg), b = 0.5 * (1 / rg - rg);
    double sd = atanh(b / (1 / (JCP_OPACITY * rg) - a)) / b;
    double dry[3], wet[3];
    for (int c = 0; c < 3; ++c) {
        double r = soak_rgb_at(p->albedo, c), ks = (1 - r) * (1 - r) / (2 * r), R, T;
        kubelka_sheet(ks, sd, &R, &T);
        dry[c] = with_faces(R, T, r_e, r_i);
        kubelka_sheet(ks * f_air / f_water, sd * f_water / f_air, &R, &T);
        wet[c] = with_faces(R, T, r_e, r_i);
    }
    out->rb_dry = dry[0] / dry[2];
    out->wet_bound = (0.2126 * wet[0] + 0.7152 * wet[1] + 0.0722 * wet[2]) /
                     (0.2126 * dry[0] + 0.7152 * dry[1] + 0.0722 * dry[2]);
    return 1;
}

static double luminance(const rh_rgb *e)
{
    return 0.2126 * e->mean[0] + 0.7152 * e->mean[1] + 0.0722 * e->mean[2];
}

static void check_same(const char *what, const rh_rgb *a, const rh_rgb *b)
{
    for (int c = 0; c < 3; ++c) {
        printf("  %s [%c]: %.5f +- %.5f against %.5f +- %.5f\n", what, "rgb"[c], a->mean[c], a->se[c], b->mean[c],
               b->se[c]);
        check_close(what, a->mean[c], b->mean[c], 4 * sqrt(a->se[c] * a->se[c] + b->se[c] * b->se[c]) + 1e-6);
    }
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    soak_preset_db *db = NULL;
    char err[256];
    if (!check_status("presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return check_finish();
    const soak_preset *p = soak_presets_find(db, "paper");
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    double t = p ? p->thickness_m * 1e3 : 0;
    published_sheet pub = {0, 0};
    int have_pub = p && water && published(p, water, &pub);
    soak_presets_free(db);
    if (!check_true("paper is a sheet with a thickness", t > 0) ||
        !check_true("published sheet numbers from the preset's data", have_pub))
        return check_finish();
    const published_sheet *ref = &pub;

    const char *half = "{\"type\": \"plane\", \"normal\": [1, 0, 0], \"offset\": 0, \"blend\": 1}";
    rh_rgb dry, wet, map_dry, map_wet, uniform;
    /* different seeds: the references are independent estimates, not the same paths */
    if (!sheet("dry preset", t, 20, 0, "1", 100, &dry) || !sheet("wet preset", t, -20, 1, "1", 200, &wet) ||
        !sheet("map, dry half", t, 20, 1, half, 300, &map_dry) || !sheet("map, wet half", t, -20, 1, half, 400, &map_wet) ||
        !sheet("uniform wetness 0.5", t, 0, 1, "0.5", 500, &uniform))
        return check_finish();
    check_same("half-wet map, dry half = the dry preset", &map_dry, &dry);
    check_same("half-wet map, wet half = the wet preset", &map_wet, &wet);
    rh_rgb mix;
    for (int c = 0; c < 3; ++c) {
        mix.mean[c] = 0.5 * (dry.mean[c] + wet.mean[c]);
        mix.se[c] = 0.5 * sqrt(dry.se[c] * dry.se[c] + wet.se[c] * wet.se[c]);
    }
    check_same("uniform wetness 0.5 = mean of dry and wet", &uniform, &mix);

    double ld = luminance(&dry), lw = luminance(&wet);
    double se = sqrt(dry.se[1] * dry.se[1] + wet.se[1] * wet.se[1]);
    double rb_dry = dry.mean[0] / dry.mean[2], rb_wet = wet.mean[0] / wet.mean[2];
    printf("  back-lit paper: wet/dry luminance %.3f, red/blue dry %.3f wet %.3f; published: red/blue %.3f,"
           " index-matching bound %.3f\n", lw / ld, rb_dry, rb_wet, ref->rb_dry, ref->wet_bound);
    check_true("back-lit wet paper brighter than dry (> 4 sigma)", lw - ld > 4 * se);
    double ratio_se = lw / ld * sqrt(pow(se / lw, 2) + pow(dry.se[1] / ld, 2));
    char what[200];
    snprintf(what, sizeof what, "back-lit wet/dry %.3f <= index-matching bound %.3f + 4 sigma", lw / ld, ref->wet_bound);
    check_true(what, lw / ld <= ref->wet_bound + 4 * ratio_se);
    double mc = 4 * dry.rb_se;
    double tol = ref->rb_dry * (TWO_FLUX_COLOUR + RGB_PROJECTION) + mc;
    snprintf(what, sizeof what, "red/blue through dry paper %.3f = published %.3f within %.3f (MC %.3f, two-flux %.3f,"
             " RGB %.3f)", rb_dry, ref->rb_dry, tol, mc, ref->rb_dry * TWO_FLUX_COLOUR, ref->rb_dry * RGB_PROJECTION);
    check_close(what, rb_dry, ref->rb_dry, tol);
    snprintf(what, sizeof what, "red/blue through dry paper %.3f >= 1 - %.3f (warm or neutral, not blue)", rb_dry, mc);
    check_true(what, rb_dry >= 1 - mc);
    double mc_wet = 4 * wet.rb_se;
    snprintf(what, sizeof what, "red/blue through wet paper %.3f in [1 - %.3f, %.3f] (warm or neutral, not more than dry)",
             rb_wet, mc_wet, ref->rb_dry + tol);
    check_true(what, rb_wet >= 1 - mc_wet && rb_wet <= ref->rb_dry + tol);
    return check_finish();
}
