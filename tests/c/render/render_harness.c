#include "render_harness.h"

#include <math.h>
#include <stdio.h>

#include "check.h"
#include "soak/image.h"
#include "soak/render.h"
#include "soak/scene.h"

int rh_render_mean(const char *what, const char *text, const char *base_dir, int reps, int spp_per_rep,
                   uint64_t seed_base, rh_reduce reduce, double *mean, double *se)
{
    return rh_render_mean_opt(what, text, base_dir, reps, spp_per_rep, seed_base, reduce, 0, mean, se);
}

int rh_render_mean_opt(const char *what, const char *text, const char *base_dir, int reps, int spp_per_rep,
                       uint64_t seed_base, rh_reduce reduce, int trace_films, double *mean, double *se)
{
    soak_scene scene;
    char err[1024] = "";
    if (!check_status(what, soak_scene_parse(text, what, base_dir, &scene, err, sizeof err), SOAK_OK)) {
        printf("  %s\n", err);
        return 0;
    }
    double s = 0, s2 = 0;
    long long nan_paths = 0, geom_errors = 0;
    for (int r = 0; r < reps; ++r) {
        soak_render_options opt;
        soak_render_options_default(&opt);
        opt.threads = 2;
        opt.spp = spp_per_rep;
        opt.seed = seed_base + (uint64_t)r;
        opt.trace_films = trace_films;
        soak_image img;
        soak_render_stats stats;
        if (!check_status("render", soak_render(&scene, &opt, &img, &stats, err, sizeof err), SOAK_OK)) {
            printf("  %s: %s\n", what, err);
            soak_scene_free(&scene);
            return 0;
        }
        int n = reduce == RH_ALL_PIXELS ? img.width * img.height * 3 : 3;
        double v = 0;
        for (int i = 0; i < n; ++i) v += img.pixels[i];
        v /= n;
        s += v;
        s2 += v * v;
        soak_image_free(&img);
        nan_paths += stats.nan_paths;
        geom_errors += stats.geometry_errors;
    }
    soak_scene_free(&scene);
    if (nan_paths || geom_errors) {
        printf("FAIL %s: %lld NaN paths, %lld geometry errors\n", what, nan_paths, geom_errors);
        check_true("no NaN path, no geometry error", 0);
    }
    *mean = s / reps;
    *se = sqrt(fmax(0.0, (s2 / reps - *mean * *mean) / (reps - 1)));
    return 1;
}
