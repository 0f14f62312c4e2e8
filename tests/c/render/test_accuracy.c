/* soak advise's and soak report's estimate of a material's radiance
 * (soak/accuracy.h) against the wetness chain, on a preset whose wet draws
 * are partly pore water (zero thickness): brick under coffee at w = 0.5, a
 * film over c = 0.23 and pore water over 0.27 more. The directional albedo
 * at a view equals the chain's directional-hemispherical total
 * (soak_wetness_albedo_sun, by reciprocity), where the film absorbs over its
 * thickness and the pore water over none; the estimate must agree within 4
 * standard errors + 2e-4 (the renderer in test_render_wet: + 1e-3). The
 * thick-film-everywhere estimate it replaces was 19 % low. The preset is
 * taken with "interface": 0: the chain's directional total has no lobe of
 * the material's own (that stack is tests/c/render/test_render_coated.c's). */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "soak/accuracy.h"
#include "soak/preset.h"
#include "soak/scene.h"
#include "soak/wetness.h"

static double mean3(soak_rgb c) { return (c.r + c.g + c.b) / 3; }

static void check_view(const soak_scene *scene, const soak_preset *p, const soak_liquid *l, const soak_wet_params *w,
                       double cos_view)
{
    soak_rgb dir, total;
    soak_albedo_estimate est;
    if (!check_status("chain total", soak_wetness_albedo_sun(p, l, w, cos_view, &dir, &total), SOAK_OK)) return;
    if (!check_status("estimate", soak_material_albedo(&scene->materials[0], 1.0, cos_view, 400000, 11, 0, &est),
                      SOAK_OK))
        return;
    double got = mean3(est.value), se = mean3(est.std_error), want = mean3(total);
    printf("  brick + coffee w 0.5, cos_view %.2f: estimate %.5f +- %.5f, chain %.5f\n", cos_view, got, se, want);
    check_close("estimate with film and pore water = the chain's directional total", got, want, 4 * se + 2e-4);
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    soak_preset_db *db = NULL;
    char err[256];
    if (!check_status("presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return check_finish();
    const soak_preset *p = soak_presets_find(db, "brick");
    const soak_liquid *l = soak_presets_find_liquid(db, "coffee");
    soak_wet_input in = p ? soak_wet_input_steady(p, 0.5) : (soak_wet_input){0};
    soak_wet_params w;
    soak_scene scene;
    const char *text = "{\"render\": {\"width\": 1, \"height\": 1},"
                       " \"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0]},"
                       " \"environment\": {\"type\": \"constant\", \"radiance\": 1},"
                       " \"materials\": {\"m\": {\"type\": \"preset\", \"name\": \"brick\", \"liquid\": \"coffee\","
                       " \"wetness\": 0.5, \"interface\": 0}},"
                       " \"objects\": [{\"type\": \"plane\", \"size\": [4, 4], \"material\": \"m\"}]}";
    if (check_true("brick and coffee", p && l) && check_status("chain", soak_wetness_eval(p, l, &in, &w), SOAK_OK) &&
        check_true("both a film and uncovered pore water",
                   w.film_coverage > 0.1 && soak_wet_interface_area(&w) > w.film_coverage + 0.1) &&
        check_status("scene", soak_scene_parse(text, "pores", ".", &scene, err, sizeof err), SOAK_OK)) {
        check_view(&scene, p, l, &w, 1.0);
        check_view(&scene, p, l, &w, 0.5);
        soak_scene_free(&scene);
    }
    soak_presets_free(db);
    return check_finish();
}
