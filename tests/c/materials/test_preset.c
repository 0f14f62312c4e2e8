/* Preset loader: the shipped file against the sources' published numbers and
 * independent formulas; malformed files written here must fail with the
 * right status and a message naming the JSON path. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "soak/preset.h"

/* van de Hulst 1980 semi-infinite albedo, written here from the formula. */
static double vdh_albedo(double omega, double g)
{
    double s = sqrt((1.0 - omega) / (1.0 - g * omega));
    return (1.0 - s) * (1.0 - 0.139 * s) / (1.0 + 1.17 * s);
}

/* Normal-incidence reflectance of a conductor, Born & Wolf. */
static double f0(double n, double k) { return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k); }

static void check_shipped(void)
{
    soak_preset_db *db = NULL;
    char err[1024] = "";
    soak_status st = soak_presets_load(NULL, &db, err, sizeof err);
    if (!check_status("load shipped materials.json", st, SOAK_OK)) {
        printf("  %s\n", err);
        return;
    }
    check_true("at least 12 presets", soak_presets_count(db) >= 12);
    static const char *const required[] = {"sand", "clay", "brick", "concrete", "asphalt", "limestone",
                                           "paper", "cotton", "oak", "marble", "copper", "aluminium"};
    for (size_t i = 0; i < sizeof required / sizeof required[0]; ++i) {
        char what[96];
        snprintf(what, sizeof what, "preset '%s' present", required[i]);
        check_true(what, soak_presets_find(db, required[i]) != NULL);
    }
    check_true("unknown name -> NULL", soak_presets_find(db, "unobtainium") == NULL);
    check_true("index -1 -> NULL", soak_presets_at(db, -1) == NULL);
    check_true("index count -> NULL", soak_presets_at(db, soak_presets_count(db)) == NULL);

    for (int i = 0; i < soak_presets_count(db); ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        char what[160];
        int ok = p->name[0] && p->display_name[0] && p->albedo_source[0] && p->roughness_source[0] &&
                 p->ior_source[0] && p->wetting_source[0];
        for (int c = 0; c < 3; ++c) ok = ok && soak_in_range(soak_rgb_at(p->albedo, c), 0, 1);
        ok = ok && soak_in_range(p->ggx_alpha_dry, 1e-4, 1) && soak_in_range(p->ggx_alpha_wet, 1e-4, p->ggx_alpha_dry);
        ok = ok && soak_in_range(p->t_fill, 0, 1e6) && soak_in_range(p->film_thickness_m, 0, 1);
        /* issue 48 item 4: every shipped preset states water's contact angle, with its source */
        ok = ok && soak_in_range(p->contact_angle_deg, 0, 180) && p->contact_angle_source &&
             p->contact_angle_source[0];
        if (p->kind == SOAK_KIND_CONDUCTOR) {
            for (int c = 0; c < 3; ++c) {
                double want = f0(soak_rgb_at(p->ior_n, c), soak_rgb_at(p->ior_k, c));
                snprintf(what, sizeof what, "%s albedo[%d] = F0(n,k) (Born & Wolf)", p->name, c);
                check_close(what, soak_rgb_at(p->albedo, c), want, 2e-3);
            }
        } else {
            ok = ok && soak_in_range(p->ior, 1, 3) && p->medium_source[0] && p->phase_source[0];
            double g = p->phase_dry.w * p->phase_dry.g1 + (1 - p->phase_dry.w) * p->phase_dry.g2;
            for (int c = 0; c < 3; ++c) {
                double om = soak_rgb_at(p->omega_dry, c);
                snprintf(what, sizeof what, "%s: van de Hulst R(omega_dry[%d]) = dry albedo", p->name, c);
                check_close(what, vdh_albedo(om, g), soak_rgb_at(p->albedo, c), 1e-10);
                snprintf(what, sizeof what, "%s: sigma_s + sigma_a = sigma_t [%d]", p->name, c);
                check_rel(what, soak_rgb_at(p->sigma_s_dry_per_m, c) + soak_rgb_at(p->sigma_a_dry_per_m, c),
                          soak_rgb_at(p->sigma_t_per_m, c), 1e-14);
            }
        }
        if (soak_material_kind_porous(p->kind))
            ok = ok && soak_in_range(p->porosity, 1e-3, 0.95) && p->s_p > 0 && p->porosity_source[0];
        else
            ok = ok && p->porosity == 0 && p->ggx_alpha_wet == p->ggx_alpha_dry;
        snprintf(what, sizeof what, "%s: every field present and in range", p->name);
        check_true(what, ok);
    }

    /* Published numbers ([JLD99], 001). */
    const soak_preset *sand = soak_presets_find(db, "sand"), *paper = soak_presets_find(db, "paper");
    const soak_preset *copper = soak_presets_find(db, "copper"), *lime = soak_presets_find(db, "limestone");
    const soak_preset *clay = soak_presets_find(db, "clay"), *concrete = soak_presets_find(db, "concrete");
    const soak_preset *marble = soak_presets_find(db, "marble");
    if (sand && paper && copper && lime && clay && concrete && marble) {
        check_close("sand porosity (Clapp & Hornberger 1978, Table 2: sand 0.395)", sand->porosity, 0.395, 0);
        check_close("concrete porosity ([Lag13]: concrete pot 25%)", concrete->porosity, 0.25, 0);
        check_true("limestone porosity in [Lag13]'s 30-45%", soak_in_range(lime->porosity, 0.30, 0.45));
        check_true("clay porosity in [Lag13]'s 40-50%", soak_in_range(clay->porosity, 0.40, 0.50));
        check_close("sand dry forward g ([JLD99])", sand->phase_dry.g1, 0.2, 0);
        check_close("paper thickness 80 g/m^2 / 800 kg/m^3 = 0.1 mm, in m", paper->thickness_m, 0.08 / 800.0, 1e-18);
        check_true("paper is a thin sheet", paper->kind == SOAK_KIND_THIN_SHEET);
        check_true("marble is non-porous", marble->kind == SOAK_KIND_NONPOROUS_DIELECTRIC);
        check_true("copper is a conductor", copper->kind == SOAK_KIND_CONDUCTOR);
        /* [JLD99] paper: dry (0.05, -0.05, w 0.2), wet g2 -0.1 with w 0.1, w weighting the backward lobe.
         * The wet g1 (and sand's wet g) are calibrated against measurements:
         * tests/c/materials/test_calibration.c; copper's n, k and water's absorption
         * are checked against their measured tables there too. */
        check_close("paper dry g1", paper->phase_dry.g1, 0.05, 0);
        check_close("paper dry g2", paper->phase_dry.g2, -0.05, 0);
        check_close("paper dry g1-weight = 1 - 0.2", paper->phase_dry.w, 1 - 0.2, 1e-15);
        check_close("paper wet g2", paper->phase_wet.g2, -0.1, 0);
        check_close("paper wet g1-weight = 1 - 0.1", paper->phase_wet.w, 1 - 0.1, 1e-15);
    }
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    if (check_true("liquid 'water' present", water != NULL)) {
        check_close("water n", water->ior, 1.333, 0);
    }
    check_true("a coloured liquid (coffee) present", soak_presets_find_liquid(db, "coffee") != NULL);
    check_true("unknown liquid -> NULL", soak_presets_find_liquid(db, "lava") == NULL);
    soak_presets_free(db);
}

static const char *const template_json =
    "{\"format\": \"soak-materials\", \"version\": 1, \"description\": \"test\",\n"
    " \"materials\": [\n"
    "  {\"name\": \"copper\", \"display_name\": \"Cu\", \"kind\": \"conductor\",\n"
    "   \"albedo\": {\"rgb\": [0.708357, 0.641305, 0.608869], \"source\": \"s\"},\n"
    "   \"roughness\": {\"ggx_alpha_dry\": 0.05, \"source\": \"s\"},\n"
    "   \"ior\": {\"n\": [3.406149, 2.1616, 1.504326], \"k\": [5.225178, 3.756258, 3.018729], \"source\": \"s\"},\n"
    "   \"wetting\": {\"film_thickness_mm\": 0.5, \"source\": \"s\"}},\n"
    "  {\"name\": \"sand\", \"display_name\": \"Sand\", \"kind\": \"porous_dielectric\",\n"
    "   \"albedo\": {\"rgb\": [0.44, 0.386, 0.231], \"source\": \"s\"},\n"
    "   \"roughness\": {\"ggx_alpha_dry\": 0.81, \"ggx_alpha_wet\": 0.7, \"source\": \"s\"},\n"
    "   \"ior\": {\"n\": 1.54, \"source\": \"s\"},\n"
    "   \"porosity\": {\"alpha\": 0.25, \"s_p\": 2.0, \"source\": \"s\"},\n"
    "   \"medium\": {\"sigma_t_per_mm\": [7.5, 7.5, 7.5], \"source\": \"s\"},\n"
    "   \"phase\": {\"dry\": {\"g1\": 0.2, \"g2\": 0, \"w\": 1}, \"wet\": {\"g1\": 0.7, \"g2\": 0, \"w\": 1}, \"source\": \"s\"},\n"
    "   \"wetting\": {\"t_fill\": 0.1, \"film_thickness_mm\": 0.5, \"source\": \"s\"}}\n"
    " ],\n"
    " \"liquids\": [{\"name\": \"water\", \"display_name\": \"Water\", \"ior\": 1.333,\n"
    "   \"sigma_a_per_mm\": [0.00035, 0.00004, 0], \"sigma_s_per_mm\": [0, 0, 0], \"source\": \"s\"}]\n"
    "}\n";

/* Writes the template with the first occurrence of `from` replaced by `to`. */
static int write_variant(const char *path, const char *from, const char *to)
{
    const char *at = from ? strstr(template_json, from) : NULL;
    if (from && !at) {
        printf("FAIL test setup: '%s' not in template\n", from);
        return 0;
    }
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    if (at) {
        fwrite(template_json, 1, (size_t)(at - template_json), f);
        fputs(to, f);
        fputs(at + strlen(from), f);
    } else {
        fputs(template_json, f);
    }
    return fclose(f) == 0;
}

static void expect_failure(const char *dir, const char *label, const char *from, const char *to,
                           soak_status want, const char *must_contain)
{
    char path[512], what[256], err[1024] = "";
    snprintf(path, sizeof path, "%s/variant.json", dir);
    if (!write_variant(path, from, to)) {
        check_true("write malformed file", 0);
        return;
    }
    soak_preset_db *db = NULL;
    soak_status st = soak_presets_load(path, &db, err, sizeof err);
    snprintf(what, sizeof what, "%s -> %s", label, soak_status_str(want));
    check_status(what, st, want);
    printf("  message: %s\n", err);
    check_true("failed load leaves db untouched", db == NULL);
    snprintf(what, sizeof what, "%s: message names the file and '%s'", label, must_contain);
    check_true(what, strstr(err, must_contain) != NULL && strstr(err, path) != NULL);
    if (db) soak_presets_free(db);
    remove(path);
}

static void check_malformed(void)
{
    char dir[] = "/tmp/soak_test_preset_XXXXXX";
    if (!mkdtemp(dir)) {
        check_true("mkdtemp", 0);
        return;
    }
    char path[512], err[1024] = "";
    snprintf(path, sizeof path, "%s/variant.json", dir);
    soak_preset_db *db = NULL;
    if (write_variant(path, NULL, NULL)) {
        soak_status st = soak_presets_load(path, &db, err, sizeof err);
        if (!check_status("unmodified template loads", st, SOAK_OK)) printf("  %s\n", err);
        check_true("template: 2 presets, 1 liquid", soak_presets_count(db) == 2 && soak_presets_liquid_count(db) == 1);
        check_true("path recorded", db && strcmp(soak_presets_path(db), path) == 0);
        soak_presets_free(db);
        remove(path);
    }

    expect_failure(dir, "syntax error", "\"version\": 1,", "\"version\": 1", SOAK_ERR_PARSE, "line 1,");
    expect_failure(dir, "syntax error on a later line", "\"s_p\": 2.0,", "\"s_p\": 2.0,,", SOAK_ERR_PARSE, "line 12,");
    /* worded as scenes word it (soak/json_read.h), with the keys accepted */
    expect_failure(dir, "unknown key", "\"s_p\": 2.0,", "\"s_p\": 2.0, \"colour\": 1,", SOAK_ERR_PARSE,
                   "materials[1].porosity.colour: unknown key (accepted: alpha, s_p, source)");
    expect_failure(dir, "NaN-like string", "\"alpha\": 0.25", "\"alpha\": \"NaN\"", SOAK_ERR_PARSE,
                   "materials[1].porosity.alpha");
    expect_failure(dir, "negative porosity", "\"alpha\": 0.25", "\"alpha\": -0.1", SOAK_ERR_ARG,
                   "materials[1].porosity.alpha");
    expect_failure(dir, "missing field", "\"s_p\": 2.0, ", "", SOAK_ERR_PARSE,
                   "materials[1].porosity.s_p: missing (required)");
    expect_failure(dir, "overflowing number", "\"alpha\": 0.25", "\"alpha\": 1e999", SOAK_ERR_ARG,
                   "materials[1].porosity.alpha");
    expect_failure(dir, "duplicate key", "\"s_p\": 2.0,", "\"s_p\": 2.0, \"s_p\": 2.0,", SOAK_ERR_PARSE,
                   "materials[1].porosity.s_p");
    expect_failure(dir, "rgb with 2 entries", "[7.5, 7.5, 7.5]", "[7.5, 7.5]", SOAK_ERR_PARSE,
                   "materials[1].medium.sigma_t_per_mm: must be an array of 3 numbers (R, G, B)");
    expect_failure(dir, "HG g = 1", "\"g1\": 0.7", "\"g1\": 1.0", SOAK_ERR_ARG, "materials[1].phase.wet.g1");
    expect_failure(dir, "wet rougher than dry", "\"ggx_alpha_wet\": 0.7", "\"ggx_alpha_wet\": 0.9", SOAK_ERR_ARG,
                   "materials[1].roughness.ggx_alpha_wet");
    expect_failure(dir, "unknown kind", "\"porous_dielectric\"", "\"porous\"", SOAK_ERR_ARG, "materials[1].kind");
    /* the optional contact angle (issue 48 item 4): both keys or neither, in [0, 180] */
    expect_failure(dir, "contact angle above 180", "\"t_fill\": 0.1, ",
                   "\"t_fill\": 0.1, \"contact_angle_deg\": 181, \"contact_angle_source\": \"s\", ", SOAK_ERR_ARG,
                   "materials[1].wetting.contact_angle_deg");
    expect_failure(dir, "contact angle without its source", "\"t_fill\": 0.1, ",
                   "\"t_fill\": 0.1, \"contact_angle_deg\": 30, ", SOAK_ERR_PARSE,
                   "materials[1].wetting.contact_angle_source: missing (required)");
    expect_failure(dir, "porosity on a conductor", "\"wetting\": {\"film_thickness_mm\": 0.5, \"source\": \"s\"}},",
                   "\"wetting\": {\"film_thickness_mm\": 0.5, \"source\": \"s\"}, \"porosity\": {}},", SOAK_ERR_PARSE,
                   "materials[0].porosity: key not used by kind conductor");
    expect_failure(dir, "conductor albedo inconsistent with n, k", "0.708357", "0.9", SOAK_ERR_ARG,
                   "materials[0].albedo.rgb[0]");
    expect_failure(dir, "bad name characters", "\"name\": \"sand\"", "\"name\": \"Sand!\"", SOAK_ERR_ARG,
                   "materials[1].name");
    expect_failure(dir, "duplicate material name", "\"name\": \"sand\"", "\"name\": \"copper\"", SOAK_ERR_ARG,
                   "materials[1]");
    expect_failure(dir, "missing liquids", ",\n \"liquids\"", ",\n \"liquids_x\"", SOAK_ERR_PARSE, "liquids_x");
    expect_failure(dir, "liquid absorption negative", "[0.00035, 0.00004, 0]", "[0.00035, -1, 0]", SOAK_ERR_ARG,
                   "liquids[0].sigma_a_per_mm[1]");
    expect_failure(dir, "wrong format tag", "\"soak-materials\"", "\"other\"", SOAK_ERR_PARSE, "format");

    /* The optional measured group: a file without it (the template, every
     * file before it existed) loads with has_measured = 0; with it, every key
     * is required and checked. */
    const char *wet_end = "\"film_thickness_mm\": 0.5, \"source\": \"s\"}}\n ]";
    const char *measured = "\"film_thickness_mm\": 0.5, \"source\": \"s\"},\n   \"measured\": {\"wet_dry_ratio\": 0.6, "
                           "\"spread\": 0.03, \"dry_albedo\": 0.4, \"wetness\": 1, \"quantity\": \"albedo_total\", "
                           "\"sun_zenith_deg\": 35, "
                           "\"source\": \"m\"}}\n ]";
    snprintf(path, sizeof path, "%s/variant.json", dir);
    if (write_variant(path, NULL, NULL) && soak_presets_load(path, &db, err, sizeof err) == SOAK_OK) {
        check_true("no measured group: has_measured = 0", !soak_presets_find(db, "sand")->has_measured);
        soak_presets_free(db);
    }
    if (write_variant(path, wet_end, measured)) {
        soak_status st = soak_presets_load(path, &db, err, sizeof err);
        if (!check_status("measured group loads", st, SOAK_OK)) printf("  %s\n", err);
        const soak_preset *sm = st == SOAK_OK ? soak_presets_find(db, "sand") : NULL;
        check_true("measured group read", sm && sm->has_measured && sm->measured_ratio == 0.6 &&
                                              sm->measured_spread == 0.03 && sm->measured_dry_albedo == 0.4 &&
                                              sm->measured_wetness == 1.0 && sm->measured_total == 1 &&
                                              sm->measured_sun_zenith_deg == 35.0 &&
                                              strcmp(sm->measured_source, "m") == 0);
        if (st == SOAK_OK) soak_presets_free(db);
        db = NULL;
        remove(path);
    }
    char bad[512];
    snprintf(bad, sizeof bad, "%s", measured);
    char *q = strstr(bad, "albedo_total");
    memcpy(q, "albedo_xxxxx", 12);
    expect_failure(dir, "measured quantity unknown", wet_end, bad, SOAK_ERR_ARG, "materials[1].measured.quantity");
    snprintf(bad, sizeof bad, "%s", measured);
    memcpy(strstr(bad, "0.03"), "-1.0", 4);
    expect_failure(dir, "measured spread negative", wet_end, bad, SOAK_ERR_ARG, "materials[1].measured.spread");
    snprintf(bad, sizeof bad, "%s", measured);
    memcpy(strstr(bad, "\"wetness\""), "\"wetnesz\"", 9);
    expect_failure(dir, "measured key misspelt", wet_end, bad, SOAK_ERR_PARSE, "materials[1].measured.wetnesz");

    err[0] = '\0';
    snprintf(path, sizeof path, "%s/does_not_exist.json", dir);
    check_status("missing file -> IO", soak_presets_load(path, &db, err, sizeof err), SOAK_ERR_IO);
    check_true("missing file: message names it", strstr(err, path) != NULL);
    check_status("NULL out -> NULL", soak_presets_load(path, NULL, err, sizeof err), SOAK_ERR_NULL);
    rmdir(dir);
}

static void check_default_path(void)
{
    char p[SOAK_PRESETS_PATH_MAX] = "", err[1024] = "";
    setenv("SOAK_MATERIALS", "/somewhere/else.json", 1);
    check_status("SOAK_MATERIALS is taken as is", soak_presets_default_path(p, sizeof p, err, sizeof err), SOAK_OK);
    check_true("SOAK_MATERIALS overrides the default path", strcmp(p, "/somewhere/else.json") == 0);
    char tiny[8] = "keep";
    check_status("SOAK_MATERIALS too long for out -> ARG", soak_presets_default_path(tiny, sizeof tiny, err, sizeof err),
                 SOAK_ERR_ARG);
    check_true("too long: out untouched", strcmp(tiny, "keep") == 0);
    unsetenv("SOAK_MATERIALS");
    check_status("default path found from the build tree", soak_presets_default_path(p, sizeof p, err, sizeof err),
                 SOAK_OK);
    size_t n = strlen(p);
    check_true("default path ends in /materials.json", n >= 15 && strcmp(p + n - 15, "/materials.json") == 0);
}

int main(void)
{
    check_default_path();
    check_shipped();
    check_malformed();
    return check_finish();
}
