/* Partly wet surfaces shaded as a mixture of their dry, wet and pore BSDFs
 * (render_mix.c) against a second method: the same surface rendered fully
 * dry, fully wet with a film everywhere and fully wet with pore water only
 * (each a single BSDF, no mixing), combined with the shares the material
 * gives them, (1 - w), w (1 - pore share), w pore share. A wet lambert
 * plane under a sun and a sky; the means must agree within 4 combined
 * standard errors. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "render_harness.h"

#define REPS 8
#define SPP 64

static const char *PLANE =
    "{\"render\": {\"width\": 4, \"height\": 4, \"max_depth\": 8},"
    " \"camera\": {\"position\": [0, -3, 2], \"look_at\": [0, 0, 0], \"up\": [0, 0, 1], \"fov\": 20},"
    " \"environment\": {\"type\": \"constant\", \"radiance\": [0.25, 0.33, 0.5]},"
    " \"lights\": [{\"type\": \"sun\", \"direction\": [-0.35, 0.55, 0.5], \"irradiance\": [2.6, 2.45, 2.2]}],"
    " \"materials\": {\"m\": {\"type\": \"wet\","
    "   \"film\": {\"ior\": 1.33, \"k\": 1, \"thickness\": %g, \"absorption\": 3, \"pore_share\": %g},"
    "   \"base\": {\"type\": \"lambert\", \"albedo\": [0.45, 0.42, 0.38]}}},"
    " \"objects\": [{\"type\": \"quad\", \"origin\": [-6, -6, 0], \"edge_u\": [12, 0, 0], \"edge_v\": [0, 12, 0],"
    "   \"material\": \"m\", \"wetness\": %g}]}";

static int plane_mean(const char *what, double thickness, double pore, double wetness, uint64_t seed, double *m,
                      double *se)
{
    char text[2048];
    snprintf(text, sizeof text, PLANE, thickness, pore, wetness);
    return rh_render_mean(what, text, ".", REPS, SPP, seed, RH_ALL_PIXELS, m, se);
}

static void compare(double w, double pore)
{
    const double th = 0.05;
    double mix, smix, dry, sdry, film, sfilm, bare, sbare;
    if (!plane_mean("mixture", th, pore, w, 11, &mix, &smix) || !plane_mean("dry", th, pore, 0.0, 31, &dry, &sdry) ||
        !plane_mean("film", th, 0.0, 1.0, 51, &film, &sfilm) || !plane_mean("pore water", 0.0, 0.0, 1.0, 71, &bare, &sbare))
        return;
    double a = 1 - w, b = w * (1 - pore), c = w * pore;
    double want = a * dry + b * film + c * bare;
    double s = sqrt(smix * smix + a * a * sdry * sdry + b * b * sfilm * sfilm + c * c * sbare * sbare);
    printf("  wetness %g, pore share %g: mixture %.6f +- %.6f, combined %.6f +- %.6f\n", w, pore, mix, smix, want, s);
    char label[160];
    snprintf(label, sizeof label, "wetness %g, pore share %g: mixture mean = share-weighted single BSDFs (4 se)", w, pore);
    check_close(label, mix, want, 4 * s);
}

int main(void)
{
    compare(0.35, 0.0);
    compare(0.6, 0.4);
    return check_finish();
}
