/* soak render: the reference path tracer on a JSON scene (scenes/README.md). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "cli.h"
#include "soak/advise.h"
#include "soak/denoise.h"
#include "soak/image.h"
#include "soak/io_guard.h"
#include "soak/render.h"
#include "soak/scene.h"

static const char *const CMD = "render";
static volatile sig_atomic_t interrupted = 0;

/* Memory of a render per pixel: the sums (3 doubles) and sample count (an
 * int) of soak_render, its float RGB image and the encoder's copy of it. */
#define RENDER_BYTES_PER_PIXEL (3 * 8 + 4 + 3 * 4 + 3 * 4)
/* --denoise adds the luminance sums (2 doubles), the variance, the features
 * (9 floats) and the filter's buffers (9 floats). */
#define DENOISE_BYTES_PER_PIXEL (2 * 8 + 4 + 9 * 4 + 9 * 4)
/* Feature rays per pixel for --denoise, spread over the pixel and the lens. */
#define DENOISE_LENS_SAMPLES 8
#define RENDER_MAX_MIB 4096

static void on_sigint(int sig)
{
    (void)sig;
    interrupted = 1;
}

typedef struct render_args {
    const char *scene_path, *out_path;
    long spp, threads, seed, width, height, max_depth;
    double time_limit, auto_tol, target_error;
    int quiet, denoise;
} render_args;

/* --time's floor: 0 would mean no limit, which is leaving --time out. */
#define RENDER_MIN_TIME 0.001

#define F(field) CLI_FIELD(render_args, field)
static const cli_opt render_opts[] = {
    {"--output", "-o", CLI_OPT_STRING, F(out_path), .meta = "FILE",
     .help = "output image (required; never one of the scene's inputs)"},
    {"--spp", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_RENDER_MAX_SPP, F(spp), .meta = "N",
     .help = "samples per pixel, %R (default: the scene's render.spp)"},
    {"--threads", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_RENDER_MAX_THREADS, F(threads), .meta = "N",
     .help = "worker threads, %R (default: the number of CPUs)"},
    {"--seed", NULL, CLI_OPT_INT, .ilo = 0, .ihi = INT32_MAX, F(seed), .meta = "S",
     .help = "random seed (default 1); same seed + spp -> identical pixels"},
    {"--time", NULL, CLI_OPT_DOUBLE, .lo = RENDER_MIN_TIME, .hi = SOAK_RENDER_MAX_TIME, F(time_limit), .meta = "T",
     .help = "stop after T seconds and keep what is done"},
    {"--target-error", NULL, CLI_OPT_DOUBLE, .lo = 1e-4, .hi = 1, F(target_error), .meta = "E",
     .help = "render to an error: each 16x16 tile stops once every pixel has 16\n"
             "samples and the standard error of its mean luminance is below\n"
             "E x max(mean, 0.01) (e.g. 0.02); --spp is then the cap. For\n"
             "pictures: a test's numbers want a fixed, stated sample count"},
    {"--width", NULL, CLI_OPT_SIZE, .ihi = SOAK_RENDER_MAX_SIZE, F(width), .meta = "W",
     .help = "image width, %R (default: the scene's render.width)"},
    {"--height", NULL, CLI_OPT_SIZE, .ihi = SOAK_RENDER_MAX_SIZE, F(height), .meta = "H",
     .help = "image height, %R (default: the scene's render.height); a render takes\n"
             "52 bytes per pixel and is refused above 4096 MiB (about 9000^2)"},
    {"--max-depth", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_RENDER_MAX_DEPTH, F(max_depth), .meta = "N",
     .help = "path length cap, %R (default: the scene's render.max_depth)"},
    {"--auto-model", NULL, CLI_OPT_DOUBLE, .lo = CLI_ADVISE_MIN_TOL, .hi = SOAK_ADVISE_MAX_TOL, F(auto_tol),
     .meta = "T",
     .help = "render each material through the cheapest model within a\n"
             "relative error T of its full description (soak advise;\n"
             "the choices are printed on stderr)"},
    {"--denoise", NULL, CLI_OPT_FLAG, .flag = 1, F(denoise),
     .help = "filter the picture: fireflies removed, then an edge-avoiding\n"
             "a-trous filter guided by each pixel's variance and by what the\n"
             "camera sees first (normal, depth, object, wetness; soak/denoise.h).\n"
             "It removes energy where it removes fireflies: for pictures only,\n"
             "never for numbers (no test reads a denoised render)"},
    {"--quiet", "-q", CLI_OPT_FLAG, .flag = 1, F(quiet), .help = "no statistics on stdout"},
};
#undef F

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak render SCENE.json -o OUT.exr|OUT.png [options]\n\n"
            "Renders a JSON scene (format: scenes/README.md) with the reference path tracer:\n"
            "next-event estimation with MIS, the wet film of Jensen et al. 1999 Eq. 1-4 and a\n"
            "subsurface random walk. EXR/HDR/TIFF outputs hold linear float radiance; PNG/JPEG are\n"
            "tone mapped: multiplied by 2^exposure (camera.exposure), then the sRGB curve, clamped\n"
            "to [0,1]. Ctrl-C stops early, writes the samples taken so far and exits 130.\n\n"
            "options:\n");
    const cli_opt_table tables[] = {CLI_TABLE(render_opts, NULL)};
    cli_opts_help(out, tables, 1);
    fprintf(out, "\nexample:\n"
                 "  soak render scenes/default_wet_dry.json -o wet_dry.png --spp 32 --threads 2\n");
}

static int scene_arg(void *ctx, const char *arg)
{
    render_args *a = ctx;
    if (a->scene_path) {
        cli_error(CMD, "unexpected argument '%s': only one scene file", arg);
        return 0;
    }
    a->scene_path = arg;
    return 1;
}

static int has_ext(const char *path, const char *ext)
{
    size_t n = strlen(path), e = strlen(ext);
    return n > e && strcasecmp(path + n - e, ext) == 0;
}

static void progress_cb(void *ctx, double fraction)
{
    cli_progress_update((cli_progress *)ctx, fraction);
}

/* --auto-model: soak advise's choices applied to the scene. */
static soak_status auto_model(soak_scene *scene, double tol)
{
    soak_advice *adv = NULL;
    int n = 0;
    char err[4096] = "";
    soak_status st = soak_advise_scene(scene, tol, NULL, &adv, &n, err, sizeof err);
    if (st == SOAK_OK) st = soak_advise_apply(scene, adv, n, err, sizeof err);
    if (st != SOAK_OK) cli_error(CMD, "--auto-model: %s", err[0] ? err : soak_status_str(st));
    else cli_advise_print(stderr, adv, n, tol);
    free(adv);
    return st;
}

/* Returns -1 to go on, else the exit code. */
static int parse_args(int argc, char **argv, render_args *a)
{
    memset(a, 0, sizeof *a);
    a->threads = sysconf(_SC_NPROCESSORS_ONLN);
    if (a->threads < 1) a->threads = 1;
    a->seed = 1;
    const cli_spec spec = {"render", "option", "soak render --help", usage, scene_arg, a};
    const cli_opt_table tables[] = {CLI_TABLE(render_opts, a)};
    int rc = cli_opts_parse(&spec, tables, 1, argc, argv);
    if (rc >= 0) return rc;
    if (!a->scene_path) {
        cli_error(CMD, "SCENE.json: missing scene file (see soak render --help)");
        return SOAK_EXIT_USAGE;
    }
    if (!a->out_path) {
        cli_error(CMD, "-o: missing output image (.exr or .png)");
        return SOAK_EXIT_USAGE;
    }
    return -1;
}

/* -o: not the scene, a writable folder, a known extension (*toned: an 8/16
 * bit format). Returns -1 to go on, else the exit code. */
static int check_output(const render_args *a, int *toned)
{
    char err[4096] = "";
    if (soak_io_check_output("-o", a->out_path, &a->scene_path, 1, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "%s (the scene file)", err);
        return SOAK_EXIT_USAGE;
    }
    soak_status pst = soak_path_check_writable(a->out_path, err, sizeof err);
    if (pst == SOAK_ERR_ARG) {
        cli_error(CMD, "-o: %s", err);
        return SOAK_EXIT_USAGE;
    }
    const char *out = a->out_path;
    int linear = has_ext(out, ".exr") || has_ext(out, ".hdr") || has_ext(out, ".tif") || has_ext(out, ".tiff");
    *toned = has_ext(out, ".png") || has_ext(out, ".jpg") || has_ext(out, ".jpeg");
    if (!linear && !*toned) {
        cli_error(CMD, "-o %s: unsupported extension (use .exr, .hdr, .tif, .png or .jpg)", out);
        return SOAK_EXIT_USAGE;
    }
    if (pst != SOAK_OK) {
        cli_error(CMD, "-o %s: %s", out, err);
        return SOAK_EXIT_FAIL;
    }
    return -1;
}

/* The output is none of the files the scene reads. */
static soak_status guard_inputs(const render_args *a, const soak_scene *scene, char *err, size_t errlen)
{
    soak_io_guard guard;
    soak_io_guard_init(&guard);
    soak_status st = soak_io_guard_output(&guard, "-o", a->out_path);
    if (st == SOAK_OK) st = soak_io_guard_input(&guard, "scene file", a->scene_path);
    for (int i = 0; i < scene->n_inputs && st == SOAK_OK; ++i)
        st = soak_io_guard_input(&guard, "file of the scene", scene->inputs[i]);
    if (st == SOAK_OK) st = soak_io_guard_check(&guard, err, errlen);
    soak_io_guard_free(&guard);
    return st;
}

/* Loads the scene, checks its files against -o, applies --auto-model and
 * the memory limit. Returns -1 with the scene loaded, else the exit code
 * with nothing to free. */
static int load_scene(const render_args *a, soak_scene *scene)
{
    char err[4096] = "";
    if (soak_scene_load(a->scene_path, scene, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "%s", err);
        return SOAK_EXIT_FAIL;
    }
    int rc = -1;
    soak_status st = guard_inputs(a, scene, err, sizeof err);
    int W = a->width > 0 ? (int)a->width : scene->width, H = a->height > 0 ? (int)a->height : scene->height;
    int bytes = RENDER_BYTES_PER_PIXEL + (a->denoise ? DENOISE_BYTES_PER_PIXEL : 0);
    double need_mib = (double)W * H * bytes / 1048576.0;
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", st == SOAK_ERR_ARG ? err : soak_status_str(st));
        rc = st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
    } else if (a->auto_tol > 0 && auto_model(scene, a->auto_tol) != SOAK_OK) {
        rc = SOAK_EXIT_FAIL;
    } else if (need_mib > RENDER_MAX_MIB) {
        cli_error(CMD, "a %dx%d render needs %.0f MiB (%d bytes per pixel); the limit is %d MiB", W, H, need_mib,
                  bytes, RENDER_MAX_MIB);
        rc = SOAK_EXIT_USAGE;
    }
    if (rc >= 0) soak_scene_free(scene);
    return rc;
}

/* --denoise: the camera's features, then the filter, in place. */
static soak_status denoise(const render_args *a, const soak_scene *scene, soak_image *img, const soak_image *var,
                           long *fireflies)
{
    char err[4096] = "";
    soak_denoise_features f;
    soak_denoise_options o;
    soak_denoise_stats ds = {0};
    soak_denoise_options_default(&o);
    soak_status st = soak_render_features(scene, img->width, img->height, DENOISE_LENS_SAMPLES, &f, err, sizeof err);
    if (st == SOAK_OK) st = soak_denoise(img, var, &f, &o, &ds, err, sizeof err);
    soak_denoise_features_free(&f);
    if (st != SOAK_OK) cli_error(CMD, "%s: --denoise: %s", a->scene_path, err[0] ? err : soak_status_str(st));
    *fireflies = ds.fireflies;
    return st;
}

/* Traces the image with Ctrl-C stopping it early (and denoises it with
 * --denoise); *exposure is the camera's, for tone mapping. Frees the scene. */
static soak_status trace(const render_args *a, soak_scene *scene, soak_image *img, soak_render_stats *stats,
                         double *exposure, long *fireflies)
{
    struct sigaction sa, old;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old);
    soak_render_options opt;
    soak_render_options_default(&opt);
    opt.width = (int)a->width;
    opt.height = (int)a->height;
    opt.spp = (int)a->spp;
    opt.threads = (int)a->threads;
    opt.seed = (uint64_t)a->seed;
    opt.time_limit = a->time_limit;
    opt.target_error = a->target_error;
    opt.max_depth = (int)a->max_depth;
    opt.cancel = &interrupted;
    soak_image var = {0};
    if (a->denoise) opt.variance = &var;
    char label[96], err[4096] = "";
    snprintf(label, sizeof label, "render %dx%d, %d spp", a->width > 0 ? (int)a->width : scene->width,
             a->height > 0 ? (int)a->height : scene->height, a->spp > 0 ? (int)a->spp : scene->spp);
    cli_progress prog;
    cli_progress_start(&prog, label, 1.0);
    opt.progress = progress_cb;
    opt.progress_ctx = &prog;
    soak_status st = soak_render(scene, &opt, img, stats, err, sizeof err);
    cli_progress_finish(&prog);
    sigaction(SIGINT, &old, NULL);
    *exposure = scene->camera.exposure;
    if (st != SOAK_OK) cli_error(CMD, "%s: render failed: %s", a->scene_path, err[0] ? err : soak_status_str(st));
    if (st == SOAK_OK && a->denoise) st = denoise(a, scene, img, &var, fireflies);
    soak_image_free(&var);
    soak_scene_free(scene);
    return st;
}

static soak_status write_image(const render_args *a, soak_image *img, int toned, double exposure)
{
    char err[4096] = "";
    soak_image_write_opts wo = {SOAK_TONE_LINEAR, SOAK_PIXEL_FLOAT};
    if (toned) {
        soak_render_expose(img, exposure);
        wo.tone = SOAK_TONE_SRGB;
        wo.pixel_type = SOAK_PIXEL_AUTO;
    }
    soak_status st = soak_image_write(a->out_path, img, &wo, err, sizeof err);
    if (st != SOAK_OK) cli_error(CMD, "-o %s: %s", a->out_path, err);
    return st;
}

static void print_stats(const render_args *a, const soak_render_stats *stats, long fireflies)
{
    double secs = stats->seconds > 0 ? stats->seconds : 1e-9;
    printf("wrote %s\n", a->out_path);
    printf("samples per pixel: %d..%d%s\n", stats->min_spp, stats->max_spp,
           stats->stopped_early ? " (stopped early)" : "");
    printf("paths: %lld (%.0f paths/s)\n", stats->paths, stats->paths / secs);
    printf("rays: %lld (%.0f rays/s)\n", stats->rays, stats->rays / secs);
    printf("capped paths: %lld, leaked medium paths: %lld, NaN paths: %lld, geometry errors: %lld\n", stats->capped,
           stats->leaked, stats->nan_paths, stats->geometry_errors);
    printf("time: %.2f s with %ld threads\n", stats->seconds, a->threads);
    printf("cpu: %.3f s (user + system, all threads)\n", stats->cpu_seconds);
    if (a->denoise) printf("denoised (a picture, not numbers): %ld fireflies removed\n", fireflies);
}

int soak_cmd_render(int argc, char **argv)
{
    render_args a;
    int toned = 0, rc = parse_args(argc, argv, &a);
    if (rc < 0) rc = check_output(&a, &toned);
    soak_scene scene;
    if (rc < 0) rc = load_scene(&a, &scene);
    if (rc >= 0) return rc;
    soak_image img = {0};
    soak_render_stats stats;
    double exposure = 0;
    long fireflies = 0;
    rc = SOAK_EXIT_FAIL;
    if (trace(&a, &scene, &img, &stats, &exposure, &fireflies) == SOAK_OK && write_image(&a, &img, toned, exposure) == SOAK_OK)
        rc = SOAK_EXIT_OK;
    soak_image_free(&img);
    if (rc != SOAK_EXIT_OK) return rc;
    if (!a.quiet) print_stats(&a, &stats, fireflies);
    if (interrupted) {
        fprintf(stderr, "soak render: interrupted; wrote the %d..%d samples per pixel done so far to %s\n",
                stats.min_spp, stats.max_spp, a.out_path);
        return 130;
    }
    return SOAK_EXIT_OK;
}
