// ctest-label: slow
/* The path tracer against independent references and [JLD99]'s claims.
 *
 *  1. A flat film over a Lambertian base under a uniform sky of radiance 1:
 *     by reciprocity the radiance toward the camera equals the directional-
 *     hemispherical reflectance for light arriving from the camera, given in
 *     closed form by Lekner & Dorf (soak_film_albedo_dir). The renderer uses
 *     that same closed form (film.c) for a film over Lambert, so this checks
 *     only its sampling (mirror lobe, diffuse part, MIS weights), not the
 *     film physics; the traced film path is checked against it in
 *     test_render_film_traced.c.
 *  2. A deep scattering half-space under the same sky against the virtual
 *     gonio-reflectometer (soak_measure). Both run the same random walk
 *     (medium.c, checked on its own against analytic and published results
 *     in test_measure_*.c and test_medium.c); what this compares is the
 *     renderer's use of it -- geometry, the camera, the boundary crossing
 *     and the index factors -- against the walk on an infinite slab.
 *  3. [JLD99]'s observations (Jensen, Legakis, Dorsey 1999, sec. 4):
 *     wet paper darker than dry lit from the viewer's side and brighter lit
 *     from behind (4.1); wet sand darker than dry (4.2, Twomey et al.); a
 *     rock with a scattering base under a water film barely darker on top
 *     (< 10 %) but brighter at grazing angles (4.2, Fig. 6c). Each
 *     difference must exceed 4 combined standard errors.
 *  4. Determinism: same seed -> identical pixels for 1 and 2 threads.
 *  6. A thin, weakly scattering index-matched slab lit from behind: the
 *     radiance toward a viewer in front is single scattering in closed form
 *     (next-event estimation must find the face the light enters through).
 *     The same under an index-matched absorbing film with pore water (no
 *     thickness): each face's film absorbs over its thick share only.
 *  7. A preset under a coloured liquid with both a film and water-filled
 *     pores (brick + coffee at w = 0.5: film over c = 0.23, pore water over
 *     0.27) under the uniform sky: the radiance toward an overhead camera is
 *     the chain's directional-hemispherical total at normal incidence
 *     (soak_wetness_albedo_sun, reciprocity), where the film absorbs over its
 *     thickness and the pore water over none.
 *  5. A heterogeneous parameter grid (soak grid format) holding the same
 *     half-space parameters, plus one far-away dense voxel that raises the
 *     majorant (so null collisions happen everywhere), gives the same
 *     reflectance as the gonio-reflectometer. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "soak/bake_volume.h"
#include "soak/base_colour.h"

#include "check.h"
#include "render_harness.h"
#include "soak/film.h"
#include "soak/measure.h"
#include "soak/preset.h"
#include "soak/wetness.h"
#include "soak/render.h"
#include "soak/scene.h"

#define REPS 8

/* Mean over pixels and channels of REPS renders, and its standard error. */
static int render_mean(const char *what, const char *text, int spp_total, double *mean, double *se)
{
    return rh_render_mean(what, text, ".", REPS, spp_total / REPS, 77, RH_ALL_PIXELS, mean, se);
}

/* Camera at angle theta_deg from the +z normal, looking at the origin, tiny fov. */
static void camera_json(char *buf, size_t n, double theta_deg, double dist)
{
    double t = theta_deg * SOAK_PI / 180.0;
    snprintf(buf, n, "\"camera\": {\"position\": [0, %.17g, %.17g], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0], \"fov\": 0.5}",
             -dist * sin(t), dist * cos(t));
}

/* One pixel of a large plane of material `material` (JSON) under a uniform
 * sky of radiance 1, seen from theta_deg off the normal. */
static void sky_plane_scene(char *text, size_t n, double theta_deg, const char *material)
{
    char cam[256];
    camera_json(cam, sizeof cam, theta_deg, 5);
    snprintf(text, n,
             "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 1000}, %s,"
             " \"environment\": {\"type\": \"constant\", \"radiance\": 1},"
             " \"materials\": {\"m\": %s},"
             " \"objects\": [{\"type\": \"plane\", \"size\": [4000, 4000], \"material\": \"m\"}]}",
             cam, material);
}

static void test_film_vs_lekner_dorf(void)
{
    double cosv[2] = {1.0, 0.5};
    for (int i = 0; i < 2; ++i) {
        char text[2048];
        sky_plane_scene(text, sizeof text, acos(cosv[i]) * 180.0 / SOAK_PI,
                        "{\"type\": \"wet\", \"film\": {\"ior\": 1.33}, \"base\": {\"type\": \"lambert\", \"albedo\": 0.5}}");
        double m, se;
        if (!render_mean("film plane", text, 65536, &m, &se)) continue;
        soak_film film = {1.33, 0, 0};
        double ref = 0;
        soak_film_albedo_dir(&film, 0.5, cosv[i], &ref);
        printf("  film over Lambert 0.5, cos_view %.2f: traced %.5f +- %.5f, Lekner-Dorf %.5f\n", cosv[i], m, se, ref);
        check_close("closed-form film as sampled by the renderer = directional albedo", m, ref, 4 * se + 1e-3);
    }
}


/* Same half-space from a grid; the material's own values (sigma_s 5) must
 * not be used inside the grid's box. */
static void test_volume_grid(const char *homogeneous_text, double ref, double ref_se)
{
    char dir[] = "/tmp/soak_rvol_XXXXXX";
    if (!check_true("temporary folder", mkdtemp(dir) != NULL)) return;
    soak_volume v;
    double size[3] = {800, 800, 200};
    if (!check_status("volume alloc", soak_volume_alloc(&v, 4, 4, 4, size), SOAK_OK)) return;
    size_t n = soak_volume_count(&v);
    float vals[SOAK_VOL_NCHANNELS] = {0.9f, 0.9f, 0.9f, 0.1f, 0.1f, 0.1f, 0.6f, -0.3f, 0.8f, 1.0f};
    for (int ch = 0; ch < SOAK_VOL_NCHANNELS; ++ch)
        for (size_t i = 0; i < n; ++i) soak_volume_plane(&v, ch)[i] = vals[ch];
    soak_volume_plane(&v, SOAK_VOL_SIGMA_S_R)[0] = 2.9f; /* majorant 3 */
    char prefix[300], err[512];
    snprintf(prefix, sizeof prefix, "%s/grid", dir);
    check_status("write grid", soak_volume_write_grid(&v, prefix, NULL, 0, 0, err, sizeof err), SOAK_OK);
    soak_volume_free(&v);
    /* Replace the homogeneous base by one with a volume. */
    char text[4096];
    const char *cut = strstr(homogeneous_text, "\"base\"");
    const char *end = cut ? strstr(cut, "}}},") : NULL;
    if (!check_true("scene text has a base to replace", cut && end)) return;
    snprintf(text, sizeof text, "%.*s\"base\": {\"type\": \"medium\", \"sigma_s\": 5, \"sigma_a\": 0, \"ior\": 1.3,"
             " \"volume\": {\"file\": \"grid.json\", \"origin\": [-400, -400, -200]}}}},%s",
             (int)(cut - homogeneous_text), homogeneous_text, end + 4);
    soak_scene scene;
    if (!check_status("grid scene", soak_scene_parse(text, "grid", dir, &scene, err, sizeof err), SOAK_OK)) {
        printf("  %s\n", err);
    } else {
        soak_scene_free(&scene);
        double m, se;
        /* render_mean resolves files against "."; run from the grid folder. */
        char cwd[1024];
        if (getcwd(cwd, sizeof cwd) && chdir(dir) == 0) {
            if (render_mean("grid half-space", text, 32768, &m, &se)) {
                printf("  grid half-space (null collisions, majorant 3): traced %.5f +- %.5f, measure %.5f\n", m, se, ref);
                check_close("grid half-space = gonio-reflectometer reflectance", m, ref,
                            4 * sqrt(se * se + ref_se * ref_se) + 2e-3);
            }
            if (chdir(cwd) != 0) check_true("chdir back", 0);
        }
    }
    snprintf(prefix, sizeof prefix, "%s/grid.json", dir);
    unlink(prefix);
    snprintf(prefix, sizeof prefix, "%s/grid.raw", dir);
    unlink(prefix);
    rmdir(dir);
}

static void test_halfspace_vs_measure(void)
{
    double cosv[2] = {1.0, 0.5};
    for (int i = 0; i < 2; ++i) {
        char cam[256], text[2048];
        camera_json(cam, sizeof cam, acos(cosv[i]) * 180.0 / SOAK_PI, 5);
        snprintf(text, sizeof text,
                 "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 1000}, %s,"
                 " \"environment\": {\"type\": \"constant\", \"radiance\": 1},"
                 " \"materials\": {\"m\": {\"type\": \"wet\", \"film\": {\"coverage\": 0},"
                 "   \"base\": {\"type\": \"medium\", \"sigma_s\": 0.9, \"sigma_a\": 0.1, \"g1\": 0.6, \"g2\": -0.3,"
                 "              \"w\": 0.8, \"ior\": 1.3}}},"
                 " \"objects\": [{\"type\": \"box\", \"min\": [-400, -400, -200], \"max\": [400, 400, 0], \"material\": \"m\"}]}",
                 cam);
        double m, se;
        if (!render_mean("half-space", text, 65536, &m, &se)) continue;
        soak_measure_setup su;
        soak_measure_setup_default(&su);
        su.config = SOAK_MEASURE_HALFSPACE;
        su.quantity = SOAK_MEASURE_R;
        su.cos_incidence = cosv[i];
        su.ior = 1.3;
        su.albedo = 0.9;
        su.phase.g1 = 0.6;
        su.phase.g2 = -0.3;
        su.phase.w = 0.8;
        su.paths = 200000;
        su.threads = 2;
        soak_measure_result res;
        if (!check_status("soak_measure", soak_measure_run(&su, &res), SOAK_OK)) continue;
        printf("  half-space albedo 0.9, n 1.3, cos %.2f: traced %.5f +- %.5f, measure %.5f +- %.5f\n", cosv[i], m, se,
               res.value, res.std_error);
        check_close("traced half-space radiance = gonio-reflectometer reflectance", m, res.value,
                    4 * sqrt(se * se + res.std_error * res.std_error) + 2e-3);
        if (i == 0) test_volume_grid(text, res.value, res.std_error);
    }
}

/* Radiance of a material seen along the normal (or at theta_view), lit by a
 * sun and a sky, wet (wetness 1) and dry (wetness 0). */
static int wet_dry(const char *what, const char *material, const char *object, double theta_view, const char *lights,
                   int spp, double *wet, double *dry, double *se_wet, double *se_dry)
{
    for (int k = 0; k < 2; ++k) {
        char cam[256], text[4096];
        camera_json(cam, sizeof cam, theta_view, 5);
        snprintf(text, sizeof text,
                 "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 1000}, %s, %s,"
                 " \"materials\": {\"m\": %s}, \"objects\": [%s, \"wetness\": %d}]}",
                 cam, lights, material, object, k == 0 ? 1 : 0);
        if (!render_mean(what, text, spp, k == 0 ? wet : dry, k == 0 ? se_wet : se_dry)) return 0;
    }
    return 1;
}

static void test_paper(void)
{
    /* Paper 0.8 mm thick ([JLD99] sec. 4.1), units mm. [JLD99] gives the
     * dry phase g1 0.05, g2 -0.05, w 0.2 and the wet g1 0.8, g2 -0.1, w 0.1;
     * with w weighting the g1 lobe as in its Eq. 5 the wet mean cosine would
     * be -0.01 (no forward scattering at all), contradicting the text ("makes
     * the forward scattering much stronger"). The printed w values are the
     * weights of the g2 lobe: we use w(g1) = 0.8 dry and 0.9 wet. */
    const char *paper = "{\"type\": \"wet\", \"film\": {\"coverage\": 0},"
                        " \"base\": {\"type\": \"medium\", \"sigma_s\": 20, \"sigma_a\": 0.04, \"ior\": 1.5,"
                        "            \"g1\": 0.8, \"g2\": -0.1, \"w\": 0.9},"
                        " \"dry\": {\"sigma_s\": 20, \"sigma_a\": 0.04, \"g1\": 0.05, \"g2\": -0.05, \"w\": 0.8}}";
    const char *slab = "{\"type\": \"box\", \"min\": [-60, -60, -0.8], \"max\": [60, 60, 0], \"material\": \"m\"";
    const char *front = "\"lights\": [{\"type\": \"sun\", \"direction\": [0.5, 0, 0.8660254037844386], \"irradiance\": 1}]";
    const char *back = "\"lights\": [{\"type\": \"sun\", \"direction\": [0.5, 0, -0.8660254037844386], \"irradiance\": 1}]";
    double w, d, sw, sd;
    if (wet_dry("paper, front lit", paper, slab, 0, front, 4096, &w, &d, &sw, &sd)) {
        printf("  paper lit from the viewer's side: wet %.5f +- %.5f, dry %.5f +- %.5f, wet/dry %.3f\n", w, sw, d, sd, w / d);
        check_true("wet paper darker than dry, front lit (> 4 sigma)", d - w > 4 * sqrt(sw * sw + sd * sd));
    }
    if (wet_dry("paper, back lit", paper, slab, 0, back, 4096, &w, &d, &sw, &sd)) {
        printf("  paper lit from behind: wet %.5f +- %.5f, dry %.5f +- %.5f, wet/dry %.3f\n", w, sw, d, sd, w / d);
        check_true("wet paper brighter than dry, back lit (> 4 sigma)", w - d > 4 * sqrt(sw * sw + sd * sd));
    }
}

/* Index-matched slab of thickness d, sun of beam irradiance E behind it at
 * cos mu_i, viewer in front along the normal (mu_o = 1), isotropic phase:
 * single scattering L1 = sigma_s E / (4 pi mu_o) * int_0^d exp(-sigma_t ((d - z)/mu_i + z/mu_o)) dz.
 * Multiple scattering adds about albedo * min(tau, 1) (here at most 1 %). */
static void backlit_slab(const char *what, double ss, double sa, int spp_total)
{
    const double d = 1.0, mu_i = cos(SOAK_PI / 6), st = ss + sa;
    const double a = st / 1.0 - st / mu_i;
    const double L1 = ss / (4 * SOAK_PI) * exp(-st * d / mu_i) * (1 - exp(-a * d)) / a;
    char text[2048];
    snprintf(text, sizeof text,
             "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 1000},"
             " \"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0], \"fov\": 0.5},"
             " \"lights\": [{\"type\": \"sun\", \"direction\": [0.5, 0, %.17g], \"irradiance\": 1}],"
             " \"materials\": {\"m\": {\"type\": \"wet\", \"film\": {\"coverage\": 0},"
             "   \"base\": {\"type\": \"medium\", \"sigma_s\": %g, \"sigma_a\": %g, \"g1\": 0, \"g2\": 0, \"w\": 1, \"ior\": 1}}},"
             " \"objects\": [{\"type\": \"box\", \"min\": [-60, -60, %g], \"max\": [60, 60, 0], \"material\": \"m\"}]}",
             -mu_i, ss, sa, -d);
    double m, se;
    if (!render_mean(what, text, spp_total, &m, &se)) return;
    printf("  %s: traced %.6g +- %.3g, single scattering %.6g\n", what, m, se, L1);
    char label[160];
    snprintf(label, sizeof label, "%s: radiance = single scattering (+ <= 2 %% multiple)", what);
    check_close(label, m, L1 * 1.01, 4 * se + 0.02 * L1);
}

/* Optical depth 0.1, and 5 with albedo 0.02: the sun reaches the vertices
 * near the viewer's face through a transmittance of 0.003, far below the
 * shadow estimate's roulette scale for a light behind the face
 * (RT_NEE_ROULETTE_T_BEHIND), so its survival and weights are exercised. */
static void test_backlit_single_scattering(void)
{
    backlit_slab("back-lit thin slab", 0.01, 0.09, 131072);
    backlit_slab("back-lit thick absorbing slab", 0.1, 4.9, 131072);
}

/* The same slab under an index-matched absorbing film (thickness 0.05,
 * absorption 10) of which a share 0.4 is pore water with no thickness: the
 * light crosses the film at the back, the view at the front, each absorbing
 * on average (1 - 0.4) exp(-0.5 / cos) + 0.4. A film everywhere would give
 * 0.34 of the clear slab; this 0.56. */
static void test_backlit_film_pores(void)
{
    const double ss = 0.01, sa = 0.09, d = 1.0, mu_i = cos(SOAK_PI / 6), st = ss + sa;
    const double a = st / 1.0 - st / mu_i, tau = 0.05 * 10.0, pore = 0.4;
    const double L1 = ss / (4 * SOAK_PI) * exp(-st * d / mu_i) * (1 - exp(-a * d)) / a;
    const double back = (1 - pore) * exp(-tau / mu_i) + pore, front = (1 - pore) * exp(-tau) + pore;
    char text[2048];
    snprintf(text, sizeof text,
             "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 1000},"
             " \"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0], \"fov\": 0.5},"
             " \"lights\": [{\"type\": \"sun\", \"direction\": [0.5, 0, %.17g], \"irradiance\": 1}],"
             " \"materials\": {\"m\": {\"type\": \"wet\","
             "   \"film\": {\"ior\": 1, \"thickness\": 0.05, \"absorption\": 10, \"pore_share\": %g},"
             "   \"base\": {\"type\": \"medium\", \"sigma_s\": %g, \"sigma_a\": %g, \"g1\": 0, \"g2\": 0, \"w\": 1, \"ior\": 1}}},"
             " \"objects\": [{\"type\": \"box\", \"min\": [-60, -60, %g], \"max\": [60, 60, 0], \"material\": \"m\"}]}",
             -mu_i, pore, ss, sa, -d);
    double m, se;
    if (!render_mean("back-lit slab under film and pores", text, 131072, &m, &se)) return;
    double want = L1 * back * front;
    printf("  back-lit slab, film with pore water: traced %.6f +- %.6f, single scattering %.6f\n", m, se, want);
    check_close("film absorbs only where it has thickness (+ <= 2 % multiple)", m, want * 1.01, 4 * se + 0.02 * want);
}

static void test_sand(void)
{
    /* Sand: dry grains scatter nearly isotropically; water in the pores makes
     * scattering forward ([JLD99] sec. 2.2, Twomey et al. 1986) and adds a
     * film. Units mm; albedo 0.96 per event. */
    const char *sand = "{\"type\": \"wet\", \"film\": {\"ior\": 1.33, \"k\": 2},"
                       " \"base\": {\"type\": \"medium\", \"sigma_s\": 9.6, \"sigma_a\": 0.4, \"ior\": 1.55,"
                       "            \"g1\": 0.8, \"g2\": -0.1, \"w\": 0.9},"
                       " \"dry\": {\"sigma_s\": 9.6, \"sigma_a\": 0.4, \"g1\": 0.1, \"g2\": -0.1, \"w\": 0.6}}";
    const char *box = "{\"type\": \"box\", \"min\": [-100, -100, -50], \"max\": [100, 100, 0], \"material\": \"m\"";
    const char *light = "\"environment\": {\"type\": \"constant\", \"radiance\": 0.2},"
                        " \"lights\": [{\"type\": \"sun\", \"direction\": [0.6, 0, 0.8], \"irradiance\": 1}]";
    double w, d, sw, sd;
    if (wet_dry("sand", sand, box, 30, light, 4096, &w, &d, &sw, &sd)) {
        printf("  sand: wet %.5f +- %.5f, dry %.5f +- %.5f, wet/dry %.3f\n", w, sw, d, sd, w / d);
        check_true("wet sand darker than dry (> 4 sigma)", d - w > 4 * sqrt(sw * sw + sd * sd));
    }
}

static void test_rock(void)
{
    /* Rock with a scattering base (index 1.5, rough own surface k = 4) under
     * a water film; the phase function is unchanged (water only on top). */
    const char *rock = "{\"type\": \"wet\", \"film\": {\"ior\": 1.33, \"k\": 4},"
                       " \"base\": {\"type\": \"medium\", \"sigma_s\": 19, \"sigma_a\": 1, \"ior\": 1.5,"
                       "            \"g1\": 0.3, \"g2\": -0.2, \"w\": 0.7}}";
    const char *box = "{\"type\": \"box\", \"min\": [-100, -100, -50], \"max\": [100, 100, 0], \"material\": \"m\"";
    const char *light = "\"environment\": {\"type\": \"constant\", \"radiance\": 0.3},"
                        " \"lights\": [{\"type\": \"sun\", \"direction\": [0.3, 0.2, 0.93], \"irradiance\": 1}]";
    double w, d, sw, sd;
    if (wet_dry("rock top", rock, box, 0, light, 4096, &w, &d, &sw, &sd)) {
        printf("  rock seen from above: wet %.5f +- %.5f, dry %.5f +- %.5f, relative difference %.3f\n", w, sw, d, sd,
               (d - w) / d);
        check_true("rock top barely darker: |wet - dry| / dry < 10 %", fabs(d - w) / d < 0.10);
    }
    if (wet_dry("rock grazing", rock, box, 80, light, 4096, &w, &d, &sw, &sd)) {
        printf("  rock at 80 deg from the normal: wet %.5f +- %.5f, dry %.5f +- %.5f, wet/dry %.3f\n", w, sw, d, sd, w / d);
        check_true("rock brighter at grazing angles when wet (> 4 sigma)", w - d > 4 * sqrt(sw * sw + sd * sd));
    }
}

static void test_determinism(void)
{
    const char *text =
        "{\"render\": {\"width\": 20, \"height\": 12, \"max_depth\": 64},"
        " \"camera\": {\"position\": [0, -5, 2], \"look_at\": [0, 0, 0.5], \"fov\": 40, \"aperture\": 0.05},"
        " \"environment\": {\"type\": \"constant\", \"radiance\": [0.2, 0.3, 0.5]},"
        " \"lights\": [{\"type\": \"sun\", \"direction\": [0.3, -0.4, 0.8], \"irradiance\": 2},"
        "              {\"type\": \"sphere\", \"center\": [2, -1, 2], \"radius\": 0.3, \"radiance\": 5}],"
        " \"materials\": {\"g\": {\"type\": \"wet\", \"base\": {\"type\": \"lambert\", \"albedo\": 0.5}},"
        "                \"s\": {\"type\": \"wet\", \"base\": {\"type\": \"medium\", \"sigma_s\": 10, \"sigma_a\": 1}}},"
        " \"objects\": [{\"type\": \"plane\", \"size\": [10, 10], \"material\": \"g\","
        "                \"wetness\": {\"type\": \"plane\", \"normal\": [1, 0, 0], \"offset\": 0}},"
        "              {\"type\": \"sphere\", \"center\": [0, 0, 0.6], \"radius\": 0.6, \"material\": \"s\"}]}";
    soak_scene scene;
    char err[512];
    if (!check_status("determinism scene", soak_scene_parse(text, "det", ".", &scene, err, sizeof err), SOAK_OK)) {
        printf("  %s\n", err);
        return;
    }
    soak_image img[4];
    int threads[4] = {2, 2, 1, 2};
    uint64_t seeds[4] = {5, 5, 5, 6};
    for (int i = 0; i < 4; ++i) {
        soak_render_options o;
        soak_render_options_default(&o);
        o.spp = 8;
        o.threads = threads[i];
        o.seed = seeds[i];
        soak_render(&scene, &o, &img[i], NULL, err, sizeof err);
    }
    size_t bytes = (size_t)img[0].width * img[0].height * 3 * sizeof(float);
    check_true("same seed, same threads: identical pixels", memcmp(img[0].pixels, img[1].pixels, bytes) == 0);
    check_true("same seed, 1 vs 2 threads: identical pixels", memcmp(img[0].pixels, img[2].pixels, bytes) == 0);
    check_true("another seed: different pixels", memcmp(img[0].pixels, img[3].pixels, bytes) != 0);
    for (int i = 0; i < 4; ++i) soak_image_free(&img[i]);
    soak_scene_free(&scene);
}

static void test_preset_film_and_pores(void)
{
    soak_preset_db *db = NULL;
    char err[256];
    if (!check_status("presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return;
    const soak_preset *p = soak_presets_find(db, "brick");
    const soak_liquid *l = soak_presets_find_liquid(db, "coffee");
    soak_wet_input in = p ? soak_wet_input_steady(p, 0.5) : (soak_wet_input){0};
    soak_wet_params w;
    soak_rgb dir, total;
    if (check_true("brick and coffee", p && l) && check_status("chain", soak_wetness_eval(p, l, &in, &w), SOAK_OK) &&
        check_status("sun albedo", soak_wetness_albedo_sun(p, l, &w, 1.0, &dir, &total), SOAK_OK)) {
        check_true("both a film and uncovered pore water", w.film_coverage > 0.1 && soak_wet_interface_area(&w) > w.film_coverage + 0.1);
        char text[2048];
        sky_plane_scene(text, sizeof text, 0.0,
                        "{\"type\": \"preset\", \"name\": \"brick\", \"liquid\": \"coffee\", \"wetness\": 0.5,"
                        " \"interface\": 0}"); /* the chain's total has no lobe of the material's own */
        double m, se;
        if (render_mean("brick + coffee", text, 65536, &m, &se)) {
            double ref = (total.r + total.g + total.b) / 3;
            printf("  brick + coffee w 0.5, overhead: traced %.5f +- %.5f, chain %.5f\n", m, se, ref);
            check_close("preset with film and pore water = the chain's directional total", m, ref, 4 * se + 1e-3);
        }
    }
    soak_presets_free(db);
}

/* A user's colour wetted by a preset's class: the scene's "base_colour" must
 * trace what soak_wet_params_for_base says (its directional total, which has
 * no lobe of the material's own interface: "interface": 0 leaves it out). */
static void test_preset_base_colour(void)
{
    soak_preset_db *db = NULL;
    char err[256];
    if (!check_status("presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return;
    const soak_preset *p = soak_presets_find(db, "sand");
    const soak_liquid *l = soak_presets_find_liquid(db, "water");
    soak_wet_input in = p ? soak_wet_input_steady(p, 0.5) : (soak_wet_input){0};
    soak_wet_params w;
    soak_rgb dir, total;
    if (check_true("sand and water", p && l) &&
        check_status("chain", soak_wet_params_for_base(p, l, &in, soak_rgb3(0.2, 0.45, 0.7), &w), SOAK_OK) &&
        check_status("sun albedo", soak_wetness_albedo_sun(p, l, &w, 1.0, &dir, &total), SOAK_OK)) {
        char text[2048];
        sky_plane_scene(text, sizeof text, 0.0,
                        "{\"type\": \"preset\", \"name\": \"sand\", \"wetness\": 0.5, \"base_colour\": [0.2, 0.45, 0.7],"
                        " \"interface\": 0}");
        double m, se;
        if (render_mean("sand class, blue-green colour", text, 65536, &m, &se)) {
            double ref = (total.r + total.g + total.b) / 3;
            printf("  sand class (0.2, 0.45, 0.7) w 0.5, overhead: traced %.5f +- %.5f, chain %.5f\n", m, se, ref);
            check_close("preset with base_colour = the chain for that colour", m, ref, 4 * se + 1e-3);
            soak_wet_params own;
            soak_rgb own_dir, own_total;
            if (check_status("own colour", soak_wetness_eval(p, l, &in, &own), SOAK_OK) &&
                check_status("own sun albedo", soak_wetness_albedo_sun(p, l, &own, 1.0, &own_dir, &own_total), SOAK_OK))
                check_true("and not the preset's own colour's",
                           fabs(m - (own_total.r + own_total.g + own_total.b) / 3) > 0.02);
        }
    }
    soak_presets_free(db);
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    test_determinism();
    test_film_vs_lekner_dorf();
    test_halfspace_vs_measure();
    test_paper();
    test_backlit_single_scattering();
    test_backlit_film_pores();
    test_sand();
    test_rock();
    test_preset_film_and_pores();
    test_preset_base_colour();
    return check_finish();
}
