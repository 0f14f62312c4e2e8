/* The Dwivedi-guided subsurface walk in the renderer (render.walk_guide,
 * soak/dwivedi.h) against the analog walk (walk_guide 0), a second
 * estimator of the same pixels: a small wet subsurface sphere under a sun
 * and sky (HG g = 0.3 and isotropic) and a thin sheet lit from behind. Each
 * pair of image means must agree within 4 combined standard errors; the
 * guided walk must also report no NaN path or geometry error (checked by the
 * harness). */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "render_harness.h"

#define REPS 8

static const char *SPHERE =
    "{\"render\": {\"width\": 6, \"height\": 6, \"max_depth\": 64, \"walk_guide\": %g},"
    " \"camera\": {\"position\": [0, -4, 1.2], \"look_at\": [0, 0, 0.5], \"up\": [0, 0, 1], \"fov\": 12},"
    " \"environment\": {\"type\": \"constant\", \"radiance\": [0.25, 0.33, 0.5]},"
    " \"lights\": [{\"type\": \"sun\", \"direction\": [-0.35, -0.55, 0.76], \"irradiance\": [2.6, 2.45, 2.2]}],"
    " \"materials\": {\"stone\": {\"type\": \"wet\", \"film\": {\"ior\": 1.33, \"k\": 1},"
    "   \"base\": {\"type\": \"medium\", \"sigma_s\": [30, 30, 30], \"sigma_a\": [0.8, 1.4, 2.6],"
    "              \"g1\": %g, \"w\": 1, \"ior\": 1.5}}},"
    " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0.5], \"radius\": 0.3, \"material\": \"stone\"}]}";

static const char *SHEET =
    "{\"render\": {\"width\": 4, \"height\": 4, \"max_depth\": 64, \"walk_guide\": %g},"
    " \"camera\": {\"position\": [0, -6, 8], \"look_at\": [0, 0, 0], \"up\": [0, 0, 1], \"fov\": 10},"
    " \"lights\": [{\"type\": \"sun\", \"direction\": [0.3, 0.5, -0.81], \"irradiance\": 2.5}],"
    " \"materials\": {\"paper\": {\"type\": \"wet\", \"film\": {\"ior\": 1.33, \"k\": 1},"
    "   \"base\": {\"type\": \"medium\", \"sigma_s\": 20, \"sigma_a\": [0.03, 0.04, 0.06], \"ior\": 1.5,"
    "              \"g1\": %g, \"w\": 1}}},"
    " \"objects\": [{\"type\": \"box\", \"min\": [-4, -3, -0.2], \"max\": [4, 3, 0], \"material\": \"paper\"}]}";

static void compare(const char *what, const char *fmt, double g, double guide_prob, int spp_total)
{
    char text[2][2048];
    double m[2], se[2];
    const double guide[2] = {0.0, guide_prob};
    for (int k = 0; k < 2; ++k) {
        snprintf(text[k], sizeof text[k], fmt, guide[k], g);
        if (!rh_render_mean(what, text[k], ".", REPS, spp_total / REPS, 91 + 17 * k, RH_ALL_PIXELS, &m[k], &se[k]))
            return;
    }
    double s = hypot(se[0], se[1]);
    printf("  %s (g %g): analog %.6f +- %.6f, guided %.6f +- %.6f\n", what, g, m[0], se[0], m[1], se[1]);
    char label[160];
    snprintf(label, sizeof label, "%s (g %g): guided mean = analog mean (4 se)", what, g);
    check_close(label, m[1], m[0], 4 * s);
}

int main(void)
{
    compare("wet subsurface sphere", SPHERE, 0.3, 0.7, 2048);
    compare("wet subsurface sphere", SPHERE, 0.0, 0.7, 2048);
    /* Guided toward the entry face at 0.7, the back-lit sheet's estimate is
     * heavy-tailed (per-seed means of 1024 spp from 0.30 to 0.94 around the
     * analog 0.43): a mean of a few seeds is then mostly below the truth and
     * its standard error meaningless. At 0.25 the per-seed means stay within
     * 5 % of each other. */
    compare("back-lit wet sheet", SHEET, 0.71, 0.25, 2048);
    return check_finish();
}
