/* The base's own specular under the liquid (soak/wet_specular.h).
 * References: the film's bounces summed one by one from Fresnel's
 * normal-incidence formula written here (a second method for the closed
 * form), identities (no film interface at n_liquid = 1: the dry F0; an
 * index-matched base: no reflection; an opaque film: none), the dry state
 * (factor 1), wetness.h's interface area, and the conductor's refraction
 * stretch alpha n_liquid at full film. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "soak/preset.h"
#include "soak/wet_specular.h"
#include "soak/wetness.h"

static double r0(double eta) { return (eta - 1) * (eta - 1) / ((eta + 1) * (eta + 1)); }

/* Light entering the film (1 - R12), then k round trips between the base
 * (R23) and the film's top from below (R12), leaving through (1 - R12). */
static double under_series(double n_base, double n_liq, double e)
{
    double r12 = r0(n_liq), r23 = r0(n_base / n_liq), sum = 0.0, bounce = (1 - r12) * r23 * e * (1 - r12);
    for (int k = 0; k < 60; ++k) {
        sum += bounce;
        bounce *= r12 * r23 * e;
    }
    return sum;
}

static void check_under(void)
{
    const double cases[][3] = {{1.54, 1.333, 1.0}, {1.5, 1.333, 0.3}, {2.4, 1.34, 0.9}, {1.2, 1.6, 1.0}, {3.0, 1.0, 1.0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        double R = -1;
        char what[96];
        snprintf(what, sizeof what, "R_under(n %.2f, liquid %.3f, e %.1f) vs bounce sum", cases[i][0], cases[i][1],
                 cases[i][2]);
        check_status(what, soak_wet_specular_under(cases[i][0], cases[i][1], cases[i][2], &R), SOAK_OK);
        check_close(what, R, under_series(cases[i][0], cases[i][1], cases[i][2]), 1e-14);
    }
    double R = -1;
    soak_wet_specular_under(1.54, 1.0, 1.0, &R);
    check_close("no liquid interface (n_liquid 1): the dry F0", R, r0(1.54), 1e-15);
    soak_wet_specular_under(1.333, 1.333, 1.0, &R);
    check_close("index-matched base: no base reflection", R, 0.0, 1e-15);
    soak_wet_specular_under(1.54, 1.333, 0.0, &R);
    check_close("opaque film: nothing comes back", R, 0.0, 0.0);
    check_status("NaN base index", soak_wet_specular_under(NAN, 1.333, 1.0, &R), SOAK_ERR_ARG);
    check_status("two-pass > 1", soak_wet_specular_under(1.5, 1.333, 1.01, &R), SOAK_ERR_ARG);
    check_status("liquid index < 1", soak_wet_specular_under(1.5, 0.9, 1.0, &R), SOAK_ERR_ARG);
    check_status("NULL out", soak_wet_specular_under(1.5, 1.333, 1.0, NULL), SOAK_ERR_NULL);
}

static void check_presets(const soak_preset_db *db)
{
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    const soak_liquid *coffee = soak_presets_find_liquid(db, "coffee");
    const char *names[] = {"sand", "brick", "oak", "marble", "paper", "copper", "aluminium"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i) {
        const soak_preset *p = soak_presets_find(db, names[i]);
        if (!check_true(names[i], p != NULL)) continue;
        const double ws[] = {0.0, 0.5 * (p->kind == SOAK_KIND_CONDUCTOR ? 1.0 : p->porosity), 0.7, 1.0};
        for (size_t k = 0; k < 4; ++k) {
            soak_wet_input in = soak_wet_input_steady(p, ws[k]);
            soak_wet_params w;
            soak_wet_specular s;
            char what[128];
            snprintf(what, sizeof what, "%s w=%.3f", names[i], ws[k]);
            if (soak_wetness_eval(p, water, &in, &w) != SOAK_OK ||
                !check_status(what, soak_wet_specular_eval(p, water, &w, &s), SOAK_OK))
                continue;
            check_close("  interface area = wetness.h's", s.interface_area, soak_wet_interface_area(&w), 0.0);
            double c = w.film_coverage;
            if (p->kind == SOAK_KIND_CONDUCTOR) {
                check_close("  conductor: base factor 1", s.base_factor, 1.0, 0.0);
                check_close("  conductor: alpha stretched over the coverage", s.ggx_alpha,
                            w.ggx_alpha * ((1 - c) + c * water->ior), 1e-15);
            } else {
                double e[3], under = 0.0;
                for (int ch = 0; ch < 3; ++ch) {
                    e[ch] = exp(-2.0 * soak_rgb_at(w.film_absorption_per_m, ch) * w.film_thickness_m);
                    under += under_series(p->ior, water->ior, e[ch]) / 3.0;
                }
                check_close("  dielectric: base factor from the bounce sum", s.base_factor,
                            (1 - c) + c * under / r0(p->ior), 1e-12);
                check_close("  dielectric: chain's alpha", s.ggx_alpha, w.ggx_alpha, 0.0);
                if (ws[k] == 0.0) check_close("  dry: factor 1", s.base_factor, 1.0, 0.0);
                if (ws[k] == 1.0) check_true("  full film: the base keeps < 15 % of its specular", s.base_factor < 0.15);
            }
        }
    }
    /* coffee absorbs: under a full film less of the base's specular returns */
    const soak_preset *sand = soak_presets_find(db, "sand");
    soak_wet_input in = soak_wet_input_steady(sand, 1.0);
    soak_wet_params ww, wc;
    soak_wet_specular sw, sc;
    soak_wetness_eval(sand, water, &in, &ww);
    soak_wetness_eval(sand, coffee, &in, &wc);
    soak_wet_specular_eval(sand, water, &ww, &sw);
    soak_wet_specular_eval(sand, coffee, &wc, &sc);
    printf("sand full film: base specular factor water %.4f, coffee %.4f\n", sw.base_factor, sc.base_factor);
    check_true("coffee film hides more of the base's specular than water", sc.base_factor < sw.base_factor);
    ww.film_coverage = NAN;
    check_status("NaN coverage", soak_wet_specular_eval(sand, water, &ww, &sw), SOAK_ERR_ARG);
    check_status("NULL params", soak_wet_specular_eval(sand, water, NULL, &sw), SOAK_ERR_NULL);
}

/* Point 4's dry-draw coat weight against the area bookkeeping written out:
 * the lobe in air over the dry part (1 - c)(1 - p f) must be ks (1 - c),
 * checked per preset and wetness, and its edges. */
static void check_grain_coat(const soak_preset_db *db)
{
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    double worst = 0;
    int n = 0;
    for (int i = 0; i < soak_presets_count(db); ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        for (int k = 0; k <= 20; ++k) {
            soak_wet_input in = soak_wet_input_steady(p, k / 20.0);
            soak_wet_params w;
            if (soak_wetness_eval(p, water, &in, &w) != SOAK_OK) continue;
            double c = w.film_coverage, A = soak_wet_interface_area(&w);
            double lobe_in_air = soak_wet_grain_coat_weight(&w) * (1 - A);
            worst = fmax(worst, fabs(lobe_in_air - w.specular_weight * (1 - c)));
            ++n;
        }
    }
    printf("grain coat weight: %d states, worst |k_dry (1 - A) - ks (1 - c)| %.2e\n", n, worst);
    check_true("dry draw's lobe = ks (1 - c) over every preset and wetness", n > 100 && worst <= 1e-12);
    soak_wet_params w = {0};
    w.specular_weight = 0.6;
    check_close("no pore water: ks", soak_wet_grain_coat_weight(&w), 0.6, 0);
    w.water_specular_weight = 0.4;
    check_close("pores full (ks = 1 - p, f = 1): every dry point a grain", soak_wet_grain_coat_weight(&w), 1.0, 1e-15);
    w.water_specular_weight = 0.2;
    check_close("half full: 0.6 / 0.8", soak_wet_grain_coat_weight(&w), 0.75, 1e-15);
    w.specular_weight = 0.9;
    check_close("ks above 1 - p f: clamped to 1", soak_wet_grain_coat_weight(&w), 1.0, 0);
    w.water_specular_weight = 1.0;
    check_close("p f = 1: no dry part, ks", soak_wet_grain_coat_weight(&w), 0.9, 0);
    w.water_specular_weight = NAN;
    check_close("NaN fill: 0", soak_wet_grain_coat_weight(&w), 0.0, 0);
    check_close("NULL: 0", soak_wet_grain_coat_weight(NULL), 0.0, 0);
}

int main(void)
{
    check_under();
    soak_preset_db *db = NULL;
    char err[512];
    if (check_status("load presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) {
        check_presets(db);
        check_grain_coat(db);
        soak_presets_free(db);
    }
    return check_finish();
}
