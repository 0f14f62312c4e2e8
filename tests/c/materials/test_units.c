/* The unit boundary (soak/units.h): a preset file in mm and 1/mm is read into
 * the core's SI once and written back in mm once. Checked here against
 * closed forms evaluated in metres by the test itself, from the numbers
 * written in the file converted here (1 mm = 1e-3 m):
 *  - a conductor under a film of an absorbing liquid: the incoherent film
 *    at normal incidence, Beer-Lambert over the two passes (soak/wetness.h
 *    step 5), e = exp(-2 sigma_a h) with sigma_a in 1/m and h in m;
 *  - a thin sheet, index matched: the Kubelka-Munk slab (Kubelka 1948; van
 *    Gemert & Star 1987's K, S) with the transport coefficients in 1/m and
 *    the thickness in m, omega from van de Hulst's albedo inverted here by
 *    bisection; dry, and wet with the liquid's coefficients mixed in by
 *    volume (Beer-Lambert for a mixture, step 3);
 *  - `soak materials --json` (soak_wetness_export_json) prints the file's
 *    mm and 1/mm values back unchanged.
 * Dropping any one conversion (loader or writer) moves these by orders of
 * magnitude. */
#define _POSIX_C_SOURCE 200809L
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "soak/preset.h"
#include "soak/sheet.h"
#include "soak/units.h"
#include "soak/wetness.h"

#define FILM_MM 0.37
#define SHEET_MM 0.23
static const double sigma_t_mm[3] = {3.7, 5.1, 9.3};
static const double ink_a_mm[3] = {0.41, 0.0123, 1.7};
static const double ink_s_mm[3] = {0.2, 0.0, 0.05};
static const double sheet_albedo[3] = {0.79, 0.55, 0.31};
#define POROSITY 0.45
#define INK_IOR 1.333

static const char *const preset_json =
    "{\"format\": \"soak-materials\", \"version\": 1, \"description\": \"units test\",\n"
    " \"materials\": [\n"
    "  {\"name\": \"cu\", \"display_name\": \"Cu\", \"kind\": \"conductor\",\n"
    "   \"albedo\": {\"rgb\": [0.708357, 0.641305, 0.608869], \"source\": \"s\"},\n"
    "   \"roughness\": {\"ggx_alpha_dry\": 0.05, \"source\": \"s\"},\n"
    "   \"ior\": {\"n\": [3.406149, 2.1616, 1.504326], \"k\": [5.225178, 3.756258, 3.018729], \"source\": \"s\"},\n"
    "   \"wetting\": {\"film_thickness_mm\": 0.37, \"source\": \"s\"}},\n"
    "  {\"name\": \"sheet\", \"display_name\": \"Sheet\", \"kind\": \"thin_sheet\",\n"
    "   \"albedo\": {\"rgb\": [0.79, 0.55, 0.31], \"source\": \"s\"},\n"
    "   \"roughness\": {\"ggx_alpha_dry\": 0.6, \"ggx_alpha_wet\": 0.3, \"source\": \"s\"},\n"
    "   \"ior\": {\"n\": 1.0, \"source\": \"s\"},\n"
    "   \"porosity\": {\"alpha\": 0.45, \"s_p\": 1.0, \"source\": \"s\"},\n"
    "   \"medium\": {\"sigma_t_per_mm\": [3.7, 5.1, 9.3], \"source\": \"s\"},\n"
    "   \"phase\": {\"dry\": {\"g1\": 0.3, \"g2\": -0.1, \"w\": 0.6}, \"wet\": {\"g1\": 0.8, \"g2\": 0.1, \"w\": 0.7},"
    " \"source\": \"s\"},\n"
    "   \"wetting\": {\"t_fill\": 0.1, \"film_thickness_mm\": 0.37, \"source\": \"s\"},\n"
    "   \"sheet\": {\"thickness_mm\": 0.23, \"source\": \"s\"}}\n"
    " ],\n"
    " \"liquids\": [{\"name\": \"ink\", \"display_name\": \"Ink\", \"ior\": 1.333,\n"
    "   \"sigma_a_per_mm\": [0.41, 0.0123, 1.7], \"sigma_s_per_mm\": [0.2, 0, 0.05], \"source\": \"s\"}]\n"
    "}\n";

/* Normal-incidence reflectance of index n + i k against a medium of index 1 (Born & Wolf). */
static double f0(double n, double k) { return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k); }

/* van de Hulst 1980 semi-infinite albedo, and its inverse in omega by bisection. */
static double vdh_albedo(double omega, double g)
{
    double s = sqrt((1.0 - omega) / (1.0 - g * omega));
    return (1.0 - s) * (1.0 - 0.139 * s) / (1.0 + 1.17 * s);
}
static double vdh_omega(double albedo, double g)
{
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
        double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        if (vdh_albedo(mid, g) < albedo) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* Kubelka-Munk slab transmittance, T = 1 / (cosh(b S d) + a/b sinh(b S d)), a = (S+K)/S, b = sqrt(a^2 - 1);
 * a pure absorber (S <= 0, clamped as sheet.h does) gives exp(-K d). */
static double km_transmittance(double K, double S, double d)
{
    if (S <= 0.0) return exp(-K * d);
    double a = (S + K) / S, b = sqrt(a * a - 1.0), x = b * S * d;
    return 1.0 / (cosh(x) + a / b * sinh(x));
}

static double mm_to_m(double mm) { return mm * 1e-3; }

static soak_preset_db *load(void)
{
    char dir[] = "/tmp/soak_test_units_XXXXXX", path[512], err[1024] = "";
    if (!mkdtemp(dir)) return NULL;
    snprintf(path, sizeof path, "%s/units.json", dir);
    FILE *f = fopen(path, "w");
    soak_preset_db *db = NULL;
    if (f && fputs(preset_json, f) >= 0 && fclose(f) == 0) {
        if (soak_presets_load(path, &db, err, sizeof err) != SOAK_OK) printf("  %s\n", err);
    } else if (f) {
        fclose(f);
    }
    remove(path);
    rmdir(dir);
    return db;
}

static void check_conductor_film(const soak_preset *cu, const soak_liquid *ink)
{
    soak_wet_input in = soak_wet_input_steady(cu, 1.0);
    soak_wet_params w;
    if (!check_status("copper under ink, wetness 1", soak_wetness_eval(cu, ink, &in, &w), SOAK_OK)) return;
    const double h = mm_to_m(FILM_MM), r12 = f0(INK_IOR, 0.0);
    for (int c = 0; c < 3; ++c) {
        double sigma_a = ink_a_mm[c] * 1e3; /* 1/m */
        double e = exp(-2.0 * sigma_a * h);
        double r23 = f0(soak_rgb_at(cu->ior_n, c) / INK_IOR, soak_rgb_at(cu->ior_k, c) / INK_IOR);
        double want = (1 - r12) * (1 - r12) * r23 * e / (1 - r12 * r23 * e);
        char what[160];
        snprintf(what, sizeof what, "copper under %.2g mm of ink [%d]: Beer-Lambert film, e = %.4f", FILM_MM, c, e);
        check_rel(what, soak_rgb_at(w.albedo, c), want, 1e-12);
    }
}

/* Step 3's coefficients in 1/m and the Kubelka-Munk slab in m at wetness 0 or 1. */
static void check_sheet(const soak_preset *p, const soak_liquid *ink, int wet)
{
    soak_wet_input in = soak_wet_input_steady(p, wet);
    soak_wet_params w;
    soak_rgb T;
    char what[200];
    snprintf(what, sizeof what, "sheet, wetness %d", wet);
    if (!check_status(what, soak_wetness_eval(p, ink, &in, &w), SOAK_OK)) return;
    if (!check_status(what, soak_sheet_transmittance(&w, p->thickness_m, p->ior, &T), SOAK_OK)) return;
    const double g_dry = 0.6 * 0.3 + 0.4 * -0.1, g_wet = 0.7 * 0.8 + 0.3 * 0.1, g = wet ? g_wet : g_dry;
    const double d = mm_to_m(SHEET_MM), liquid = wet ? POROSITY : 0.0;
    for (int c = 0; c < 3; ++c) {
        double omega = vdh_omega(sheet_albedo[c], g_dry), st = sigma_t_mm[c] * 1e3;
        double ss = omega * st + liquid * ink_s_mm[c] * 1e3, sa = (1 - omega) * st + liquid * ink_a_mm[c] * 1e3;
        double K = 2.0 * sa, S = 0.75 * ss * (1.0 - g) - 0.25 * sa;
        double want = km_transmittance(K, S, d);
        snprintf(what, sizeof what, "sheet w=%d [%d]: sigma_a = %.6g 1/m (mixture)", wet, c, sa);
        check_rel(what, soak_rgb_at(w.sigma_a_per_m, c), sa, 1e-9);
        snprintf(what, sizeof what, "sheet w=%d [%d]: sigma_s = %.6g 1/m (mixture)", wet, c, ss);
        check_rel(what, soak_rgb_at(w.sigma_s_per_m, c), ss, 1e-9);
        snprintf(what, sizeof what, "sheet w=%d [%d]: Kubelka-Munk T over %.2g mm, tau %.3f", wet, c, SHEET_MM,
                 (ss + sa) * d);
        check_rel(what, soak_rgb_at(T, c), want, 1e-9);
    }
}

static int rgb_is(const cJSON *a, const double want[3])
{
    if (!cJSON_IsArray(a) || cJSON_GetArraySize(a) != 3) return 0;
    for (int i = 0; i < 3; ++i) {
        const cJSON *v = cJSON_GetArrayItem(a, i);
        if (!cJSON_IsNumber(v) || v->valuedouble != want[i]) return 0;
    }
    return 1;
}

static const cJSON *named(const cJSON *arr, const char *name)
{
    const cJSON *it;
    cJSON_ArrayForEach(it, arr)
    {
        const cJSON *n = cJSON_GetObjectItemCaseSensitive(it, "name");
        if (cJSON_IsString(n) && strcmp(n->valuestring, name) == 0) return it;
    }
    return NULL;
}

static double num(const cJSON *o, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

static void check_round_trip(const soak_preset_db *db)
{
    char *text = NULL;
    if (!check_status("materials --json", soak_wetness_export_json(db, "ink", 0, &text), SOAK_OK)) return;
    cJSON *root = cJSON_Parse(text);
    const cJSON *mats = cJSON_GetObjectItemCaseSensitive(root, "materials");
    const cJSON *cu = named(mats, "cu"), *sheet = named(mats, "sheet");
    const cJSON *ink = named(cJSON_GetObjectItemCaseSensitive(root, "liquids"), "ink");
    if (check_true("exported JSON has cu, sheet, ink", cu && sheet && ink)) {
        check_close("cu film_thickness_mm printed back", num(cu, "film_thickness_mm"), FILM_MM, 0.0);
        check_close("sheet film_thickness_mm printed back", num(sheet, "film_thickness_mm"), FILM_MM, 0.0);
        check_close("sheet thickness_mm printed back", num(sheet, "thickness_mm"), SHEET_MM, 0.0);
        check_true("sheet sigma_t_per_mm printed back [3.7, 5.1, 9.3]",
                   rgb_is(cJSON_GetObjectItemCaseSensitive(sheet, "sigma_t_per_mm"), sigma_t_mm));
        check_true("ink sigma_a_per_mm printed back [0.41, 0.0123, 1.7]",
                   rgb_is(cJSON_GetObjectItemCaseSensitive(ink, "sigma_a_per_mm"), ink_a_mm));
        check_true("ink sigma_s_per_mm printed back [0.2, 0, 0.05]",
                   rgb_is(cJSON_GetObjectItemCaseSensitive(ink, "sigma_s_per_mm"), ink_s_mm));
    }
    cJSON_Delete(root);
    free(text);
}

/* Every length a user writes with up to three decimals of a mm (0.001 to
 * 1000 mm), and every coefficient with up to four of a 1/mm, reads into SI
 * and prints back as the same %.15g text (cJSON's first choice). */
static void check_decimal_round_trips(void)
{
    long bad_len = 0, bad_coef = 0, n = 0;
    char a[40], b[40];
    for (long k = 1; k <= 1000000; ++k, ++n) {
        double mm = k / 1000.0, per_mm = k / 10000.0;
        snprintf(a, sizeof a, "%.15g", mm);
        snprintf(b, sizeof b, "%.15g", soak_mm_from_m(soak_m_from_mm(mm)));
        bad_len += strcmp(a, b) != 0;
        snprintf(a, sizeof a, "%.15g", per_mm);
        snprintf(b, sizeof b, "%.15g", soak_per_mm_from_per_m(soak_per_m_from_per_mm(per_mm)));
        bad_coef += strcmp(a, b) != 0;
    }
    printf("  %ld lengths and coefficients each: %ld and %ld print differently after mm -> SI -> mm\n", n, bad_len,
           bad_coef);
    check_true("decimal mm lengths survive mm -> m -> mm in print", bad_len == 0);
    check_true("decimal 1/mm coefficients survive 1/mm -> 1/m -> 1/mm in print", bad_coef == 0);
    check_close("1 mm is 1e-3 m", soak_m_from_mm(1.0), 1e-3, 0.0);
    check_close("1 /mm is 1000 /m", soak_per_m_from_per_mm(1.0), 1000.0, 0.0);
}

int main(void)
{
    check_decimal_round_trips();
    soak_preset_db *db = load();
    if (!check_true("load the test presets", db != NULL)) return check_finish();
    const soak_preset *cu = soak_presets_find(db, "cu"), *sheet = soak_presets_find(db, "sheet");
    const soak_liquid *ink = soak_presets_find_liquid(db, "ink");
    if (check_true("cu, sheet, ink loaded", cu && sheet && ink)) {
        check_conductor_film(cu, ink);
        check_sheet(sheet, ink, 0);
        check_sheet(sheet, ink, 1);
        check_round_trip(db);
    }
    soak_presets_free(db);
    return check_finish();
}
