/* A scene's preset material at the unit boundary (soak/scene.h): the chain
 * works in m and 1/m, the scene in its own length unit given by "unit_mm".
 * The medium coefficients, film thickness and film absorption the tracer
 * gets must be the chain's, converted here by the test (a coefficient per
 * scene unit = per m * unit_mm / 1000, a length in units = m * 1000 /
 * unit_mm), for scenes in mm, cm and m. */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "soak/preset.h"
#include "soak/scene.h"
#include "soak/wetness.h"

static const soak_material *find_material(const soak_scene *s, const char *name)
{
    for (int i = 0; i < s->n_materials; ++i)
        if (strcmp(s->materials[i].name, name) == 0) return &s->materials[i];
    return NULL;
}

static void check_rgb_rel(const char *what, soak_rgb got, soak_rgb want, double rel)
{
    char w[200];
    for (int c = 0; c < 3; ++c) {
        snprintf(w, sizeof w, "%s [%d]", what, c);
        check_rel(w, soak_rgb_at(got, c), soak_rgb_at(want, c), rel);
    }
}

static soak_rgb scaled(soak_rgb v, double s) { return soak_rgb3(v.r * s, v.g * s, v.b * s); }

/* paper (a traced medium) and sand (a film over the chain's base) soaked
 * with coffee, in a scene whose unit is unit_mm millimetres. */
static void check_unit(const soak_preset_db *db, double unit_mm)
{
    char text[2048], what[160], err[1024] = "";
    snprintf(text, sizeof text,
             "{\"render\": {\"width\": 1, \"height\": 1},"
             " \"camera\": {\"position\": [0, -5, 1], \"look_at\": [0, 0, 0], \"fov\": 40},"
             " \"lights\": [{\"type\": \"sun\", \"direction\": [0, 0, 1], \"irradiance\": 1}],"
             " \"materials\": {"
             "  \"paper\": {\"type\": \"preset\", \"name\": \"paper\", \"wetness\": 0.6, \"liquid\": \"coffee\","
             " \"unit_mm\": %.17g},"
             "  \"sand\": {\"type\": \"preset\", \"name\": \"sand\", \"wetness\": 1, \"liquid\": \"coffee\","
             " \"unit_mm\": %.17g}},"
             " \"objects\": [{\"type\": \"box\", \"min\": [-1, -1, 0], \"max\": [0, 1, 1], \"material\": \"paper\"},"
             "  {\"type\": \"box\", \"min\": [0, -1, 0], \"max\": [1, 1, 1], \"material\": \"sand\"}]}",
             unit_mm, unit_mm);
    soak_scene scene;
    snprintf(what, sizeof what, "scene in units of %g mm", unit_mm);
    if (!check_status(what, soak_scene_parse(text, what, ".", &scene, err, sizeof err), SOAK_OK)) {
        printf("  %s\n", err);
        return;
    }
    const soak_liquid *coffee = soak_presets_find_liquid(db, "coffee");
    const soak_preset *paper = soak_presets_find(db, "paper"), *sand = soak_presets_find(db, "sand");
    const soak_material *mp = find_material(&scene, "paper"), *ms = find_material(&scene, "sand");
    if (check_true("paper, sand, coffee in the presets and the scene", coffee && paper && sand && mp && ms)) {
        const double per_unit = unit_mm / 1000.0, units_per_m = 1000.0 / unit_mm;
        soak_wet_params wp, ws;
        soak_wet_input ip = soak_wet_input_steady(paper, 0.6), is = soak_wet_input_steady(sand, 1.0);
        check_status("paper chain", soak_wetness_eval(paper, coffee, &ip, &wp), SOAK_OK);
        check_status("sand chain", soak_wetness_eval(sand, coffee, &is, &ws), SOAK_OK);
        snprintf(what, sizeof what, "unit %g mm: paper medium sigma_s per unit", unit_mm);
        check_rgb_rel(what, mp->medium.sigma_s, scaled(wp.sigma_s_per_m, per_unit), 1e-12);
        snprintf(what, sizeof what, "unit %g mm: paper medium sigma_a per unit", unit_mm);
        check_rgb_rel(what, mp->medium.sigma_a, scaled(wp.sigma_a_per_m, per_unit), 1e-12);
        snprintf(what, sizeof what, "unit %g mm: sand film absorption per unit", unit_mm);
        check_rgb_rel(what, ms->film_absorption, scaled(coffee->sigma_a_per_m, per_unit), 1e-12);
        snprintf(what, sizeof what, "unit %g mm: sand film thickness in units (%g mm)", unit_mm,
                 1000.0 * sand->film_thickness_m);
        check_rel(what, ms->film_thickness, ws.film_thickness_m * units_per_m, 1e-12);
        snprintf(what, sizeof what, "unit %g mm: the film's optical depth is unit-free", unit_mm);
        check_rel(what, ms->film_thickness * ms->film_absorption.b, ws.film_thickness_m * coffee->sigma_a_per_m.b,
                  1e-12);
    }
    soak_scene_free(&scene);
}

int main(void)
{
    soak_preset_db *db = NULL;
    char err[1024] = "";
    if (!check_status("load presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) {
        printf("  %s\n", err);
        return check_finish();
    }
    check_unit(db, 1.0);
    check_unit(db, 10.0);
    check_unit(db, 1000.0);
    soak_presets_free(db);
    return check_finish();
}
