/* The renderer's closed-form film over a Lambert base (render_surface.c,
 * film_lambert: the film's internal reflections summed analytically) against
 * references that do not use soak/film.h:
 *  1. Uniform sky of radiance 1 over an absorbing film, partly covered
 *     (wetness 0.6, so the bare-Lambert path is mixed in): by reciprocity
 *     the radiance toward the camera is the directional-hemispherical
 *     reflectance for light arriving from the camera, 0.6 R_film + 0.4 A,
 *     with R_film traced by the virtual gonio-reflectometer (soak_measure:
 *     photons bounced through the film one by one).
 *  2. The sun alone (no sky): L = E cos_l f(l, v), f = the bounce series of
 *     Lekner & Dorf 1988 with Beer-Lambert absorption, re-derived here:
 *       f = (1-F_l) a_l (1-F_v) a_v A / (pi n^2 (1 - A Q)),
 *       Q = 2 int_0^1 mu F_int(mu) exp(-2 tau / mu) dmu,
 *     a = exp(-tau / mu) along the refracted ray, Fresnel written out below,
 *     Q by a midpoint sum. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "render_harness.h"
#include "soak/measure.h"
#include "soak/render.h"
#include "soak/scene.h"

#define REPS 8
#define N_FILM 1.33
#define ALBEDO 0.7
#define ABSORPTION 1.5
#define THICKNESS 0.4

static int render_mean(const char *what, const char *text, int spp_total, double *mean, double *se)
{
    return rh_render_mean(what, text, ".", REPS, spp_total / REPS, 91, RH_ALL_PIXELS, mean, se);
}

/* Camera at cos_view from +z in the y-z plane, looking at the origin, tiny fov. */
static void camera_json(char *buf, size_t n, double cos_view)
{
    double s = sqrt(1 - cos_view * cos_view);
    snprintf(buf, n, "\"camera\": {\"position\": [0, %.17g, %.17g], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0], \"fov\": 0.5}",
             -5 * s, 5 * cos_view);
}

/* Unpolarised Fresnel reflectance from air onto index n at cos_i (> 0). */
static double fresnel_air(double cos_i, double n, double *cos_t)
{
    double sin_t2 = (1 - cos_i * cos_i) / (n * n);
    double ct = sqrt(1 - sin_t2);
    double rs = (cos_i - n * ct) / (cos_i + n * ct), rp = (n * cos_i - ct) / (n * cos_i + ct);
    *cos_t = ct;
    return 0.5 * (rs * rs + rp * rp);
}

static void test_sky_vs_measure(void)
{
    double cosv[2] = {0.8, 0.3};
    for (int i = 0; i < 2; ++i) {
        char cam[256], text[2048];
        camera_json(cam, sizeof cam, cosv[i]);
        snprintf(text, sizeof text,
                 "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 1000}, %s,"
                 " \"environment\": {\"type\": \"constant\", \"radiance\": 1},"
                 " \"materials\": {\"m\": {\"type\": \"wet\", \"film\": {\"ior\": %g, \"absorption\": %g, \"thickness\": %g},"
                 "   \"base\": {\"type\": \"lambert\", \"albedo\": %g}}},"
                 " \"objects\": [{\"type\": \"plane\", \"size\": [4000, 4000], \"material\": \"m\", \"wetness\": 0.6}]}",
                 cam, N_FILM, ABSORPTION, THICKNESS, ALBEDO);
        double m, se;
        if (!render_mean("film plane, sky", text, 32768, &m, &se)) continue;
        soak_measure_setup su;
        soak_measure_setup_default(&su);
        su.config = SOAK_MEASURE_FILM;
        su.cos_incidence = cosv[i];
        su.ior = N_FILM;
        su.base_albedo = ALBEDO;
        su.film_alpha = ABSORPTION;
        su.film_thickness = THICKNESS;
        su.paths = 400000;
        su.threads = 2;
        soak_measure_result res;
        if (!check_status("soak_measure", soak_measure_run(&su, &res), SOAK_OK)) continue;
        double ref = 0.6 * res.reflectance + 0.4 * ALBEDO, ref_se = 0.6 * res.reflectance_err;
        printf("  wetness 0.6, tau %.2f, cos_view %.2f: rendered %.5f +- %.5f, measure %.5f +- %.5f\n",
               ABSORPTION * THICKNESS, cosv[i], m, se, ref, ref_se);
        check_close("closed-form film under the sky = traced reflectance", m, ref, 4 * sqrt(se * se + ref_se * ref_se) + 1e-3);
    }
}

static void test_sun_vs_series(void)
{
    const double tau = ABSORPTION * THICKNESS, cos_l = 0.6, cos_v = 0.9, E = 2.0;
    /* Q: flux leaving the base sent back down by the film surface. */
    const int steps = 200000;
    double Q = 0;
    for (int k = 0; k < steps; ++k) {
        double mu = (k + 0.5) / steps, s_air2 = N_FILM * N_FILM * (1 - mu * mu), F = 1, ct;
        if (s_air2 < 1) F = fresnel_air(sqrt(1 - s_air2), N_FILM, &ct);
        Q += 2 * mu * F * exp(-2 * tau / mu) / steps;
    }
    double mu_l, mu_v;
    double tl = (1 - fresnel_air(cos_l, N_FILM, &mu_l)) * exp(-tau / mu_l);
    double tv = (1 - fresnel_air(cos_v, N_FILM, &mu_v)) * exp(-tau / mu_v);
    double f = tl * tv * ALBEDO / (SOAK_PI * N_FILM * N_FILM * (1 - ALBEDO * Q));
    double ref = E * cos_l * f;
    /* Sun in the x-z plane, camera in the y-z plane: off the mirror direction. */
    char cam[256], text[2048];
    camera_json(cam, sizeof cam, cos_v);
    snprintf(text, sizeof text,
             "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 1000}, %s,"
             " \"lights\": [{\"type\": \"sun\", \"direction\": [%.17g, 0, %.17g], \"irradiance\": %g}],"
             " \"materials\": {\"m\": {\"type\": \"wet\", \"film\": {\"ior\": %g, \"absorption\": %g, \"thickness\": %g},"
             "   \"base\": {\"type\": \"lambert\", \"albedo\": %g}}},"
             " \"objects\": [{\"type\": \"plane\", \"size\": [4000, 4000], \"material\": \"m\"}]}",
             cam, sqrt(1 - cos_l * cos_l), cos_l, E, N_FILM, ABSORPTION, THICKNESS, ALBEDO);
    double m, se;
    if (!render_mean("film plane, sun", text, 4096, &m, &se)) return;
    printf("  sun cos %.2f, view cos %.2f, tau %.2f: rendered %.6f +- %.6f, series %.6f (Q %.5f)\n", cos_l, cos_v, tau, m,
           se, ref, Q);
    check_close("closed-form film under the sun = bounce series", m, ref, 4 * se + 1e-4 * ref);
}

int main(void)
{
    test_sky_vs_measure();
    test_sun_vs_series();
    return check_finish();
}
