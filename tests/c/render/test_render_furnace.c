// ctest-label: slow
/* White furnace: a non-absorbing object in a uniform constant environment of
 * radiance L must look exactly like the environment (energy conservation and
 * unbiasedness of the whole path: film Fresnel + TIR, index factors, MIS with
 * environment sampling, the subsurface walk and its Russian roulette).
 * Reference: L itself (Kirchhoff / radiance invariance in an isothermal
 * enclosure). Every pixel must be within 3 standard errors or 1 % of L; the
 * standard error per pixel is measured from 16 independent renders. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "soak/render.h"
#include "soak/scene.h"

#define REPS 16

/* trace_films: trace a film over Lambert bounce by bounce instead of its closed form */
/* Returns the largest per-pixel standard error (-1 when it could not render). */
static double furnace(const char *what, const char *material_json, int spp_total, int trace_films)
{
    char text[4096];
    snprintf(text, sizeof text,
             "{ \"render\": {\"width\": 3, \"height\": 3, \"max_depth\": 100000},"
             "  \"camera\": {\"position\": [0, -4, 0.3], \"look_at\": [0, 0, 0], \"fov\": 30},"
             "  \"environment\": {\"type\": \"constant\", \"radiance\": 0.75},"
             "  \"materials\": {\"m\": %s},"
             "  \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\"}] }",
             material_json);
    soak_scene scene;
    char err[1024] = "";
    soak_status st = soak_scene_parse(text, what, ".", &scene, err, sizeof err);
    if (!check_status(what, st, SOAK_OK)) {
        printf("  %s\n", err);
        return -1;
    }
    const double L = 0.75;
    int W = scene.width, H = scene.height;
    double sum[6 * 6] = {0}, sum2[6 * 6] = {0};
    setvbuf(stdout, NULL, _IONBF, 0);
    long long capped = 0, nan_paths = 0, geom_errors = 0;
    for (int r = 0; r < REPS; ++r) {
        soak_render_options opt;
        soak_render_options_default(&opt);
        opt.threads = 2;
        opt.spp = spp_total / REPS;
        opt.seed = 1000 + (uint64_t)r;
        opt.trace_films = trace_films;
        soak_image img;
        soak_render_stats stats;
        if (!check_status("render", soak_render(&scene, &opt, &img, &stats, err, sizeof err), SOAK_OK)) break;
        capped += stats.capped;
        nan_paths += stats.nan_paths;
        geom_errors += stats.geometry_errors;
        for (int i = 0; i < W * H; ++i) {
            double v = (img.pixels[3 * i] + img.pixels[3 * i + 1] + img.pixels[3 * i + 2]) / 3.0;
            sum[i] += v;
            sum2[i] += v * v;
        }
        soak_image_free(&img);
    }
    double worst = 0, mean = 0, worst_sigma = 0, max_se = 0;
    int bad = 0;
    for (int i = 0; i < W * H; ++i) {
        double m = sum[i] / REPS, var = (sum2[i] / REPS - m * m) * REPS / (REPS - 1);
        double se = sqrt(fmax(var, 0.0) / REPS);
        max_se = fmax(max_se, se);
        double dev = fabs(m - L);
        if (dev > worst) worst = dev, worst_sigma = se;
        if (dev > 3 * se && dev > 0.01 * L) bad++;
        mean += m / (W * H);
    }
    printf("  %s: image mean %.5f (L = %.2f), worst pixel |diff| %.5f (its standard error %.5f), capped %lld\n", what,
           mean, L, worst, worst_sigma, capped);
    check_true("every pixel within 3 sigma or 1 % of the environment", bad == 0);
    check_rel("image mean equals the environment (1 %)", mean, L, 0.01);
    check_true("no capped paths", capped == 0);
    check_close("NaN paths", (double)nan_paths, 0, 0);
    check_close("geometry errors", (double)geom_errors, 0, 0);
    soak_scene_free(&scene);
    return max_se;
}

int main(void)
{
    furnace("film over white Lambert",
            "{\"type\": \"wet\", \"film\": {\"ior\": 1.33}, \"base\": {\"type\": \"lambert\", \"albedo\": 1}}", 65536, 0);
    furnace("film over white Lambert, traced (closed form off: light paths through the film, TIR)",
            "{\"type\": \"wet\", \"film\": {\"ior\": 1.33}, \"base\": {\"type\": \"lambert\", \"albedo\": 1}}", 65536, 1);
    furnace("film over white Lambert, half wet (stochastic coverage)",
            "{\"type\": \"wet\", \"film\": {\"ior\": 1.5, \"coverage\": 0.5}, \"base\": {\"type\": \"lambert\", \"albedo\": 1}}",
            65536, 0);
    furnace("film over a non-absorbing scattering medium",
            "{\"type\": \"wet\", \"film\": {\"ior\": 1.33}, \"base\": {\"type\": \"medium\", \"sigma_s\": 8, "
            "\"sigma_a\": 0, \"g1\": 0.8, \"g2\": -0.2, \"w\": 0.7, \"ior\": 1.5}}",
            65536, 0);
    furnace("film (k = 3) over a non-absorbing coloured-extinction medium",
            "{\"type\": \"wet\", \"film\": {\"ior\": 1.33, \"k\": 3}, \"base\": {\"type\": \"medium\", \"sigma_s\": [4, 8, 16], "
            "\"sigma_a\": 0, \"g1\": 0.3, \"g2\": -0.3, \"w\": 0.5, \"ior\": 1.2}}",
            65536, 0);
    furnace("dry scattering medium (no film)",
            "{\"type\": \"wet\", \"base\": {\"type\": \"medium\", \"sigma_s\": 8, \"g1\": 0.5, \"ior\": 1.5}, "
            "\"film\": {\"coverage\": 0}}",
            65536, 0);
    /* Radiance convention (rt_ctx.h, rt_rr_weight): inside glass beta
     * holds 1/n^2 but roulette plays on beta * eta_scale = 1, so it never
     * fires and every path returns L exactly: zero variance. Playing it on
     * beta alone kills 56 % of the paths inside n = 1.5 glass (noise). */
    double se = furnace("smooth glass", "{\"type\": \"dielectric\", \"ior\": 1.5}", 16384, 0);
    check_close("smooth glass: zero variance (roulette never plays on the 1/n^2 factor)", se, 0, 1e-6);
    return check_finish();
}
