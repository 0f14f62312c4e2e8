/* Every preset at every wetness, through the models a renderer would use
 * with the parameters soak_wetness_eval produces: reciprocity on random
 * direction pairs and energy (directional albedo <= 1 by quadrature), per
 * colour channel; and the mapping's own outputs stay physical (albedos in
 * [0,1], roughness and phase in range). */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "testutil.h"
#include "soak/models.h"
#include "soak/preset.h"
#include "soak/wetness.h"

/* Midpoint rule in (mu^(1/2), phi), cells concentrated near the horizon. */
static double albedo(const soak_model *m, const soak_model_ctx *ctx, soak_vec3 wi)
{
    const int NU = 48, NP = 96;
    double sum = 0;
    for (int a = 0; a < NU; ++a) {
        double u0 = (double)a / NU, u1 = (double)(a + 1) / NU, u = 0.5 * (u0 + u1), mu = u * u;
        double dmu = u1 * u1 - u0 * u0, s = sqrt(fmax(0, 1 - mu * mu));
        for (int b = 0; b < NP; ++b) {
            double phi = 2 * SOAK_PI * (b + 0.5) / NP, f = 0;
            /* a failed evaluation makes the albedo NaN, which fails "<= 1" */
            if (soak_model_eval(m, ctx, wi, soak_v3(s * cos(phi), s * sin(phi), mu), &f) != SOAK_OK) return NAN;
            sum += f * mu * dmu * (2 * SOAK_PI / NP);
        }
    }
    return sum;
}

static int in01(soak_rgb c) { return c.r >= 0 && c.r <= 1 && c.g >= 0 && c.g <= 1 && c.b >= 0 && c.b <= 1; }

int main(void)
{
    tu_rng rng = tu_xorshift64(0x853c49e6748fea9bull);
    soak_preset_db *db = NULL;
    char err[1024];
    if (!check_status("load presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) {
        printf("%s\n", err);
        return check_finish();
    }
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    const double ws[] = {0.0, 0.2, 0.4, 0.6, 0.8, 1.0};
    for (int i = 0; i < soak_presets_count(db); ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        int conductor = p->kind == SOAK_KIND_CONDUCTOR;
        const char *names[] = {"film-ctx", "ww", "porous-ggx", conductor ? "ggx-conductor" : "ggx-dielectric"};
        double worst_rec = 0, worst_albedo = 0, model_max[4] = {0, 0, 0, 0};
        int mapping_ok = 1, setups = 0, setup_fail = 0, eval_fail = 0, n_models = conductor ? 2 : 4;
        for (int k = 0; k < 6; ++k) {
            soak_wet_input in = soak_wet_input_steady(p, ws[k]);
            soak_wet_params wp;
            if (soak_wetness_eval(p, water, &in, &wp) != SOAK_OK) {
                mapping_ok = 0;
                setup_fail += 3 * n_models;
                continue;
            }
            mapping_ok &= in01(wp.albedo) && in01(wp.albedo_total) && wp.ggx_alpha >= 1e-4 && wp.ggx_alpha <= 1 &&
                          wp.fill >= 0 && wp.fill <= 1 && soak_hg2_validate(&wp.phase) == SOAK_OK;
            for (int c = 0; c < 3; ++c) {
                soak_model_params mp;
                soak_model_params_default(&mp);
                mp.albedo = soak_rgb_at(wp.albedo, c);
                mp.roughness = wp.ggx_alpha;
                mp.ior = conductor ? soak_rgb_at(p->ior_n, c) : p->ior;
                mp.k = conductor ? soak_rgb_at(p->ior_k, c) : 0.0;
                mp.n_film = wp.film ? wp.film_ior : 1.0;
                mp.absorption = soak_rgb_at(wp.film_absorption_per_m, c);
                mp.thickness = wp.film_thickness_m;
                mp.porosity = p->porosity;
                mp.sp = p->s_p;
                mp.fill = wp.fill;
                for (int m = conductor ? 1 : 0; m < 4; m += (conductor && m == 1) ? 2 : 1) {
                    const soak_model *model = soak_model_find(names[m]);
                    soak_model_ctx ctx;
                    if (model->setup(&mp, &ctx) != SOAK_OK) {
                        ++setup_fail;
                        continue;
                    }
                    ++setups;
                    for (int r = 0; r < 200; ++r) {
                        soak_vec3 a = tu_upper_dir(&rng, 0.0), b = tu_upper_dir(&rng, 0.0);
                        double f1 = NAN, f2 = NAN;
                        eval_fail += soak_model_eval(model, &ctx, a, b, &f1) != SOAK_OK;
                        eval_fail += soak_model_eval(model, &ctx, b, a, &f2) != SOAK_OK;
                        worst_rec = fmax(worst_rec, fabs(f1 - f2) / fmax(fmax(f1, f2), 1e-3));
                    }
                    const double th[] = {0, 60, 88};
                    for (int t = 0; t < 3; ++t)
                        {
                        double e = albedo(model, &ctx, soak_v3_polar(th[t] * SOAK_PI / 180, 0));
                        worst_albedo = e == e ? fmax(worst_albedo, e) : INFINITY;
                        model_max[m] = fmax(model_max[m], e);
                    }
                }
            }
        }
        char what[160];
        snprintf(what, sizeof what, "%s: wetness mapping in range at w = 0..1", p->name);
        check_true(what, mapping_ok);
        snprintf(what, sizeof what, "%s: every model sets up at every wetness and channel (%d of %d)", p->name,
                 setups, 6 * 3 * n_models);
        check_true(what, setup_fail == 0 && setups == 6 * 3 * n_models);
        snprintf(what, sizeof what, "%s: model evaluations that failed", p->name);
        check_close(what, eval_fail, 0, 0);
        snprintf(what, sizeof what, "%s: reciprocity over all wetness (max rel diff)", p->name);
        check_close(what, worst_rec, 0.0, 1e-6);
        snprintf(what, sizeof what, "%s: directional albedo <= 1 over all wetness (max %.5f)", p->name, worst_albedo);
        check_true(what, worst_albedo <= 1.0 + 3e-3);
        /* an all-zero model passes the two checks above: each must reflect */
        for (int m = conductor ? 1 : 0; m < 4; m += (conductor && m == 1) ? 2 : 1) {
            snprintf(what, sizeof what, "%s / %s: reflects something (max directional albedo %.4f > 0.01)", p->name,
                     names[m], model_max[m]);
            check_true(what, model_max[m] > 0.01);
        }
    }
    soak_presets_free(db);
    return check_finish();
}
