/* Energy of the caustic photon map (render_photons.c), without rendering.
 *
 * A glass plate (index 1.5, 2 x 2, non-absorbing) floats over a deep
 * scattering slab (index 1.4, no film, albedo 0.8) under an overhead sun of
 * irradiance E. At normal incidence every ray stays on its vertical line, so
 * the flux the photon map must hold is known in closed form (incoherent
 * multiple reflections, Born & Wolf's stack sums):
 *   plate transmittance  T_p = (1 - R) / (1 + R),  R = ((n - 1) / (n + 1))^2,
 *   plate reflectance    R_p = 2R / (1 + R),
 *   into the slab        E A T_p (1 - F) / (1 - F R_p)   (F: air/slab at 0 deg;
 *                        light the slab reflects comes back from the plate),
 * and the photons are stored at their first scattering event, carrying the
 * scattered share albedo = sigma_s / sigma_t of it (the slab is 16 mean free
 * paths deep: exp(-16) of it would pass unscattered). The photon powers must
 * sum to that within 4 standard errors of the emission's binomial noise. All
 * photons lie under the plate. A second scene, the plate index-matched and
 * the slab reflecting nothing more, checks the same sum against E A albedo.
 * The stored power is what the gather turns into light: with it wrong every
 * caustic is off by the same factor. The gather's volume near a face (the
 * sphere below a plane at depth d above its centre) is checked against the
 * integral of its slices, pi (r^2 (d + r) - (d^3 + r^3) / 3). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "render_photons.h"
#include "soak/scene.h"

#define N_PHOTONS 200000

#define PLATE_SCENE(ior)                                                                                          \
    "{\"render\": {\"width\": 1, \"height\": 1},"                                                                 \
    " \"camera\": {\"position\": [0, -30, 10], \"look_at\": [0, 0, 0], \"up\": [0, 0, 1], \"fov\": 10},"            \
    " \"lights\": [{\"type\": \"sun\", \"direction\": [0, 0, 1], \"irradiance\": 2}],"                              \
    " \"materials\": {\"m\": {\"type\": \"wet\", \"film\": {\"coverage\": 0}, \"base\": {\"type\": \"medium\","     \
    "                 \"sigma_s\": 1, \"sigma_a\": 0.25, \"g1\": 0.3, \"ior\": 1.4}},"                              \
    "                 \"glass\": {\"type\": \"dielectric\", \"ior\": " ior "}},"                                     \
    " \"objects\": [{\"type\": \"box\", \"min\": [-40, -40, -12.8], \"max\": [40, 40, 0], \"material\": \"m\"},"     \
    "             {\"type\": \"box\", \"min\": [-1, -1, 2], \"max\": [1, 1, 2.5], \"material\": \"glass\"}]}"

static double sq(double x) { return x * x; }

/* Sums the stored photons' mean-channel power; counts those outside the plate's footprint. */
static int photon_power(const char *text, double *sum, double *se, long *outside)
{
    soak_scene sc;
    char err[512] = "";
    if (!check_status("parse the plate scene", soak_scene_parse(text, "plate", ".", &sc, err, sizeof err), SOAK_OK)) {
        printf("  %s\n", err);
        return 0;
    }
    rt_ctx c;
    memset(&c, 0, sizeof c);
    c.scene = &sc;
    rt_photon_map map;
    int ok = check_status("trace the photons", rt_photons_build(&c, N_PHOTONS, 0.05, 7, NULL, 0, &map), SOAK_OK);
    double s = 0, s2 = 0;
    *outside = 0;
    for (size_t i = 0; ok && i < map.n; ++i) {
        const rt_photon *p = &map.photons[i];
        double v = (p->power[0] + p->power[1] + p->power[2]) / 3.0;
        s += v;
        s2 += v * v;
        if (fabs(p->pos[0]) > 1.001 || fabs(p->pos[1]) > 1.001) ++*outside;
    }
    /* every emitted photon contributes v or 0: the standard error of the sum over N emissions */
    *sum = s;
    *se = sqrt(fmax(0.0, s2 - s * s / N_PHOTONS));
    printf("  %zu photons stored of %lld emitted, power %.5f +- %.5f\n", map.n, map.emitted, s, *se);
    rt_photons_free(&map);
    soak_scene_free(&sc);
    return ok;
}

/* The sphere's volume below the plane, summed slice by slice from its bottom. */
static double slices_below(double r, double d) { return SOAK_PI * (r * r * (d + r) - (d * d * d + r * r * r) / 3); }

static void check_clipped_volume(void)
{
    const double r = 0.3, depths[] = {0.0, 0.05, 0.15, 0.29};
    for (int i = 0; i < 4; ++i) {
        char what[96];
        snprintf(what, sizeof what, "gather volume below a face at depth %.2f r", depths[i] / r);
        check_close(what, rt_sphere_volume_below(r, depths[i]), slices_below(r, depths[i]), 1e-12);
    }
    check_close("gather volume beyond the radius: the whole sphere", rt_sphere_volume_below(r, 0.5), slices_below(r, r),
                1e-12);
    check_close("gather volume, no face known (INFINITY)", rt_sphere_volume_below(r, INFINITY), slices_below(r, r), 1e-12);
    check_close("gather volume, centre above the face: clamped to half", rt_sphere_volume_below(r, -0.1),
                slices_below(r, 0), 1e-12);
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    check_clipped_volume();
    const double E = 2.0, A = 4.0, albedo = 1.0 / 1.25;
    double R = sq(0.5 / 2.5), Tp = (1 - R) / (1 + R), Rp = 2 * R / (1 + R), F = sq(0.4 / 2.4);
    double want = E * A * Tp * (1 - F) / (1 - F * Rp) * albedo;
    double got, se;
    long outside;
    if (photon_power(PLATE_SCENE("1.5"), &got, &se, &outside)) {
        printf("  closed form: %.5f (T_plate %.5f, 1 - F_slab %.5f)\n", want, Tp, 1 - F);
        check_close("glass plate: stored power = E A T_p (1-F) albedo (4 sigma)", got, want, 4 * se);
        check_true("glass plate: every photon under the plate", outside == 0);
    }
    double want_im = E * A * (1 - F) * albedo; /* no plate reflection: nothing comes back */
    if (photon_power(PLATE_SCENE("1.0"), &got, &se, &outside)) {
        printf("  closed form: %.5f\n", want_im);
        check_close("index-matched plate: stored power = E A (1-F) albedo (4 sigma)", got, want_im, 4 * se);
        check_true("index-matched plate: every photon under the plate", outside == 0);
    }
    return check_finish();
}
