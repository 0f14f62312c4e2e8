/* The OSL shaders' math (c_core/export/src/soak_wet_math.h, the source of
 * osl/soak_wet_math.h and of the shaders' inlined copy, compiled here as C) on the
 * tables the shaders carry (export_osl.c) against the core itself:
 *  - the pore-filling schedule = soak_wetness_eval's delivered liquid;
 *  - knot lookups of albedo, interface coverage, the material's lobe in air
 *    ks (1 - c) (KS x (1 - KF)), roughness and sheet
 *    transmittance = soak_wetness_eval / soak_sheet_transmittance within the
 *    export's knot tolerance (plus float rounding);
 *  - the base-colour lookup = soak_wet_params_for_base within the base
 *    tolerance, at points between the nodes;
 *  - the diffuse closure's weight along a view, WetColor x View, = the
 *    core's directional albedo (soak_wetness_albedo_sun, reciprocity) within
 *    the knot tolerance, views 0-75 deg;
 *  - the Fresnel weight of the liquid's mirror = soak_fresnel_dielectric
 *    (both directions, total internal reflection, no interface). */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "export_osl_tables.h"
#include "soak/fresnel.h"
#include "soak/sheet.h"
#include "soak/wetness.h"
#include "soak_wet_math.h"

#define FLOAT_EPS 1e-5 /* the shader's tables are single precision */

static void test_schedule(const soak_preset *p, const soak_liquid *l)
{
    const double cases[][4] = {{1.0, 0.5, 0.2, 0.4}, {0.7, 0.1, 0.2, 0.4}, {0.7, 0.9, 0.2, 0.4}, {0.3, 0.2, 0.2, 0.0},
                               {0.3, 0.19, 0.2, 0.0}, {1.0, -3.0, -5.0, 1.5}, {0.0, 1.0, 0.0, 0.1}};
    double worst = 0.0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        soak_wet_input in = soak_wet_input_steady(p, cases[i][0]);
        in.time = cases[i][1];
        in.t0 = cases[i][2];
        in.t_fill = cases[i][3];
        soak_wet_params w;
        if (!check_status("core schedule", soak_wetness_eval(p, l, &in, &w), SOAK_OK)) return;
        float got = soak_delivered((float)in.wetness, (float)in.time, (float)in.t0, (float)in.t_fill);
        worst = fmax(worst, fabs(got - w.liquid));
        float dry = soak_remaining((float)in.wetness, (float)in.time, (float)in.t0, (float)in.t_fill);
        worst = fmax(worst, fabs(dry - (in.wetness - w.liquid)));
    }
    check_close("soak_delivered / soak_remaining = the core's delivered liquid", worst, 0.0, FLOAT_EPS);
}

static void test_fresnel(void)
{
    const double etas[] = {1.0 / 1.5, 1.0 / 1.333, 1.0, 1.333, 1.34, 1.5, 2.5};
    double worst = 0.0;
    soak_status st = SOAK_OK;
    for (size_t e = 0; e < sizeof etas / sizeof etas[0]; ++e) {
        for (int i = 0; i <= 400; ++i) {
            double c = i / 400.0, R;
            if ((st = soak_fresnel_dielectric(c, etas[e], &R, NULL)) != SOAK_OK) break;
            worst = fmax(worst, fabs(soak_fresnel((float)c, (float)etas[e]) - R));
        }
    }
    check_status("core Fresnel", st, SOAK_OK);
    check_close("soak_fresnel = soak_fresnel_dielectric (401 angles x 7 indices)", worst, 0.0, FLOAT_EPS);
    /* Identity: water's normal reflectance ((n-1)/(n+1))^2 = 0.0203732 */
    check_close("soak_fresnel at normal incidence, water", soak_fresnel(1.0f, 1.333f), 0.0203732, 1e-6);
}

static void test_tables(const soak_preset_db *db, const soak_osl_tables *t)
{
    double worst_knot = 0.0, worst_base = 0.0, worst_sheet = 0.0;
    soak_status st = SOAK_OK;
    for (int pi = 0; pi < t->n_presets; ++pi) {
        const soak_preset *p = soak_presets_at(db, t->preset.v[pi]);
        for (int li = 0; li < t->n_liquids; ++li) {
            const soak_liquid *l = soak_presets_liquid_at(db, li);
            int k = pi * t->n_liquids + li;
            for (int s = 0; s <= 60; ++s) {
                double L = (s + 0.29) / 60.29;
                soak_wet_input in = soak_wet_input_steady(p, L);
                soak_wet_params w;
                if ((st = soak_wetness_eval(p, l, &in, &w)) != SOAK_OK) break;
                int off = t->k_off.v[k], n = t->k_n.v[k];
                for (int c = 0; c < 3; ++c) {
                    float got = soak_interp(t->kw.v, off, n, (float)L, t->ka.v, 3 * off + c, 3);
                    worst_knot = fmax(worst_knot, fabs(got - soak_rgb_at(w.albedo, c)));
                }
                double iface = p->kind == SOAK_KIND_CONDUCTOR
                                   ? w.film_coverage
                                   : w.film_coverage + (1 - w.film_coverage) * w.water_specular_weight;
                worst_knot = fmax(worst_knot, fabs(soak_interp(t->kw.v, off, n, (float)L, t->kc.v, off, 1) - iface));
                /* the material's lobe in air, ks (1 - c) (soak/wet_specular.h point 1) */
                double lobe = soak_interp(t->kw.v, off, n, (float)L, t->ks.v, off, 1) *
                              (1 - soak_interp(t->kw.v, off, n, (float)L, t->kf.v, off, 1));
                int own = p->kind != SOAK_KIND_CONDUCTOR && p->kind != SOAK_KIND_THIN_SHEET;
                worst_knot = fmax(worst_knot, fabs(lobe - (own ? w.specular_weight * (1 - w.film_coverage) : 0.0)));
                worst_knot = fmax(worst_knot,
                                  fabs(soak_interp(t->kw.v, off, n, (float)L, t->kr.v, off, 1) - sqrt(w.ggx_alpha)));
                if (p->kind == SOAK_KIND_THIN_SHEET) {
                    soak_rgb T;
                    if ((st = soak_sheet_transmittance(&w, p->thickness_m, p->ior, &T)) != SOAK_OK) break;
                    for (int c = 0; c < 3; ++c) {
                        float got = soak_interp_log(t->kw.v, off, n, (float)L, t->kt.v, 3 * off + c, 3);
                        double ref = soak_rgb_at(T, c);
                        if (ref > 1e-6) worst_sheet = fmax(worst_sheet, fabs(got - ref) / ref);
                    }
                }
                for (int j = 0; j <= 12; ++j) {
                    double a = (j + 0.43) / 12.43;
                    soak_wet_params o;
                    if ((st = soak_wet_params_for_base(p, l, &in, (soak_rgb){a, a, a}, &o)) != SOAK_OK) break;
                    for (int c = 0; c < 3; ++c) {
                        float got = soak_base_lookup(t->ba.v, t->ba_off.v[k], t->ba_n.v[k], t->bw.v, t->bw_off.v[k],
                                                     t->bw_n.v[k], t->bg.v, t->bg_off.v[3 * k + c], (float)a, (float)L);
                        worst_base = fmax(worst_base, fabs(got - soak_rgb_at(o.albedo, c)));
                    }
                }
            }
        }
    }
    check_status("core evaluations", st, SOAK_OK);
    check_close("shader knot lookups (albedo, coverage, lobe, roughness) vs the core", worst_knot, 0.0,
                SOAK_EXPORT_KNOT_TOL + FLOAT_EPS);
    check_close("shader base-colour lookup vs soak_wet_params_for_base", worst_base, 0.0,
                SOAK_EXPORT_BASE_TOL + FLOAT_EPS);
    /* sheet transmittance spans decades: the knots bound 0.1 ln T within the
     * knot tolerance, so T within exp(10 tol) - 1 = 2.0 % relative */
    check_close("shader sheet transmittance vs the core (relative)", worst_sheet, 0.0,
                exp(10.0 * SOAK_EXPORT_KNOT_TOL) - 1.0 + FLOAT_EPS);
}

_Static_assert(SOAK_VIEW_N == SOAK_EXPORT_VIEW_N, "the shaders' view grid is the export's");

static void test_view(const soak_preset_db *db, const soak_osl_tables *t)
{
    double worst = 0.0;
    soak_status st = SOAK_OK;
    for (int pi = 0; pi < t->n_presets; ++pi) {
        const soak_preset *p = soak_presets_at(db, t->preset.v[pi]);
        for (int li = 0; li < t->n_liquids && st == SOAK_OK; ++li) {
            const soak_liquid *l = soak_presets_liquid_at(db, li);
            const int k = pi * t->n_liquids + li, off = t->k_off.v[k], n = t->k_n.v[k];
            for (int s = 0; s <= 60 && st == SOAK_OK; ++s) {
                const double L = (s + 0.29) / 60.29;
                soak_wet_input in = soak_wet_input_steady(p, L);
                soak_wet_params w;
                if ((st = soak_wetness_eval(p, l, &in, &w)) != SOAK_OK) break;
                for (double deg = 0.0; deg <= 75.001 && st == SOAK_OK; deg += 7.5) {
                    const double mu = cos(deg * SOAK_PI / 180);
                    soak_rgb dir, total;
                    if ((st = soak_wetness_albedo_sun(p, l, &w, mu, &dir, &total)) != SOAK_OK) break;
                    for (int c = 0; c < 3; ++c) {
                        float colour = soak_interp(t->kw.v, off, n, (float)L, t->ka.v, 3 * off + c, 3);
                        float view = soak_view_lookup(t->kw.v, off, n, (float)L, t->kv.v, 3 * SOAK_VIEW_N * off + c,
                                                      (float)mu);
                        worst = fmax(worst, fabs(colour * view - soak_rgb_at(dir, c)));
                    }
                }
            }
        }
    }
    check_status("core evaluations (view)", st, SOAK_OK);
    check_close("shader WetColor x View vs the core's directional albedo (views to 75 deg)", worst, 0.0,
                SOAK_EXPORT_KNOT_TOL + FLOAT_EPS);
}

int main(void)
{
    soak_preset_db *db = NULL;
    char err[512];
    if (!check_status("load presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return check_finish();
    soak_osl_tables t;
    if (check_status("build the shader tables", soak_osl_tables_build(db, 0, &t), SOAK_OK)) {
        check_true("one table per preset and liquid",
                   t.k_off.n == soak_presets_count(db) * soak_presets_liquid_count(db) && t.bg_off.n == 3 * t.k_off.n);
        test_schedule(soak_presets_at(db, 0), soak_presets_liquid_at(db, 0));
        test_fresnel();
        test_tables(db, &t);
        test_view(db, &t);
        soak_osl_tables_free(&t);
    }
    /* soak_wet_sheet.osl's tables: the thin sheets only, the same values */
    if (check_status("build the sheet shader's tables", soak_osl_tables_build(db, 1, &t), SOAK_OK)) {
        int sheets = 0;
        for (int i = 0; i < soak_presets_count(db); ++i) sheets += soak_presets_at(db, i)->kind == SOAK_KIND_THIN_SHEET;
        check_true("the sheet tables hold every thin sheet and nothing else", t.n_presets == sheets && sheets >= 2);
        for (int i = 0; i < t.n_presets; ++i)
            check_true("a kept preset is a thin sheet", soak_presets_at(db, t.preset.v[i])->kind == SOAK_KIND_THIN_SHEET);
        test_tables(db, &t);
        soak_osl_tables_free(&t);
    }
    soak_presets_free(db);
    return check_finish();
}
