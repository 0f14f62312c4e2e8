/* An opaque or metal preset under an object wetness (a constant, a plane, a
 * map) renders as the chain at the point's liquid amount L = object wetness
 * * material wetness, as the front ends evaluate it (issue 39: a map's dry
 * part kept the material's filled pores). References are second scenes: the
 * same preset at wetness L with no object wetness, i.e. parse_preset's own
 * chain evaluation, not the levels under test.
 *
 *  1. Identity: material wetness 1 with a constant object wetness v, and
 *     with a wetness plane whose value at the pixel is v (a blend so wide
 *     that it is constant over the pixel; v = 0.3, 0.7 fall between the
 *     levels, so the interpolation is checked too), equal the preset at
 *     wetness v, for brick, sand and copper, v in {0, 0.3, 0.7}: each channel
 *     within four combined standard errors.
 *  2. A wet map whose pixels are all 0 renders as the dry preset.
 *  3. A half-wet plane (blend 0) under a uniform sky, the preset without its
 *     own specular interface ("interface": 0): the dry half's luminance over
 *     the wet half's is the chain's own ratio (soak_wetness_eval at wetness 0
 *     and 1, then soak_wetness_albedo_sun at the view's cosine: by
 *     reciprocity the directional albedo a uniform sky shows, with the
 *     liquid's mirror) within 5 % (Monte Carlo error and the tracer's
 *     closed-form film over Lambert; measured: 0.05 %), and well away from 1
 *     (the chain's ratio is about 2). Before the levels the dry half kept the
 *     wet material's filled pores.
 *  4. soak advise's radiance at a hit (soak_material_radiance) follows the
 *     same levels: sand under object wetness 0.3 = sand at wetness 0.3. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "render_harness.h"
#include "soak/accuracy.h"
#include "soak/image.h"
#include "soak/preset.h"
#include "soak/render.h"
#include "soak/scene.h"
#include "soak/wetness.h"

/* One render of SIDE x SIDE pixels that all see the same point (a field of
 * view of 0.5 degrees): each pixel is an independent estimate, so their
 * spread gives the standard error (one BSDF set-up per estimate). */
#define SIDE 16
#define SPP 64
/* cos of the view's 20 degrees off the normal (camera at (x0, -1.82, 5)) */
#define VIEW_COS (5.0 / sqrt(1.82 * 1.82 + 25.0))

/* A large plane around x = x0 seen from above at 20 degrees off
 * the normal; a uniform sky and (sun != 0) a sun; preset `name` at
 * material wetness mat_w, object wetness `object_w` (JSON, NULL: none). */
static int plane(const char *what, const char *name, double mat_w, const char *object_w, double x0, int sun,
                 uint64_t seed, rh_rgb *e)
{
    /* sun = 0: the sky only and the preset without its own specular interface
     * ("interface": 0), the part of the surface the chain's albedo describes */
    char text[4096], wet[1400] = "";
    if (object_w) snprintf(wet, sizeof wet, ", \"wetness\": %s", object_w);
    snprintf(text, sizeof text,
             "{\"render\": {\"width\": %d, \"height\": %d, \"max_depth\": 8},"
             " \"camera\": {\"position\": [%.17g, -1.82, 5], \"look_at\": [%.17g, 0, 0], \"up\": [0, 0, 1], \"fov\": 0.5},"
             " \"environment\": {\"type\": \"constant\", \"radiance\": 1},"
             " \"lights\": [%s],"
             " \"materials\": {\"m\": {\"type\": \"preset\", \"name\": \"%s\", \"wetness\": %.17g, \"interface\": %d}},"
             " \"objects\": [{\"type\": \"plane\", \"center\": [0, 0, 0], \"normal\": [0, 0, 1], \"size\": [400, 400],"
             " \"material\": \"m\"%s}]}",
             SIDE, SIDE, x0, x0, sun ? "{\"type\": \"sun\", \"direction\": [-0.5, 0.4, 0.77], \"irradiance\": 2}" : "", name, mat_w,
             sun, wet);
    return rh_render_rgb(what, text, 1, SPP, seed, e);
}

static double luminance(const double c[3]) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

static void check_same(const char *what, const rh_rgb *a, const rh_rgb *b)
{
    for (int c = 0; c < 3; ++c) {
        printf("  %s [%c]: %.5f +- %.5f against %.5f +- %.5f\n", what, "rgb"[c], a->mean[c], a->se[c], b->mean[c],
               b->se[c]);
        check_close(what, a->mean[c], b->mean[c], 4 * sqrt(a->se[c] * a->se[c] + b->se[c] * b->se[c]) + 1e-6);
    }
}

/* A 4 x 4 wet map of zeros in dir; its path in out. */
static int zero_map(const char *dir, char *out, size_t n)
{
    soak_image img;
    if (!check_status("map", soak_image_alloc(&img, 4, 4, 1), SOAK_OK)) return 0;
    memset(img.pixels, 0, 16 * sizeof *img.pixels);
    snprintf(out, n, "%s/zero.exr", dir);
    char err[512] = "";
    int ok = check_status("write the zero map", soak_image_write(out, &img, NULL, err, sizeof err), SOAK_OK);
    if (!ok) printf("  %s\n", err);
    soak_image_free(&img);
    return ok;
}

/* Checks 1 and 2 for one preset. */
static void identity(const char *name, const char *map, uint64_t seed)
{
    static const double v[3] = {0.0, 0.3, 0.7};
    for (int i = 0; i < 3; ++i) {
        char what[160], cw[64], pw[256];
        rh_rgb ref, con, pl;
        snprintf(cw, sizeof cw, "%.17g", v[i]);
        /* x = 0.5 - (x0 - offset) / blend = v at x0 = 0 */
        snprintf(pw, sizeof pw, "{\"type\": \"plane\", \"normal\": [1, 0, 0], \"offset\": %.17g, \"blend\": 1e6}",
                 -(0.5 - v[i]) * 1e6);
        snprintf(what, sizeof what, "%s at wetness %g", name, v[i]);
        if (!plane(what, name, v[i], NULL, 0, 1, seed + 10 * (uint64_t)i, &ref)) return;
        snprintf(what, sizeof what, "%s, constant object wetness %g = the preset at %g", name, v[i], v[i]);
        if (plane(what, name, 1, cw, 0, 1, seed + 10 * (uint64_t)i + 1000, &con)) check_same(what, &con, &ref);
        snprintf(what, sizeof what, "%s, wetness plane %g at the pixel = the preset at %g", name, v[i], v[i]);
        if (plane(what, name, 1, pw, 0, 1, seed + 10 * (uint64_t)i + 2000, &pl)) check_same(what, &pl, &ref);
        if (v[i] != 0.0) continue;
        char mw[1200];
        rh_rgb mp;
        snprintf(mw, sizeof mw, "{\"type\": \"map\", \"file\": \"%s\"}", map);
        snprintf(what, sizeof what, "%s, a wet map of zeros = the dry preset", name);
        if (plane(what, name, 1, mw, 0, 1, seed + 3000, &mp)) check_same(what, &mp, &ref);
    }
}

/* Check 3: the chain's dry/wet ratio of luminance under a uniform sky seen
 * at VIEW_COS: by reciprocity the directional-hemispherical reflectance at
 * that angle, with the liquid's mirror (soak_wetness_albedo_sun's
 * albedo_total). */
static double chain_ratio(const char *name)
{
    soak_preset_db *db = NULL;
    char err[256];
    double ratio = NAN;
    if (!check_status("presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return ratio;
    const soak_preset *p = soak_presets_find(db, name);
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    soak_wet_params w0, w1;
    soak_wet_input i0 = soak_wet_input_steady(p, 0.0), i1 = soak_wet_input_steady(p, 1.0);
    soak_rgb d0, d1, t0, t1;
    if (p && water && soak_wetness_eval(p, water, &i0, &w0) == SOAK_OK && soak_wetness_eval(p, water, &i1, &w1) == SOAK_OK &&
        soak_wetness_albedo_sun(p, water, &w0, VIEW_COS, &d0, &t0) == SOAK_OK &&
        soak_wetness_albedo_sun(p, water, &w1, VIEW_COS, &d1, &t1) == SOAK_OK) {
        double a0[3] = {t0.r, t0.g, t0.b}, a1[3] = {t1.r, t1.g, t1.b};
        ratio = luminance(a0) / luminance(a1);
    }
    soak_presets_free(db);
    return ratio;
}

static void half_wet(const char *name, uint64_t seed)
{
    const char *half = "{\"type\": \"plane\", \"normal\": [1, 0, 0], \"offset\": 0, \"blend\": 0}";
    rh_rgb dry, wet;
    char what[160];
    snprintf(what, sizeof what, "%s half-wet, dry half", name);
    if (!plane(what, name, 1, half, 20, 0, seed, &dry)) return;
    snprintf(what, sizeof what, "%s half-wet, wet half", name);
    if (!plane(what, name, 1, half, -20, 0, seed + 100, &wet)) return;
    double r = luminance(dry.mean) / luminance(wet.mean), chain = chain_ratio(name);
    printf("  %s: wet/dry luminance ratio rendered %.4f, chain %.4f\n", name, 1 / r, 1 / chain);
    snprintf(what, sizeof what, "%s: dry/wet luminance %.4f = the chain's %.4f within 5 %%", name, r, chain);
    check_close(what, r, chain, 0.05 * chain);
    snprintf(what, sizeof what, "%s: dry/wet luminance %.4f differs from 1 (the chain's %.4f)", name, r, chain);
    check_true(what, fabs(chain - 1) > 0.1 && fabs(r - 1) > 0.5 * fabs(chain - 1));
}

/* Check 4 (soak advise's radiance at a hit, soak_material_radiance): sand
 * at material wetness 1 and a hit's object wetness 0.3 (a constant; a
 * wetness plane, between levels) equals sand at wetness 0.3 at object
 * wetness 1, within four combined standard errors. */
static int radiance_of(const char *what, const char *object_w, double mat_w, double x, soak_albedo_estimate *e)
{
    char text[2048], err[1024] = "";
    snprintf(text, sizeof text,
             "{\"render\": {\"width\": 1, \"height\": 1}, \"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0],"
             " \"up\": [0, 1, 0], \"fov\": 1}, \"environment\": {\"type\": \"constant\", \"radiance\": 1},"
             " \"materials\": {\"m\": {\"type\": \"preset\", \"name\": \"sand\", \"wetness\": %.17g}},"
             " \"objects\": [{\"type\": \"plane\", \"center\": [0, 0, 0], \"normal\": [0, 0, 1], \"size\": [4, 4],"
             " \"material\": \"m\", \"wetness\": %s}]}",
             mat_w, object_w);
    soak_scene scene;
    if (!check_status(what, soak_scene_parse(text, what, ".", &scene, err, sizeof err), SOAK_OK)) {
        printf("  %s\n", err);
        return 0;
    }
    soak_local_light sun = {soak_v3(-0.48, 0.36, 0.8), soak_rgb3(2, 2, 2)};
    soak_vec3 wo = soak_v3(0, 0.3420201433256687, 0.9396926207859084);
    int ok = check_status(what, soak_material_radiance(&scene.materials[0], x, wo, soak_rgb3(1, 1, 1), &sun, 1, 20000, 7, e),
                          SOAK_OK);
    soak_scene_free(&scene);
    return ok;
}

static void advise_radiance(void)
{
    soak_albedo_estimate ref, con, pl;
    const char *plane_w = "{\"type\": \"plane\", \"normal\": [1, 0, 0], \"offset\": 0, \"blend\": 1}";
    if (!radiance_of("sand at 0.3 (radiance)", "1", 0.3, 1.0, &ref) ||
        !radiance_of("sand, object wetness 0.3 (radiance)", "0.3", 1, 0.3, &con) ||
        !radiance_of("sand, plane at 0.3 (radiance)", plane_w, 1, 0.3, &pl))
        return;
    for (int k = 0; k < 2; ++k) {
        const soak_albedo_estimate *e = k ? &pl : &con;
        for (int c = 0; c < 3; ++c) {
            double a = soak_rgb_at(e->value, c), b = soak_rgb_at(ref.value, c);
            double sa = soak_rgb_at(e->std_error, c), sb = soak_rgb_at(ref.std_error, c);
            char what[160];
            snprintf(what, sizeof what, "advise radiance, sand %s 0.3 = sand at 0.3 [%c]: %.5f vs %.5f",
                     k ? "plane" : "constant", "rgb"[c], a, b);
            check_close(what, a, b, 4 * sqrt(sa * sa + sb * sb) + 1e-6);
        }
    }
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    char dir[] = "/tmp/soak_wet_levels_XXXXXX", map[256];
    if (!check_true("temporary folder", mkdtemp(dir) != NULL)) return check_finish();
    if (zero_map(dir, map, sizeof map)) {
        identity("brick", map, 100);
        identity("sand", map, 200);
        identity("copper", map, 300);
    }
    half_wet("brick", 400);
    half_wet("sand", 500);
    advise_radiance();
    remove(map);
    rmdir(dir);
    return check_finish();
}
