/* soak render: the reference path tracer on a JSON scene (scenes/README.md). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "cli.h"
#include "soak/advise.h"
#include "soak/image.h"
#include "soak/io_guard.h"
#include "soak/render.h"
#include "soak/scene.h"

static volatile sig_atomic_t interrupted = 0;

/* Memory of a render per pixel: the sums (3 doubles) and sample count (an
 * int) of soak_render, its float RGB image and the encoder's copy of it. */
#define RENDER_BYTES_PER_PIXEL (3 * 8 + 4 + 3 * 4 + 3 * 4)
#define RENDER_MAX_MIB 4096

static void on_sigint(int sig)
{
    (void)sig;
    interrupted = 1;
}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak render SCENE.json -o OUT.exr|OUT.png [options]\n\n"
            "Renders a JSON scene (format: scenes/README.md) with the reference path tracer:\n"
            "next-event estimation with MIS, the wet film of Jensen et al. 1999 Eq. 1-4 and a\n"
            "subsurface random walk. EXR/HDR/TIFF outputs hold linear float radiance; PNG/JPEG are\n"
            "tone mapped: multiplied by 2^exposure (camera.exposure), then the sRGB curve, clamped\n"
            "to [0,1]. Ctrl-C stops early, writes the samples taken so far and exits 130.\n\n"
            "options:\n"
            "  -o, --output FILE   output image (required; never one of the scene's inputs)\n"
            "  --spp N             samples per pixel (default: the scene's render.spp)\n"
            "  --threads N         worker threads (default: the number of CPUs)\n"
            "  --seed S            random seed (default 1); same seed + spp -> identical pixels\n"
            "  --time T            stop after T seconds and keep what is done\n"
            "  --width W --height H  image size (default: the scene's render.width/height); a render\n"
            "                      takes 52 bytes per pixel and is refused above 4096 MiB (about 9000^2)\n"
            "  --max-depth N       path length cap (default: the scene's render.max_depth)\n"
            "  --auto-model T      render each material through the cheapest model within a\n"
            "                      relative error T of its full description (soak advise;\n"
            "                      the choices are printed on stderr)\n"
            "  -q, --quiet         no statistics on stdout\n\n"
            "example:\n"
            "  soak render scenes/default_wet_dry.json -o wet_dry.png --spp 32 --threads 2\n");
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
static soak_status auto_model(const char *scene_path, soak_scene *scene, double tol)
{
    soak_advice *adv = NULL;
    int n = 0;
    char err[4096] = "";
    soak_status st = soak_advise_scene(scene, tol, NULL, &adv, &n, err, sizeof err);
    if (st == SOAK_OK) st = soak_advise_apply(scene, adv, n, err, sizeof err);
    if (st != SOAK_OK) cli_error("render", "--auto-model: %s", err[0] ? err : soak_status_str(st));
    else cli_advise_print(stderr, adv, n, tol);
    free(adv);
    (void)scene_path;
    return st;
}

int soak_cmd_render(int argc, char **argv)
{
    const char *cmd = "render", *scene_path = NULL, *out_path = NULL;
    long spp = 0, threads = sysconf(_SC_NPROCESSORS_ONLN), width = 0, height = 0, max_depth = 0, seed = 1;
    double time_limit = 0, auto_tol = 0;
    int quiet = 0;
    if (threads < 1) threads = 1;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v;
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            usage(stdout);
            return SOAK_EXIT_OK;
        } else if (strcmp(a, "-o") == 0 || cli_is(a, "--output")) {
            if (!(out_path = cli_value(cmd, argc, argv, &i))) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--spp")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_int(cmd, "--spp", v, 1, 10000000, &spp))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--threads")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_int(cmd, "--threads", v, 1, 256, &threads))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--seed")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_int(cmd, "--seed", v, 0, 2147483647L, &seed))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--time")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_double(cmd, "--time", v, 0.001, 1e9, &time_limit))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--width")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_size(cmd, "--width", v, CLI_MAX_IMAGE_SIDE, &width))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--height")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_size(cmd, "--height", v, CLI_MAX_IMAGE_SIDE, &height))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--max-depth")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_int(cmd, "--max-depth", v, 1, 100000, &max_depth))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--auto-model")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_double(cmd, "--auto-model", v, 1e-9, 10, &auto_tol))
                return SOAK_EXIT_USAGE;
        } else if (strcmp(a, "-q") == 0 || strcmp(a, "--quiet") == 0) {
            quiet = 1;
        } else if (a[0] == '-' && a[1] != '\0') {
            cli_error(cmd, "unknown option '%s' (see soak render --help)", a);
            return SOAK_EXIT_USAGE;
        } else if (!scene_path) {
            scene_path = a;
        } else {
            cli_error(cmd, "unexpected argument '%s': only one scene file", a);
            return SOAK_EXIT_USAGE;
        }
    }
    if (!scene_path) {
        cli_error(cmd, "SCENE.json: missing scene file (see soak render --help)");
        return SOAK_EXIT_USAGE;
    }
    if (!out_path) {
        cli_error(cmd, "-o: missing output image (.exr or .png)");
        return SOAK_EXIT_USAGE;
    }
    char err[4096];
    if (soak_io_check_output("-o", out_path, &scene_path, 1, err, sizeof err) != SOAK_OK) {
        cli_error(cmd, "%s (the scene file)", err);
        return SOAK_EXIT_USAGE;
    }
    soak_status pst = soak_path_check_writable(out_path, err, sizeof err);
    if (pst == SOAK_ERR_ARG) {
        cli_error(cmd, "-o: %s", err);
        return SOAK_EXIT_USAGE;
    }
    int linear = has_ext(out_path, ".exr") || has_ext(out_path, ".hdr") || has_ext(out_path, ".tif") ||
                 has_ext(out_path, ".tiff");
    int toned = has_ext(out_path, ".png") || has_ext(out_path, ".jpg") || has_ext(out_path, ".jpeg");
    if (!linear && !toned) {
        cli_error(cmd, "-o %s: unsupported extension (use .exr, .hdr, .tif, .png or .jpg)", out_path);
        return SOAK_EXIT_USAGE;
    }
    if (pst != SOAK_OK) {
        cli_error(cmd, "-o %s: %s", out_path, err);
        return SOAK_EXIT_FAIL;
    }
    soak_scene scene;
    soak_status st = soak_scene_load(scene_path, &scene, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(cmd, "%s", err);
        return SOAK_EXIT_FAIL;
    }
    soak_io_guard guard;
    soak_io_guard_init(&guard);
    st = soak_io_guard_output(&guard, "-o", out_path);
    if (st == SOAK_OK) st = soak_io_guard_input(&guard, "scene file", scene_path);
    for (int i = 0; i < scene.n_inputs && st == SOAK_OK; ++i) st = soak_io_guard_input(&guard, "file of the scene", scene.inputs[i]);
    if (st == SOAK_OK) st = soak_io_guard_check(&guard, err, sizeof err);
    soak_io_guard_free(&guard);
    if (st != SOAK_OK) {
        cli_error(cmd, "%s", st == SOAK_ERR_ARG ? err : soak_status_str(st));
        soak_scene_free(&scene);
        return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
    }
    if (auto_tol > 0 && auto_model(scene_path, &scene, auto_tol) != SOAK_OK) {
        soak_scene_free(&scene);
        return SOAK_EXIT_FAIL;
    }

    int W = width > 0 ? (int)width : scene.width, H = height > 0 ? (int)height : scene.height;
    double need_mib = (double)W * H * RENDER_BYTES_PER_PIXEL / 1048576.0;
    if (need_mib > RENDER_MAX_MIB) {
        cli_error(cmd, "a %dx%d render needs %.0f MiB (%d bytes per pixel); the limit is %d MiB", W, H, need_mib,
                  RENDER_BYTES_PER_PIXEL, RENDER_MAX_MIB);
        soak_scene_free(&scene);
        return SOAK_EXIT_USAGE;
    }
    struct sigaction sa, old;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old);

    soak_render_options opt;
    soak_render_options_default(&opt);
    opt.width = (int)width;
    opt.height = (int)height;
    opt.spp = (int)spp;
    opt.threads = (int)threads;
    opt.seed = (uint64_t)seed;
    opt.time_limit = time_limit;
    opt.max_depth = (int)max_depth;
    opt.cancel = &interrupted;
    char label[96];
    snprintf(label, sizeof label, "render %dx%d, %d spp", width > 0 ? (int)width : scene.width,
             height > 0 ? (int)height : scene.height, spp > 0 ? (int)spp : scene.spp);
    cli_progress prog;
    cli_progress_start(&prog, label, 1.0);
    opt.progress = progress_cb;
    opt.progress_ctx = &prog;
    soak_image img = {0};
    soak_render_stats stats;
    st = soak_render(&scene, &opt, &img, &stats, err, sizeof err);
    cli_progress_finish(&prog);
    sigaction(SIGINT, &old, NULL);
    double exposure = scene.camera.exposure;
    soak_scene_free(&scene);
    if (st != SOAK_OK) {
        cli_error(cmd, "%s: render failed: %s", scene_path, err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    soak_image_write_opts wo = {SOAK_TONE_LINEAR, SOAK_PIXEL_FLOAT};
    if (toned) {
        soak_render_expose(&img, exposure);
        wo.tone = SOAK_TONE_SRGB;
        wo.pixel_type = SOAK_PIXEL_AUTO;
    }
    st = soak_image_write(out_path, &img, &wo, err, sizeof err);
    soak_image_free(&img);
    if (st != SOAK_OK) {
        cli_error(cmd, "-o %s: %s", out_path, err);
        return SOAK_EXIT_FAIL;
    }
    if (!quiet) {
        double secs = stats.seconds > 0 ? stats.seconds : 1e-9;
        printf("wrote %s\n", out_path);
        printf("samples per pixel: %d..%d%s\n", stats.min_spp, stats.max_spp, stats.stopped_early ? " (stopped early)" : "");
        printf("paths: %lld (%.0f paths/s)\n", stats.paths, stats.paths / secs);
        printf("rays: %lld (%.0f rays/s)\n", stats.rays, stats.rays / secs);
        printf("capped paths: %lld, leaked medium paths: %lld, NaN paths: %lld, geometry errors: %lld\n", stats.capped,
               stats.leaked, stats.nan_paths, stats.geometry_errors);
        printf("time: %.2f s with %ld threads\n", stats.seconds, threads);
    }
    if (interrupted) {
        fprintf(stderr, "soak render: interrupted; wrote the %d..%d samples per pixel done so far to %s\n", stats.min_spp,
                stats.max_spp, out_path);
        return 130;
    }
    return SOAK_EXIT_OK;
}
