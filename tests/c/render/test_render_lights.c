/* Light transport of the path tracer against closed forms, on a Lambertian
 * plane (radiance = albedo/pi * irradiance):
 *  - sphere light straight above: E = pi L (r/d)^2 (light and BSDF
 *    sampling combined by MIS: a wrong weight or pdf shows here);
 *  - point light: E = I cos / d^2;
 *  - sun: E = E_sun cos;
 *  - environment map (constant per row): E = sum_i L_i pi (z0^2 - z1^2)
 *    over the rows of the upper hemisphere, z = cos(theta) at row edges
 *    (the bilinear lookup moves it by 0.03 %, inside the tolerance);
 *  - the map's bilinear lookup on a ramp, and its orientation;
 *  - a quad loaded from an OBJ mesh (with UVs) and a wet map image read back
 *    through the scene: the wetness at a UV is the pixel written there;
 *  - a rough conductor (GGX) under a uniform sky of radiance 1: the pixel is
 *    the directional albedo, integrated here by midpoint quadrature of the
 *    model's BRDF (tests the renderer's sampling, pdf and MIS weights);
 *  - Russian roulette at albedo 1: inside a closed white box no path is ever
 *    killed, so every path must be stopped (and counted) by max_depth.
 * Each estimate is compared within 4 standard errors (measured over 8
 * independent renders) plus 0.2 %. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "render_harness.h"
#include "soak/ggx.h"
#include "soak/image.h"
#include "soak/render.h"
#include "soak/scene.h"

#define REPS 8

static int render_mean(const char *what, const char *text, const char *base_dir, int spp_total, double *mean, double *se)
{
    return rh_render_mean(what, text, base_dir, REPS, spp_total / REPS, 11, RH_FIRST_PIXEL, mean, se);
}

/* 1x1 image of the plane point at the origin seen from 60 degrees. */
#define PLANE_SCENE(lights)                                                                                         \
    "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 50},"                                                \
    " \"camera\": {\"position\": [0, -4.330127018922193, 2.5], \"look_at\": [0, 0, 0], \"fov\": 0.2}," lights "," \
    " \"materials\": {\"m\": {\"type\": \"lambert\", \"albedo\": 0.6}},"                                            \
    " \"objects\": [{\"type\": \"plane\", \"size\": [1000, 1000], \"material\": \"m\"}]}"

static void check_estimate(const char *what, double m, double se, double ref)
{
    printf("  %s: traced %.6f +- %.6f, closed form %.6f\n", what, m, se, ref);
    check_close(what, m, ref, 4 * se + 2e-3 * ref);
}

/* The map's orientation (Cycles': u = 0.5 - (azimuth - rotation) / 2 pi, so a
 * panorama seen from inside is not mirrored), read through "hdri" from
 * SOAK_HDRI_DIR: an 8x4 map lit only in columns 2-3 (u in [0.25, 0.5]; the
 * bilinear lookup is 1 between their centres, round u = 0.375) is seen at
 * azimuth 30 + 360 (0.5 - 0.375) = 75 degrees, and not at the mirror
 * image's 30 + 360 * 0.375 = 165 (u = 0.125, between the dark columns 0 and
 * 1). A missing name fails naming SOAK_HDRI_DIR. */
#define ENV_LOOK(az)                                                                                                 \
    "{\"render\": {\"width\": 1, \"height\": 1}, \"camera\": {\"position\": [0, 0, 0], \"look_at\": "            \
    "[" az "], \"fov\": 2}, \"environment\": {\"type\": \"map\", \"hdri\": \"col\", \"rotation\": 30},"             \
    " \"materials\": {\"m\": {\"type\": \"lambert\", \"albedo\": 0.6}},"                                              \
    " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, -50], \"radius\": 0.1, \"material\": \"m\"}]}"

static void test_env_orientation(const char *dir)
{
    soak_image col;
    if (!check_status("column map", soak_image_alloc(&col, 8, 4, 3), SOAK_OK)) return;
    for (int i = 0; i < 4; ++i)
        for (int j = 2; j <= 3; ++j)
            for (int ch = 0; ch < 3; ++ch) col.pixels[((size_t)i * 8 + j) * 3 + ch] = 1.0f;
    char path[300], err[512];
    snprintf(path, sizeof path, "%s/col.exr", dir);
    soak_image_write_opts wo = {SOAK_TONE_LINEAR, SOAK_PIXEL_FLOAT};
    check_status("write column map", soak_image_write(path, &col, &wo, err, sizeof err), SOAK_OK);
    soak_image_free(&col);
    setenv("SOAK_HDRI_DIR", dir, 1);
    double m, se;
    /* cos/sin of 75 and 165 degrees */
    if (render_mean("map columns 2-3 seen", ENV_LOOK("0.258819, 0.965926, 0"), dir, 64, &m, &se))
        check_close("the lit columns at azimuth 75", m, 1.0, 1e-6);
    if (render_mean("map mirror image", ENV_LOOK("-0.965926, 0.258819, 0"), dir, 64, &m, &se))
        check_close("nothing at their mirror image, 165", m, 0.0, 1e-6);
    soak_scene sc;
    const char *missing = "{\"camera\": {\"position\": [0, 0, 0], \"look_at\": [1, 0, 0]},"
                          " \"environment\": {\"type\": \"map\", \"hdri\": \"nosuch\"},"
                          " \"materials\": {}, \"objects\": []}";
    check_true("a missing hdri is an error",
               soak_scene_parse(missing, "hdri scene", dir, &sc, err, sizeof err) != SOAK_OK &&
                   strstr(err, "environment.hdri") && strstr(err, "SOAK_HDRI_DIR"));
    unsetenv("SOAK_HDRI_DIR");
    unlink(path);
}

/* The map is looked up bilinearly between texel centres: texel (row i,
 * column j) of an 8x4 ramp holds 1 + j + 4 i, a plane the bilinear
 * interpolation reproduces exactly. At u = 0.35, v = 0.525 (x = uW - 0.5 =
 * 2.3, y = vH - 0.5 = 1.6) it is 1 + 2.3 + 6.4 = 9.7; a nearest lookup gives
 * texel (2, 2) = 11. Direction: azimuth 360 (0.5 - u) = 54 degrees
 * (rotation 0), 94.5 degrees from the zenith; the 0.02-degree pixel spans
 * 1e-4 texel, where the plane is linear. Also across the seam: u = 0.98
 * (x = 7.34, between column 7 and column 0), v = 0.375 (y = 1): 1 + 7 + 4
 * + 0.34 (0 - 7) = 9.62. */
static void test_env_bilinear(const char *dir)
{
    soak_image ramp;
    if (!check_status("ramp map", soak_image_alloc(&ramp, 8, 4, 3), SOAK_OK)) return;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 8; ++j)
            for (int ch = 0; ch < 3; ++ch) ramp.pixels[((size_t)i * 8 + j) * 3 + ch] = (float)(1 + j + 4 * i);
    char path[300], err[512];
    snprintf(path, sizeof path, "%s/col.exr", dir);
    soak_image_write_opts wo = {SOAK_TONE_LINEAR, SOAK_PIXEL_FLOAT};
    check_status("write ramp map", soak_image_write(path, &ramp, &wo, err, sizeof err), SOAK_OK);
    soak_image_free(&ramp);
    setenv("SOAK_HDRI_DIR", dir, 1);
    const double deg = SOAK_PI / 180;
    const double cases[2][3] = {{0.35, 0.525, 9.7}, {0.98, 0.375, 9.62}};
    for (int k = 0; k < 2; ++k) {
        double phi = 360 * (0.5 - cases[k][0]) * deg, th = 180 * cases[k][1] * deg;
        char scene[1024];
        snprintf(scene, sizeof scene,
                 "{\"render\": {\"width\": 1, \"height\": 1}, \"camera\": {\"position\": [0, 0, 0],"
                 " \"look_at\": [%.9f, %.9f, %.9f], \"up\": [0, 0, 1], \"fov\": 0.02},"
                 " \"environment\": {\"type\": \"map\", \"hdri\": \"col\"},"
                 " \"materials\": {\"m\": {\"type\": \"lambert\", \"albedo\": 0.6}}, \"objects\": [{\"type\":"
                 " \"sphere\", \"center\": [0, 0, -50], \"radius\": 0.1, \"material\": \"m\"}]}",
                 sin(th) * cos(phi), sin(th) * sin(phi), cos(th));
        double m, se;
        if (render_mean(k ? "ramp map across the seam" : "ramp map between texels", scene, dir, 16, &m, &se))
            check_close(k ? "bilinear across the seam = 9.62" : "bilinear between texels = 9.7", m, cases[k][2],
                        2e-3);
    }
    unsetenv("SOAK_HDRI_DIR");
    unlink(path);
}

static void test_conductor(void)
{
    const double alpha = 0.3, eta = 0.2, k = 3.0, theta_v = 45.0 * SOAK_PI / 180.0;
    const char *text =
        "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 4},"
        " \"camera\": {\"position\": [0, -3.5355339059327378, 3.5355339059327378], \"look_at\": [0, 0, 0], \"fov\": 0.2},"
        " \"environment\": {\"type\": \"constant\", \"radiance\": 1},"
        " \"materials\": {\"m\": {\"type\": \"conductor\", \"eta\": 0.2, \"k\": 3, \"roughness\": 0.3}},"
        " \"objects\": [{\"type\": \"plane\", \"size\": [1000, 1000], \"material\": \"m\"}]}";
    double m, se;
    if (!render_mean("conductor", text, ".", 16384, &m, &se)) return;
    /* Directional albedo int f cos dw by the midpoint rule in (cos theta, phi). */
    soak_vec3 wo = soak_v3(0, -sin(theta_v), cos(theta_v));
    const int NU = 1200, NP = 600;
    double ref = 0;
    for (int i = 0; i < NU; ++i) {
        double mu = (i + 0.5) / NU, s = sqrt(1 - mu * mu);
        for (int j = 0; j < NP; ++j) {
            double phi = 2 * SOAK_PI * (j + 0.5) / NP;
            soak_vec3 wi = soak_v3(s * cos(phi), s * sin(phi), mu);
            double f = 0;
            soak_ggx_brdf_conductor(alpha, eta, k, wi, wo, &f);
            ref += f * mu;
        }
    }
    ref *= 2 * SOAK_PI / ((double)NU * NP);
    check_estimate("GGX conductor under a uniform sky = directional albedo (quadrature)", m, se, ref);
}

static void test_roulette_albedo_one(void)
{
    const char *text =
        "{\"render\": {\"width\": 2, \"height\": 2, \"max_depth\": 12},"
        " \"camera\": {\"position\": [0, 0, 0], \"look_at\": [0, 1, 0], \"fov\": 60},"
        " \"lights\": [{\"type\": \"point\", \"position\": [0.3, 0.2, 0.1], \"intensity\": 1}],"
        " \"materials\": {\"white\": {\"type\": \"lambert\", \"albedo\": 1}},"
        " \"objects\": [{\"type\": \"box\", \"min\": [-1, -1, -1], \"max\": [1, 1, 1], \"material\": \"white\"}]}";
    soak_scene scene;
    char err[512];
    if (!check_status("white box", soak_scene_parse(text, "white box", ".", &scene, err, sizeof err), SOAK_OK)) return;
    soak_render_options o;
    soak_render_options_default(&o);
    o.spp = 16;
    soak_image img;
    soak_render_stats st;
    if (check_status("render white box", soak_render(&scene, &o, &img, &st, err, sizeof err), SOAK_OK)) {
        printf("  white box, max_depth 12: %lld paths, %lld capped\n", st.paths, st.capped);
        check_true("albedo 1: roulette never kills, every path is capped and counted", st.capped == st.paths && st.paths == 64);
        soak_image_free(&img);
    }
    soak_scene_free(&scene);
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    double m, se;
    const double albedo = 0.6;

    /* Sphere light radius 0.5, centre 2 above the origin, radiance 3. */
    if (render_mean("sphere light",
                    PLANE_SCENE("\"lights\": [{\"type\": \"sphere\", \"center\": [0, 0, 2], \"radius\": 0.5, \"radiance\": 3}]"),
                    ".", 8192, &m, &se))
        check_estimate("sphere light: albedo/pi * pi L (r/d)^2", m, se, albedo / SOAK_PI * SOAK_PI * 3 * 0.0625);

    if (render_mean("point light",
                    PLANE_SCENE("\"lights\": [{\"type\": \"point\", \"position\": [1, 0, 2], \"intensity\": 5}]"), ".", 256,
                    &m, &se))
        check_estimate("point light: albedo/pi * I cos / d^2", m, se, albedo / SOAK_PI * 5 * (2 / sqrt(5.0)) / 5.0);

    if (render_mean("sun",
                    PLANE_SCENE("\"lights\": [{\"type\": \"sun\", \"direction\": [0.6, 0, 0.8], \"irradiance\": 2}]"), ".",
                    256, &m, &se))
        check_estimate("sun: albedo/pi * E cos", m, se, albedo / SOAK_PI * 2 * 0.8);

    /* Environment map: rows of radiance 1 + cos(theta at the row centre). */
    char dir[] = "/tmp/soak_lights_XXXXXX";
    if (mkdtemp(dir)) {
        int W = 16, H = 24;
        soak_image env;
        soak_image_alloc(&env, W, H, 3);
        double ref = 0;
        for (int i = 0; i < H; ++i) {
            double Li = 1 + cos(SOAK_PI * (i + 0.5) / H);
            for (int j = 0; j < W * 3; ++j) env.pixels[(size_t)i * W * 3 + j] = (float)Li;
            double z0 = cos(SOAK_PI * i / H), z1 = cos(SOAK_PI * (i + 1) / H);
            if (z1 >= 0) ref += (float)Li * SOAK_PI * (z0 * z0 - z1 * z1);
        }
        char path[300];
        snprintf(path, sizeof path, "%s/sky.exr", dir);
        char err[512];
        soak_image_write_opts wo = {SOAK_TONE_LINEAR, SOAK_PIXEL_FLOAT};
        check_status("write sky", soak_image_write(path, &env, &wo, err, sizeof err), SOAK_OK);
        if (render_mean("environment map",
                        PLANE_SCENE("\"environment\": {\"type\": \"map\", \"file\": \"sky.exr\", \"rotation\": 30}"), dir,
                        4096, &m, &se))
            check_estimate("environment map: albedo/pi * sum L_i pi (z0^2 - z1^2)", m, se, albedo / SOAK_PI * ref);
        unlink(path);
        test_env_orientation(dir);
        test_env_bilinear(dir);

        /* Wet map over a mesh quad: 4x2 image, column j value j/4, top row 1. */
        soak_image wet;
        soak_image_alloc(&wet, 4, 2, 1);
        for (int j = 0; j < 4; ++j) {
            wet.pixels[j] = 1.0f;            /* top row: v in [0.5, 1] */
            wet.pixels[4 + j] = 0.25f * j;   /* bottom row: v in [0, 0.5] */
        }
        char wpath[300], opath[300];
        snprintf(wpath, sizeof wpath, "%s/wet.exr", dir);
        snprintf(opath, sizeof opath, "%s/quad.obj", dir);
        check_status("write wet map", soak_image_write(wpath, &wet, &wo, err, sizeof err), SOAK_OK);
        FILE *f = fopen(opath, "w");
        if (f) {
            fputs("v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n", f);
            fclose(f);
        }
        const char *text =
            "{\"camera\": {\"position\": [1, 1, 5], \"look_at\": [1, 1, 0], \"up\": [0, 1, 0]},"
            " \"environment\": {\"type\": \"constant\", \"radiance\": 1},"
            " \"materials\": {\"w\": {\"type\": \"wet\", \"base\": {\"type\": \"lambert\", \"albedo\": 0.5}}},"
            " \"objects\": [{\"type\": \"mesh\", \"file\": \"quad.obj\", \"material\": \"w\", \"translate\": [0, 0, 0],"
            "               \"wetness\": {\"type\": \"map\", \"file\": \"wet.exr\"}}]}";
        soak_scene sc;
        if (check_status("mesh scene", soak_scene_parse(text, "mesh scene", dir, &sc, err, sizeof err), SOAK_OK)) {
            check_true("mesh: 2 triangles", soak_geometry_triangle_count(sc.geometry, sc.objects[0].object_id) == 2);
            soak_ray r = {soak_v3(1.7, 0.3, 5), soak_v3(0, 0, -1), 0, INFINITY};
            soak_hit h;
            int found = 0;
            soak_geometry_intersect(sc.geometry, &r, &h, &found);
            check_true("mesh hit", found);
            if (found) {
                check_close("mesh uv u = x/2", h.u, 0.85, 1e-6);
                check_close("mesh uv v = y/2", h.v, 0.15, 1e-6);
                /* u = 0.85 -> column 3, v = 0.15 -> bottom row: 0.75. */
                check_close("wet map value at uv", soak_scene_wetness(&sc.objects[0], h.p, h.u, h.v), 0.75, 1e-6);
                check_close("wet map top row", soak_scene_wetness(&sc.objects[0], h.p, 0.1, 0.9), 1.0, 1e-6);
            }
            soak_scene_free(&sc);
        } else {
            printf("  %s\n", err);
        }
        soak_image_free(&env);
        soak_image_free(&wet);
        unlink(wpath);
        unlink(opath);
        rmdir(dir);
    }

    /* Plane wetness: linear blend across the plane. */
    soak_object o;
    memset(&o, 0, sizeof o);
    o.wetness.type = SOAK_WETNESS_PLANE;
    o.wetness.normal = soak_v3(1, 0, 0);
    o.wetness.offset = 0;
    o.wetness.blend = 0.2;
    check_close("plane wetness at the offset", soak_scene_wetness(&o, soak_v3(0, 5, 0), 0, 0), 0.5, 1e-12);
    check_close("plane wetness wet side", soak_scene_wetness(&o, soak_v3(-0.2, 0, 0), 0, 0), 1.0, 1e-12);
    check_close("plane wetness dry side", soak_scene_wetness(&o, soak_v3(0.05, 0, 0), 0, 0), 0.25, 1e-12);
    test_conductor();
    test_roulette_albedo_one();
    return check_finish();
}
