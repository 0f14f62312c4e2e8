/* The traced film's eval / pdf contract (soak/bsdf.h, bsdf_walk.c) and what
 * every BSDF promises its callers. References, each independent of the
 * estimator under test:
 *  - over Lambert the film has a closed form (Lekner & Dorf 1988, soak/film.h,
 *    the BSDF without film_traced): the mean of the stochastic f at fixed
 *    direction pairs, with and without absorption, equals it within 4
 *    standard errors (+ 1e-9 for the rounding of the two forms);
 *  - reciprocity in the mean: f(i, o) and f(o, i) estimated independently
 *    agree within 4 combined standard errors (over a rough conductor, which
 *    has no closed form);
 *  - variance: the standard error eval_mean reports is the spread of
 *    independent batch means (a second estimate of the same variance): their
 *    ratio within the chi-square bounds of 40 batches (0.55 .. 1.55, two-sided
 *    p ~ 1e-3), and one estimate's relative standard deviation below 1.5
 *    (measured 0.61 over Lambert, 0.13 over GGX: a light sample's noise
 *    stays below that of the BSDF sample it is weighed against);
 *  - soak_bsdf_pdf gives exactly eval's pdf (its cheap path) for every kind;
 *  - on an error return nothing is written (status.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "soak/bsdf.h"
#include "testutil.h"

static soak_vec3 dir_at(double cos_t, double phi)
{
    double s = sqrt(1 - cos_t * cos_t);
    return soak_v3(s * cos(phi), s * sin(phi), cos_t);
}

static int film_pair(soak_bsdf *traced, soak_bsdf *closed, double albedo, double absorption, double thickness)
{
    soak_bsdf_desc d;
    soak_bsdf_desc_default(&d, SOAK_BSDF_LAMBERT);
    d.albedo = soak_rgb3(albedo, albedo, albedo), d.film_ior = 1.333;
    d.film_absorption = soak_rgb3(absorption, 0.5 * absorption, 0), d.film_thickness = thickness;
    int ok = check_status("closed film set-up", soak_bsdf_setup(&d, closed), SOAK_OK);
    d.film_traced = 1;
    return check_status("traced film set-up", soak_bsdf_setup(&d, traced), SOAK_OK) && ok;
}

static void test_mean_vs_closed_form(void)
{
    const double cases[2][3] = {{0.8, 0, 0}, {0.6, 0.5, 0.4}};
    const double pairs[4][3] = {{1.0, 0.9, 1.0}, {0.5, 0.95, 2.0}, {0.2, 0.4, 0.5}, {0.9, 0.15, 3.0}};
    for (int c = 0; c < 2; ++c) {
        soak_bsdf tr, cl;
        if (!film_pair(&tr, &cl, cases[c][0], cases[c][1], cases[c][2])) continue;
        for (int p = 0; p < 4; ++p) {
            soak_vec3 wo = dir_at(pairs[p][0], 0), wi = dir_at(pairs[p][1], pairs[p][2]);
            soak_rgb f, se, ref;
            if (!check_status("eval_mean", soak_bsdf_eval_mean(&tr, wi, wo, 40000, 11 + p, &f, &se, NULL), SOAK_OK) ||
                !check_status("closed eval", soak_bsdf_eval(&cl, wi, wo, &ref, NULL), SOAK_OK))
                continue;
            for (int ch = 0; ch < 3; ++ch) {
                double m = soak_rgb_at(f, ch), s = soak_rgb_at(se, ch), r = soak_rgb_at(ref, ch);
                char what[200];
                snprintf(what, sizeof what,
                         "albedo %.1f, absorption %.2f: cos_o %.2f cos_i %.2f ch %d: traced f %.6f +- %.6f = Lekner-Dorf %.6f",
                         cases[c][0], cases[c][1] * cases[c][2], pairs[p][0], pairs[p][1], ch, m, s, r);
                if (ch == 0) printf("  %s\n", what);
                check_true(what, fabs(m - r) <= 4 * s + 1e-9);
            }
        }
    }
}

static int ggx_film(soak_bsdf *b)
{
    soak_bsdf_desc d;
    soak_bsdf_desc_default(&d, SOAK_BSDF_GGX_CONDUCTOR);
    d.eta = soak_rgb3(0.2, 0.9, 1.1), d.k = soak_rgb3(3.9, 2.4, 2.2), d.alpha = 0.35, d.film_ior = 1.333;
    d.film_absorption = soak_rgb3(0.1, 0.2, 0.3), d.film_thickness = 0.5;
    return check_status("film over ggx set-up", soak_bsdf_setup(&d, b), SOAK_OK);
}

static void test_reciprocal_in_the_mean(void)
{
    soak_bsdf b;
    if (!ggx_film(&b)) return;
    soak_vec3 a = dir_at(0.8, 0.3), c = dir_at(0.35, 2.9);
    soak_rgb f1, f2, s1, s2;
    if (soak_bsdf_eval_mean(&b, a, c, 40000, 1, &f1, &s1, NULL) != SOAK_OK ||
        soak_bsdf_eval_mean(&b, c, a, 40000, 2, &f2, &s2, NULL) != SOAK_OK) {
        check_true("film over ggx: eval_mean", 0);
        return;
    }
    double d = fabs(f1.g - f2.g), bound = 4 * sqrt(s1.g * s1.g + s2.g * s2.g);
    char what[200];
    snprintf(what, sizeof what, "film over ggx: f(i,o) %.6f +- %.6f = f(o,i) %.6f +- %.6f in the mean", f1.g, s1.g, f2.g,
             s2.g);
    printf("  %s\n", what);
    check_true(what, d <= bound && f1.g > 0);
}

/* Reported standard error vs the spread of batch means, and one estimate's spread. */
static void check_variance(const char *name, const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    enum { BATCHES = 40, PER = 500 };
    double m[BATCHES], sum = 0, se2 = 0;
    for (int k = 0; k < BATCHES; ++k) {
        soak_rgb f, se;
        if (soak_bsdf_eval_mean(b, wi, wo, PER, 1000 + k, &f, &se, NULL) != SOAK_OK) return (void)check_true(name, 0);
        m[k] = f.g, sum += f.g, se2 += se.g * se.g / BATCHES;
    }
    double mean = sum / BATCHES, var = 0;
    for (int k = 0; k < BATCHES; ++k) var += (m[k] - mean) * (m[k] - mean) / (BATCHES - 1);
    double ratio = var / se2, rel_sd = sqrt(se2 * PER) / mean;
    char what[200];
    snprintf(what, sizeof what, "%s: batch-mean variance / reported se^2 = %.3f in [0.55, 1.55]", name, ratio);
    printf("  %s\n", what);
    check_true(what, ratio >= 0.55 && ratio <= 1.55);
    snprintf(what, sizeof what, "%s: one estimate's relative sd %.3f < 1.5", name, rel_sd);
    printf("  %s\n", what);
    check_true(what, rel_sd < 1.5);
}

static void test_variance(void)
{
    soak_bsdf tr, cl, g;
    if (film_pair(&tr, &cl, 0.8, 0, 0)) check_variance("film over lambert", &tr, dir_at(0.7, 1.0), dir_at(0.6, 0));
    if (ggx_film(&g)) check_variance("film over ggx", &g, dir_at(0.7, 3.0), dir_at(0.6, 0));
}

static void test_pdf_is_evals(void)
{
    soak_bsdf_desc d[5];
    const char *names[5] = {"lambert", "ggx", "coated", "film/lambert", "film/ggx traced"};
    soak_bsdf_desc_default(&d[0], SOAK_BSDF_LAMBERT);
    soak_bsdf_desc_default(&d[1], SOAK_BSDF_GGX_DIELECTRIC);
    soak_bsdf_desc_default(&d[2], SOAK_BSDF_COATED);
    soak_bsdf_desc_default(&d[3], SOAK_BSDF_LAMBERT);
    d[3].film_ior = 1.333;
    soak_bsdf_desc_default(&d[4], SOAK_BSDF_GGX_CONDUCTOR);
    d[4].film_ior = 1.333;
    tu_rng rng = tu_splitmix64(5);
    for (int k = 0; k < 5; ++k) {
        soak_bsdf b;
        if (!check_status(names[k], soak_bsdf_setup(&d[k], &b), SOAK_OK)) continue;
        int same = 1;
        for (int i = 0; i < 200; ++i) {
            soak_vec3 wi = tu_upper_dir(&rng, 0.02), wo = tu_upper_dir(&rng, 0.02);
            soak_rgb f;
            double p1 = -1, p2 = -2;
            if (soak_bsdf_eval(&b, wi, wo, &f, &p1) != SOAK_OK || soak_bsdf_pdf(&b, wi, wo, &p2) != SOAK_OK || p1 != p2)
                same = 0;
        }
        char what[160];
        snprintf(what, sizeof what, "%s: soak_bsdf_pdf = eval's pdf at 200 pairs", names[k]);
        check_true(what, same);
    }
}

/* status.h: on an error return the outputs are as they were. */
static void test_outputs_untouched(void)
{
    soak_bsdf b;
    soak_bsdf_desc d;
    soak_bsdf_desc_default(&d, SOAK_BSDF_GGX_CONDUCTOR);
    d.film_ior = 1.333;
    if (!check_status("set-up", soak_bsdf_setup(&d, &b), SOAK_OK)) return;
    soak_bsdf_sample s, before;
    memset(&s, 0x5a, sizeof s);
    before = s;
    int ok = 7;
    double u_bad[3] = {0.5, NAN, 0.5}, u[3] = {0.5, 0.5, 0.5};
    check_status("sample rejects NaN u", soak_bsdf_sample_dir(&b, dir_at(0.5, 0), u_bad, &s, &ok), SOAK_ERR_ARG);
    check_status("sample rejects a non-unit wo", soak_bsdf_sample_dir(&b, soak_v3(0, 0, 2), u, &s, &ok), SOAK_ERR_ARG);
    check_true("sample_dir: outputs untouched on error", ok == 7 && memcmp(&s, &before, sizeof s) == 0);
    soak_rgb f = soak_rgb3(-1, -1, -1), se = f;
    double pdf = -1;
    check_status("eval rejects NaN", soak_bsdf_eval(&b, soak_v3(NAN, 0, 1), dir_at(0.5, 0), &f, &pdf), SOAK_ERR_ARG);
    check_status("pdf rejects non-unit", soak_bsdf_pdf(&b, soak_v3(0, 0, 3), dir_at(0.5, 0), &pdf), SOAK_ERR_ARG);
    check_status("eval_mean rejects n = 0", soak_bsdf_eval_mean(&b, dir_at(0.5, 1), dir_at(0.5, 0), 0, 1, &f, &se, NULL),
                 SOAK_ERR_ARG);
    check_true("eval / pdf / eval_mean: outputs untouched on error", f.r == -1 && f.g == -1 && se.b == -1 && pdf == -1);
    check_status("pdf needs its output", soak_bsdf_pdf(&b, dir_at(0.5, 1), dir_at(0.5, 0), NULL), SOAK_ERR_NULL);
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    test_outputs_untouched();
    test_pdf_is_evals();
    test_mean_vs_closed_form();
    test_reciprocal_in_the_mean();
    test_variance();
    return check_finish();
}
