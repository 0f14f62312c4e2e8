/* The view factor (soak_wetness_view_factor): the diffuse colour seen at a
 * view angle under uniform light, relative to the hemispherical albedo.
 *  - identity: its cosine-weighted mean over the hemisphere is 1 (the
 *    hemispherical albedo is the mean of the directional ones);
 *  - second method: fully wet under a water film, the base's multiple
 *    reflections are common to every direction, so the factor is the film's
 *    directional transmission (textbook Fresnel, Beer-Lambert along the
 *    refracted path) over its cosine-weighted mean, computed here;
 *  - dry surfaces and conductors: 1;
 *  - a user's own colour: the factor at the preset's colour stays within a
 *    stated bound of the factor at any grey dry albedo (front ends use the
 *    preset's);
 *  - bad input rejected, grazing view finite. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "soak/preset.h"
#include "soak/base_colour.h"
#include "soak/wetness.h"

/* docs/ACCURACY.md: the view factor's colour term, views up to 60 deg and up to 80 deg */
#define COLOUR_TERM_60 0.01
#define COLOUR_TERM_80 0.05

static double textbook_fresnel(double cos_i, double n)
{
    double sin_t = sqrt(fmax(0.0, 1.0 - cos_i * cos_i)) / n, cos_t = sqrt(1.0 - sin_t * sin_t);
    double rs = (cos_i - n * cos_t) / (cos_i + n * cos_t), rp = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

static double film_transmission(double cos_i, double n, double absorb_h)
{
    double sin_t = sqrt(fmax(0.0, 1.0 - cos_i * cos_i)) / n, cos_t = sqrt(1.0 - sin_t * sin_t);
    return (1.0 - textbook_fresnel(cos_i, n)) * exp(-absorb_h / cos_t);
}

static int eval_at(const soak_preset *p, const soak_liquid *l, double wetness, soak_wet_params *w)
{
    soak_wet_input in = soak_wet_input_steady(p, wetness);
    return soak_wetness_eval(p, l, &in, w) == SOAK_OK;
}

static void check_normalised(const soak_preset_db *db, const soak_liquid *l)
{
    double worst = 0.0;
    for (int i = 0; i < soak_presets_count(db); ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        const double wets[] = {0.0, 0.5 * p->porosity, p->porosity, 0.6, 1.0};
        for (int j = 0; j < 5; ++j) {
            soak_wet_params w;
            if (!check_true("eval", eval_at(p, l, wets[j], &w))) continue;
            const int n = 400; /* midpoint rule in mu: ~1e-6 here, independent of film.c's quadrature */
            soak_rgb mean = {0, 0, 0};
            for (int k = 0; k < n; ++k) {
                double mu = (k + 0.5) / n;
                soak_rgb f;
                if (soak_wetness_view_factor(p, l, &w, mu, &f) != SOAK_OK) {
                    check_true("view factor evaluates", 0);
                    break;
                }
                mean = soak_rgb3(mean.r + 2 * mu * f.r / n, mean.g + 2 * mu * f.g / n, mean.b + 2 * mu * f.b / n);
            }
            worst = fmax(worst, fmax(fabs(mean.r - 1), fmax(fabs(mean.g - 1), fabs(mean.b - 1))));
        }
    }
    char what[160];
    snprintf(what, sizeof what, "%s: cosine-weighted mean of the view factor = 1 (worst %.2e)", l->name, worst);
    check_close(what, worst, 0.0, 5e-5);
}

static void check_full_film(const soak_preset_db *db, const soak_liquid *l)
{
    const char *names[] = {"sand", "brick", "asphalt", "oak"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k) {
        const soak_preset *p = soak_presets_find(db, names[k]);
        soak_wet_params w;
        if (!check_true("preset", p != NULL) || !check_true("eval", eval_at(p, l, 1.0, &w))) continue;
        double worst = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double ah = soak_rgb_at(w.film_absorption_per_m, c) * w.film_thickness_m;
            const int n = 4000;
            double mean = 0.0;
            for (int i = 0; i < n; ++i) {
                double mu = (i + 0.5) / n;
                mean += 2 * mu * film_transmission(mu, l->ior, ah) / n;
            }
            for (double mu = 0.05; mu <= 1.0; mu += 0.05) {
                soak_rgb f;
                if (!check_status("view factor", soak_wetness_view_factor(p, l, &w, mu, &f), SOAK_OK)) break;
                worst = fmax(worst, fabs(soak_rgb_at(f, c) - film_transmission(mu, l->ior, ah) / mean));
            }
        }
        char what[200];
        snprintf(what, sizeof what, "%s + %s fully wet: factor = film transmission / its mean (worst %.2e)",
                 p->name, l->name, worst);
        check_close(what, worst, 0.0, 2e-4);
    }
}

static void check_unity(const soak_preset_db *db, const soak_liquid *l)
{
    for (int i = 0; i < soak_presets_count(db); ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        const int conductor = p->kind == SOAK_KIND_CONDUCTOR;
        soak_wet_params w;
        if (!eval_at(p, l, conductor ? 1.0 : 0.0, &w)) continue;
        soak_rgb f;
        char what[160];
        snprintf(what, sizeof what, "%s %s: view factor 1 at 70 deg", p->name, conductor ? "wet conductor" : "dry");
        if (check_status(what, soak_wetness_view_factor(p, l, &w, cos(70 * SOAK_PI / 180), &f), SOAK_OK))
            check_true(what, f.r == 1.0 && f.g == 1.0 && f.b == 1.0);
    }
}

/* The factor at the preset's own colour against the factor at grey dry
 * albedos 0.02 ... 0.98 (what a user's texture gives), views 0-80 deg. */
static double colour_term(const soak_preset *p, const soak_liquid *l, double wet, double max_deg)
{
    soak_wet_params own;
    if (!eval_at(p, l, wet, &own)) return INFINITY;
    soak_wet_input in = soak_wet_input_steady(p, wet);
    double worst = 0.0;
    for (double a = 0.02; a < 0.99; a += 0.12) {
        soak_wet_params user;
        if (soak_wet_params_for_base(p, l, &in, soak_rgb3(a, a, a), &user) != SOAK_OK) return INFINITY;
        for (double deg = 0; deg <= max_deg + 1e-9; deg += 10) {
            soak_rgb f_own, f_user;
            double mu = cos(deg * SOAK_PI / 180);
            if (soak_wetness_view_factor(p, l, &own, mu, &f_own) != SOAK_OK ||
                soak_wetness_view_factor(p, l, &user, mu, &f_user) != SOAK_OK)
                return INFINITY;
            worst = fmax(worst, fabs(f_own.g - f_user.g));
        }
    }
    return worst;
}

/* The factor at the preset's own colour against the factor at grey dry
 * albedos 0.02 ... 0.98 (what a user's texture gives). */
static void check_colour_term(const soak_preset_db *db, const soak_liquid *l)
{
    const double max_deg[2] = {60, 80}, bound[2] = {COLOUR_TERM_60, COLOUR_TERM_80};
    for (int k = 0; k < 2; ++k) {
        double worst = 0.0;
        for (int i = 0; i < soak_presets_count(db); ++i) {
            const soak_preset *p = soak_presets_at(db, i);
            if (p->kind == SOAK_KIND_CONDUCTOR) continue;
            for (int j = 1; j <= 20; ++j) worst = fmax(worst, colour_term(p, l, j / 20.0, max_deg[k]));
        }
        char what[200];
        snprintf(what, sizeof what, "%s: factor at the preset's colour vs any grey, views to %.0f deg (worst %.4f)",
                 l->name, max_deg[k], worst);
        check_close(what, worst, 0.0, bound[k]);
    }
}

static void check_inputs(const soak_preset_db *db, const soak_liquid *l)
{
    const soak_preset *sand = soak_presets_find(db, "sand");
    soak_wet_params w;
    soak_rgb f;
    if (!sand || !eval_at(sand, l, 1.0, &w)) return;
    check_status("cos_o NaN rejected", soak_wetness_view_factor(sand, l, &w, NAN, &f), SOAK_ERR_ARG);
    check_status("cos_o > 1 rejected", soak_wetness_view_factor(sand, l, &w, 1.0 + 1e-9, &f), SOAK_ERR_ARG);
    check_status("cos_o < 0 rejected", soak_wetness_view_factor(sand, l, &w, -0.1, &f), SOAK_ERR_ARG);
    check_status("NULL factor rejected", soak_wetness_view_factor(sand, l, &w, 0.5, NULL), SOAK_ERR_NULL);
    check_status("NULL params rejected", soak_wetness_view_factor(sand, l, NULL, 0.5, &f), SOAK_ERR_NULL);
    if (check_status("grazing view evaluates", soak_wetness_view_factor(sand, l, &w, 0.0, &f), SOAK_OK))
        check_true("grazing: finite, no light out along the surface", isfinite(f.g) && f.g >= 0 && f.g < 1e-6);
    if (check_status("normal view", soak_wetness_view_factor(sand, l, &w, 1.0, &f), SOAK_OK))
        check_true("normal view of a wet surface: brighter than the hemispherical mean", f.g > 1.0);
}

int main(void)
{
    soak_preset_db *db = NULL;
    char err[512];
    if (!check_status("load shipped presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) {
        printf("%s\n", err);
        return check_finish();
    }
    const char *liquids[] = {"water", "coffee"};
    for (size_t i = 0; i < 2; ++i) {
        const soak_liquid *l = soak_presets_find_liquid(db, liquids[i]);
        if (!check_true("liquid present", l != NULL)) continue;
        check_normalised(db, l);
        check_full_film(db, l);
        check_unity(db, l);
        check_colour_term(db, l);
        check_inputs(db, l);
    }
    soak_presets_free(db);
    return check_finish();
}
