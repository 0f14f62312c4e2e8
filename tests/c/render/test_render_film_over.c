/* A preset's "film_over": water over a rock whose inside is dry ([JLD99]
 * sec. 4.2, Fig. 6c, the gallery's beach rock (c)). The dry limestone
 * preset, its own interface left out ("interface": 0: the Lambertian body of
 * the chain's subsurface albedo), under a full film of water 0.5 mm thick,
 * seen along the normal under a uniform sky of radiance 1: by reciprocity
 * its radiance is the directional-hemispherical albedo of a film over that
 * Lambertian body, in closed form (Lekner & Dorf, soak_film_albedo_dir) per
 * channel with the liquid's index and absorption. Also: without film_over
 * the dry preset has no film (it is darker or brighter by the film's
 * effect, so the key is not ignored), and the key's errors are named. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "render_harness.h"
#include "soak/film.h"
#include "soak/preset.h"
#include "soak/scene.h"
#include "soak/wetness.h"

static void scene_text(char *text, size_t n, const char *extra)
{
    snprintf(text, n,
             "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 1000},"
             " \"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0], \"fov\": 0.5},"
             " \"environment\": {\"type\": \"constant\", \"radiance\": 1},"
             " \"materials\": {\"m\": {\"type\": \"preset\", \"name\": \"limestone\", \"wetness\": 0,"
             "   \"liquid\": \"water\", \"unit_mm\": 1000, \"interface\": 0%s}},"
             " \"objects\": [{\"type\": \"plane\", \"size\": [4000, 4000], \"material\": \"m\"}]}",
             extra);
}

static void check_rejected(const char *what, const char *extra, const char *needle)
{
    char text[2048], err[1024] = "";
    soak_scene scene;
    scene_text(text, sizeof text, extra);
    soak_status st = soak_scene_parse(text, what, ".", &scene, err, sizeof err);
    if (st == SOAK_OK) soak_scene_free(&scene);
    printf("  %s: %s\n", what, err);
    check_true(what, st != SOAK_OK && strstr(err, needle) != NULL);
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    soak_preset_db *db = NULL;
    char err[256];
    if (!check_status("presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return check_finish();
    const soak_preset *p = soak_presets_find(db, "limestone");
    const soak_liquid *l = soak_presets_find_liquid(db, "water");
    soak_wet_params w;
    soak_wet_input in = p ? soak_wet_input_steady(p, 0.0) : (soak_wet_input){0};
    double ref = 0, ref_dry = 0;
    if (check_true("limestone and water", p && l) && check_status("chain", soak_wetness_eval(p, l, &in, &w), SOAK_OK)) {
        const double a[3] = {w.albedo_subsurface.r, w.albedo_subsurface.g, w.albedo_subsurface.b};
        const double k[3] = {l->sigma_a_per_m.r, l->sigma_a_per_m.g, l->sigma_a_per_m.b};
        for (int c = 0; c < 3; ++c) {
            soak_film film = {l->ior, k[c], 0.0005};
            double r = 0;
            check_status("Lekner-Dorf", soak_film_albedo_dir(&film, a[c], 1.0, &r), SOAK_OK);
            ref += r / 3;
            ref_dry += a[c] / 3;
        }
    }
    soak_presets_free(db);
    char text[2048];
    double m, se, md, sed;
    scene_text(text, sizeof text, ", \"film_over\": {\"coverage\": 1, \"thickness\": 0.0005}");
    if (rh_render_mean("film over dry limestone", text, ".", 8, 4096, 5, RH_FIRST_PIXEL, &m, &se)) {
        printf("  water 0.5 mm over dry limestone: traced %.5f +- %.5f, Lekner-Dorf %.5f\n", m, se, ref);
        check_close("film_over = film over the dry chain's body (closed form)", m, ref, 4 * se + 1e-3);
    }
    scene_text(text, sizeof text, "");
    if (rh_render_mean("dry limestone", text, ".", 8, 4096, 6, RH_FIRST_PIXEL, &md, &sed)) {
        printf("  dry limestone without a film: traced %.5f +- %.5f, its body %.5f\n", md, sed, ref_dry);
        check_close("no film_over: the dry body alone", md, ref_dry, 4 * sed + 1e-3);
        check_true("the film changes the dry rock (> 4 sigma)", fabs(m - md) > 4 * hypot(se, sed));
    }
    check_rejected("film_over without a thickness", ", \"film_over\": {\"coverage\": 1}", "thickness");
    check_rejected("film_over with a model view", ", \"model\": \"ww\", \"film_over\": {\"thickness\": 0.001}",
                   "film_over");
    check_rejected("film_over with a stray key", ", \"film_over\": {\"thickness\": 0.001, \"depth\": 1}", "depth");
    return check_finish();
}
