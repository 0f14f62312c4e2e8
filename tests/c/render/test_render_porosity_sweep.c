/* The flowerpot porosity sweep of docs/gallery.md (scenes/gallery/
 * flowerpot_porosity.json: the porous model of [Hnat06], terracotta albedo
 * (0.555, 0.212, 0.11), ks 0.05, ks_water 0.3, roughness 0.3, pores full)
 * against seed 002's statement of [Hnat06] sec. 4, Fig. 5: "when alpha_poro
 * increases, the surface becomes darker and more specular". At the scene's
 * light (its sun and sky), on a face of the pot turned to the camera:
 *
 *  1. the wet pot's lit body, seen from the scene's camera: its luminance
 *     falls strictly from alpha_poro 0 to 0.5 (each step beyond 4 standard
 *     errors), and the sweep spans a visible range: the most porous pot at
 *     most 0.85 of the least (a 15 % luminance step, several times the ~2 %
 *     the eye tells apart side by side, Weber);
 *  2. the same face seen in the sun's mirror direction (the highlight): the
 *     wet pot's highlight grows strictly with alpha_poro.
 * The dry pot is rendered too and its wet/dry ratio printed (in this model
 * the empty pores darken the dry surface with alpha_poro as well, so the
 * ratio is not what the statement is about).
 * Printed per alpha_poro: wet/dry luminance and the highlight, the numbers
 * docs/gallery.md quotes. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "render_harness.h"

#define N_PORO 6

/* Channel mean of one pixel of a vertical wall (normal
 * -y) of the pot's porous material at porosity poro and object wetness wet,
 * seen from direction view (unit, toward the camera), under the scene's sun
 * and sky. */
static int wall(double poro, int wet, const double view[3], double *lum, double *se)
{
    char text[2048];
    snprintf(text, sizeof text,
             "{\"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 16},"
             " \"camera\": {\"position\": [%.9g, %.9g, %.9g], \"look_at\": [0, 0, 0], \"up\": [0, 0, 1], \"fov\": 0.5},"
             " \"environment\": {\"type\": \"constant\", \"radiance\": 0.25},"
             " \"lights\": [{\"type\": \"sun\", \"direction\": [-0.4, -0.8, 0.8], \"irradiance\": 3.0}],"
             " \"materials\": {\"pot\": {\"type\": \"porous\", \"albedo\": [0.555, 0.212, 0.11], \"porosity\": %g,"
             "   \"fill\": 1, \"roughness\": 0.3, \"ks\": 0.05, \"ks_water\": 0.3}},"
             " \"objects\": [{\"type\": \"plane\", \"center\": [0, 0, 0], \"normal\": [0, -1, 0], \"size\": [100, 100],"
             "   \"material\": \"pot\", \"wetness\": %d}]}",
             5 * view[0], 5 * view[1], 5 * view[2], poro, wet);
    return rh_render_mean("porous wall", text, ".", 8, 1024, 17, RH_FIRST_PIXEL, lum, se);
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    /* the scene's camera (0, -1.6, 0.55) seen from a pot's front at (0, -0.1, 0.08) */
    double cam[3] = {0, -1.5, 0.47}, n = sqrt(cam[1] * cam[1] + cam[2] * cam[2]);
    cam[1] /= n;
    cam[2] /= n;
    /* the sun (-0.4, -0.8, 0.8)/1.2 mirrored about the wall's normal -y */
    const double mirror[3] = {0.4 / 1.2, -0.8 / 1.2, -0.8 / 1.2};
    double body[N_PORO], body_se[N_PORO], spec[N_PORO], spec_se[N_PORO];
    for (int i = 0; i < N_PORO; ++i) {
        double poro = 0.1 * i, ld, sd;
        if (!wall(poro, 1, cam, &body[i], &body_se[i]) || !wall(poro, 0, cam, &ld, &sd) ||
            !wall(poro, 1, mirror, &spec[i], &spec_se[i]))
            return check_finish();
        printf("  alpha_poro %.1f: body wet %.5f +- %.5f (dry %.5f, wet/dry %.3f); wet highlight %.4f +- %.4f\n", poro,
               body[i], body_se[i], ld, body[i] / ld, spec[i], spec_se[i]);
    }
    for (int i = 1; i < N_PORO; ++i) {
        char what[160];
        snprintf(what, sizeof what, "alpha_poro %.1f -> %.1f: wet body darker (> 4 sigma)", 0.1 * (i - 1), 0.1 * i);
        check_true(what, body[i - 1] - body[i] > 4 * hypot(body_se[i - 1], body_se[i]));
        snprintf(what, sizeof what, "alpha_poro %.1f -> %.1f: wet highlight brighter (> 4 sigma)", 0.1 * (i - 1), 0.1 * i);
        check_true(what, spec[i] - spec[i - 1] > 4 * hypot(spec_se[i - 1], spec_se[i]));
    }
    printf("  the sweep's span: wet body %.3f of alpha_poro 0's at 0.5, highlight %.2fx\n", body[N_PORO - 1] / body[0],
           spec[N_PORO - 1] / spec[0]);
    check_true("the sweep spans a visible range (alpha_poro 0.5 at most 0.85 of 0)", body[N_PORO - 1] < 0.85 * body[0]);
    return check_finish();
}
