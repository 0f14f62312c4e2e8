// ctest-label: slow
/* The renderer's traced film (bsdf_walk.c's stochastic eval, pdf and
 * sample, shaded by render_surface.c like any BSDF): refraction into the film, light sampling through it, internal reflection and total
 * internal reflection at its underside, and the Snell Jacobian in the MIS
 * weights. A film over a Lambert base is normally replaced by its closed
 * form; soak_render_options.trace_films forces the traced path, so the
 * closed form becomes an independent reference for it.
 *
 *  1. Film over Lambert 0.5 under a uniform sky of radiance 1: the radiance
 *     toward the camera is the directional albedo (reciprocity), Lekner &
 *     Dorf's closed form (soak_film_albedo_dir).
 *  2. The same lit by a sun only (light sampling through the film, the only
 *     strategy for a delta light): L = f(wi, wo) E cos_i with f the closed-
 *     form BRDF (soak_film_brdf).
 *  3. The same lit by a wide sphere light (light sampling and BSDF sampling
 *     combined by MIS): L = int f L_e cos dw over the light's cone, by
 *     quadrature here, plus the film top's mirror image of the light.
 *  4. A GGX conductor base under a film, uniform sky: the directional albedo
 *     F12 + (1 - F12) E(mu2), where E, the fraction escaping the film after
 *     any number of base reflections and internal (total) reflections, solves
 *     E(mu) = int K(mu, mu') [(1 - F21(mu')) + F21(mu') E(mu')] dmu' with the
 *     azimuth-integrated base kernel K (mirror reflection keeps the azimuth,
 *     so the azimuth integrates out). Solved by Gauss-Legendre quadrature
 *     split at the critical angle; the base BRDF is soak_ggx_brdf_conductor_raw,
 *     checked on its own in test_ggx.c, and Fresnel is written out here.
 *
 * The white furnace of the traced film is in test_render_furnace.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "testutil.h"
#include "render_harness.h"
#include "soak/film.h"
#include "soak/ggx.h"

#define REPS 8
#define N2 1.33

static int traced(const char *what, const char *text, int spp_total, double *mean, double *se)
{
    return rh_render_mean_opt(what, text, ".", REPS, spp_total / REPS, 91, RH_ALL_PIXELS, 1, mean, se);
}

/* Camera at theta_deg from the +z normal in the y-z plane, tiny fov. */
static void scene_text(char *buf, size_t n, double theta_deg, const char *lights, const char *base)
{
    double t = theta_deg * SOAK_PI / 180.0;
    snprintf(buf, n,
             "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 1000},"
             " \"camera\": {\"position\": [0, %.17g, %.17g], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0], \"fov\": 0.5},"
             " %s, \"materials\": {\"m\": {\"type\": \"wet\", \"film\": {\"ior\": %g}, \"base\": %s}},"
             " \"objects\": [{\"type\": \"plane\", \"size\": [4000, 4000], \"material\": \"m\"}]}",
             -5 * sin(t), 5 * cos(t), lights, N2, base);
}

static double fresnel(double n1, double n2, double ci);

static const char *LAMBERT = "{\"type\": \"lambert\", \"albedo\": 0.5}";

static void test_sky_lambert(void)
{
    const double th[2] = {0, 60};
    for (int i = 0; i < 2; ++i) {
        char text[2048];
        scene_text(text, sizeof text, th[i], "\"environment\": {\"type\": \"constant\", \"radiance\": 1}", LAMBERT);
        double m, se, ref = NAN;
        if (!traced("traced film, sky", text, 131072, &m, &se)) continue;
        soak_film film = {N2, 0, 0};
        soak_film_albedo_dir(&film, 0.5, cos(th[i] * SOAK_PI / 180), &ref);
        printf("  traced film over Lambert 0.5, sky, view %g deg: %.5f +- %.5f, Lekner-Dorf %.5f\n", th[i], m, se, ref);
        check_close("traced film under a sky = closed-form directional albedo", m, ref, 4 * se + 1e-3);
    }
}

static void test_sun_lambert(void)
{
    /* sun at 40 deg in the x-z plane, camera at 0 and 60 deg in the y-z plane */
    const double ts = 40 * SOAK_PI / 180, th[2] = {0, 60};
    char lights[256];
    snprintf(lights, sizeof lights, "\"lights\": [{\"type\": \"sun\", \"direction\": [%.17g, 0, %.17g], \"irradiance\": 2}]",
             sin(ts), cos(ts));
    for (int i = 0; i < 2; ++i) {
        char text[2048];
        scene_text(text, sizeof text, th[i], lights, LAMBERT);
        double m, se, f = NAN, tv = th[i] * SOAK_PI / 180;
        if (!traced("traced film, sun", text, 65536, &m, &se)) continue;
        soak_film film = {N2, 0, 0};
        soak_film_brdf(&film, 0.5, soak_v3(sin(ts), 0, cos(ts)), soak_v3(0, -sin(tv), cos(tv)), &f);
        double ref = f * 2 * cos(ts);
        printf("  traced film over Lambert 0.5, sun at 40 deg, view %g deg: %.5f +- %.5f, closed form %.5f\n", th[i], m,
               se, ref);
        check_close("traced film under a sun = closed-form BRDF x E cos", m, ref, 4 * se + 1e-3);
    }
}

static void test_sphere_lambert(void)
{
    /* sphere light of radiance 1, radius 9, centre 12 away at 40 deg: a wide
     * cone, where light and BSDF sampling have comparable pdfs (MIS matters) */
    const double ts = 40 * SOAK_PI / 180, D = 12, R = 9, Le = 1;
    soak_vec3 c = soak_v3(D * sin(ts), 0, D * cos(ts));
    char lights[256];
    snprintf(lights, sizeof lights,
             "\"lights\": [{\"type\": \"sphere\", \"center\": [%.17g, 0, %.17g], \"radius\": %g, \"radiance\": %g}]", c.x,
             c.z, R, Le);
    /* reference: midpoint rule over the cone (cos from cos_max to 1, azimuth) */
    const double cmax = sqrt(1 - (R / D) * (R / D));
    soak_vec3 ax = soak_v3(sin(ts), 0, cos(ts)), u = soak_v3(cos(ts), 0, -sin(ts)), v = soak_v3(0, 1, 0);
    const double tv = 20 * SOAK_PI / 180; /* its mirror direction is 4.7 deg inside the light cone */
    soak_vec3 wo = soak_v3(0, -sin(tv), cos(tv));
    soak_film film = {N2, 0, 0};
    double ref = 0;
    const int NC = 200, NP = 200;
    for (int a = 0; a < NC; ++a) {
        double ct = cmax + (1 - cmax) * (a + 0.5) / NC, st = sqrt(1 - ct * ct);
        for (int b = 0; b < NP; ++b) {
            double ph = 2 * SOAK_PI * (b + 0.5) / NP, f = 0;
            soak_vec3 wi = soak_v3_add(soak_v3_scale(ax, ct),
                                       soak_v3_add(soak_v3_scale(u, st * cos(ph)), soak_v3_scale(v, st * sin(ph))));
            if (wi.z > 0) soak_film_brdf(&film, 0.5, wi, wo, &f);
            ref += f * Le * wi.z * (1 - cmax) / NC * 2 * SOAK_PI / NP;
        }
    }
    /* the film top's mirror image of the camera direction: Fresnel x Le when it meets the light */
    soak_vec3 mirror = soak_v3(0, sin(tv), cos(tv));
    double cd = soak_v3_dot(c, mirror);
    if (cd > 0 && soak_v3_dot(c, c) - cd * cd < R * R) ref += fresnel(1, N2, cos(tv)) * Le;
    char text[2048];
    scene_text(text, sizeof text, 20, lights, LAMBERT);
    double m, se;
    if (!traced("traced film, sphere light", text, 65536, &m, &se)) return;
    printf("  traced film over Lambert 0.5, sphere light, view 20 deg: %.5f +- %.5f, quadrature %.5f\n", m, se, ref);
    check_close("traced film under a sphere light (MIS) = closed-form BRDF over the light's cone", m, ref,
                4 * se + 1e-3);
}

/* ---- 4. GGX base under a film ---- */

/* unpolarised Fresnel reflectance, from index n1 into n2, cos in n1 */
static double fresnel(double n1, double n2, double ci)
{
    double s2 = (n1 / n2) * (n1 / n2) * (1 - ci * ci);
    if (s2 >= 1) return 1.0;
    double ct = sqrt(1 - s2);
    double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct), rp = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
    return 0.5 * (rs * rs + rp * rp);
}

typedef struct base_ref {
    double alpha, eta, k; /* relative to the film */
} base_ref;

/* K(mu -> mu') weight for one node: int f(wi, wo) mu' dphi, times the node weight. */
static double kernel(const base_ref *b, double mu, double mu2, double wnode)
{
    const int NP = 256;
    soak_vec3 wi = soak_v3(sqrt(1 - mu * mu), 0, mu);
    double s = sqrt(fmax(0, 1 - mu2 * mu2)), sum = 0;
    for (int p = 0; p < NP; ++p) {
        double ph = SOAK_PI * (p + 0.5) / NP; /* symmetric in phi: half the circle, twice */
        soak_vec3 wo = soak_v3(s * cos(ph), s * sin(ph), mu2);
        sum += soak_ggx_brdf_conductor_raw(b->alpha, b->eta, b->k, wi, wo);
    }
    return sum * 2 * SOAK_PI / NP * mu2 * wnode;
}

#define NQ 48
static double ggx_film_albedo(const base_ref *b, double cos_view)
{
    double x[2 * NQ], w[2 * NQ], F[2 * NQ], E[2 * NQ];
    double mc = sqrt(1 - 1 / (N2 * N2)); /* critical cosine in the film */
    tu_gauss_legendre(NQ, 0, mc, x, w);
    tu_gauss_legendre(NQ, mc, 1, x + NQ, w + NQ);
    for (int j = 0; j < 2 * NQ; ++j) F[j] = fresnel(N2, 1, x[j]);
    /* (I - K diag F) E = K (1 - F), by fixed-point iteration (K F has norm < 1) */
    static double K[2 * NQ][2 * NQ];
    for (int i = 0; i < 2 * NQ; ++i)
        for (int j = 0; j < 2 * NQ; ++j) K[i][j] = kernel(b, x[i], x[j], w[j]);
    for (int i = 0; i < 2 * NQ; ++i) E[i] = 0;
    for (int it = 0; it < 2000; ++it) {
        double delta = 0;
        for (int i = 0; i < 2 * NQ; ++i) {
            double e = 0;
            for (int j = 0; j < 2 * NQ; ++j) e += K[i][j] * ((1 - F[j]) + F[j] * E[j]);
            delta = fmax(delta, fabs(e - E[i]));
            E[i] = e;
        }
        if (delta < 1e-13) break;
    }
    double mu2 = sqrt(1 - (1 - cos_view * cos_view) / (N2 * N2)), e = 0;
    for (int j = 0; j < 2 * NQ; ++j) e += kernel(b, mu2, x[j], w[j]) * ((1 - F[j]) + F[j] * E[j]);
    double F12 = fresnel(1, N2, cos_view);
    return F12 + (1 - F12) * e;
}

static void test_sky_ggx(void)
{
    /* conductor eta 0.4, k 2.6 relative to air, roughness 0.3 */
    const base_ref b = {0.3, 0.4 / N2, 2.6 / N2};
    const char *base = "{\"type\": \"ggx\", \"eta\": 0.4, \"k\": 2.6, \"roughness\": 0.3}";
    const double th[3] = {0, 60, 80};
    for (int i = 0; i < 3; ++i) {
        char text[2048];
        scene_text(text, sizeof text, th[i], "\"environment\": {\"type\": \"constant\", \"radiance\": 1}", base);
        double m, se;
        if (!traced("traced film over GGX, sky", text, 131072, &m, &se)) continue;
        double ref = ggx_film_albedo(&b, cos(th[i] * SOAK_PI / 180));
        printf("  film over GGX conductor, sky, view %g deg: traced %.5f +- %.5f, integral equation %.5f\n", th[i], m,
               se, ref);
        check_close("film over GGX under a sky = directional albedo by quadrature", m, ref, 4 * se + 1e-3);
    }
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    test_sky_lambert();
    test_sun_lambert();
    test_sphere_lambert();
    test_sky_ggx();
    return check_finish();
}
