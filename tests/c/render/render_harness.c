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

/* Adds the estimates of one render to the sums: its first pixel (all = 0) or every pixel. */
static void rgb_sums(const soak_image *img, int all, double s[3], double s2[3], double *q, double *q2, int *n)
{
    int count = all ? img->width * img->height : 1;
    for (int i = 0; i < count; ++i) {
        const float *p = img->pixels + (size_t)i * img->channels;
        for (int c = 0; c < 3; ++c) {
            double x = p[c];
            s[c] += x;
            s2[c] += x * x;
        }
        double rb = p[0] / fmax(p[2], 1e-300);
        *q += rb;
        *q2 += rb * rb;
    }
    *n += count;
}

int rh_render_rgb(const char *what, const char *text, int reps, int spp, uint64_t seed, rh_rgb *e)
{
    soak_scene scene;
    char err[1024] = "";
    if (!check_status(what, soak_scene_parse(text, what, ".", &scene, err, sizeof err), SOAK_OK)) {
        printf("  %s\n", err);
        return 0;
    }
    double s[3] = {0}, s2[3] = {0}, q = 0, q2 = 0;
    int ok = 1, n = 0;
    for (int r = 0; r < reps && ok; ++r) {
        soak_render_options opt;
        soak_render_options_default(&opt);
        opt.threads = 2;
        opt.spp = spp;
        opt.seed = seed + (uint64_t)r;
        soak_image img;
        soak_render_stats stats;
        ok = check_status(what, soak_render(&scene, &opt, &img, &stats, err, sizeof err), SOAK_OK);
        if (!ok) break;
        ok = check_true("no NaN path, no geometry error", stats.nan_paths == 0 && stats.geometry_errors == 0);
        rgb_sums(&img, reps == 1, s, s2, &q, &q2, &n);
        soak_image_free(&img);
    }
    soak_scene_free(&scene);
    for (int c = 0; c < 3 && ok; ++c) {
        e->mean[c] = s[c] / n;
        e->se[c] = sqrt(fmax(0.0, (s2[c] / n - e->mean[c] * e->mean[c]) / (n - 1)));
    }
    if (ok) e->rb_se = sqrt(fmax(0.0, (q2 / n - (q / n) * (q / n)) / (n - 1)));
    return ok;
}
