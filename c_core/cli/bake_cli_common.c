/* Option handling, output checks, frame loop and progress shared by the 2D
 * `soak bake` kinds. */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"
#include "soak/staged.h"

#define MAX_FRAMES 100000
#define MAX_FRAME_NUMBER 9999999
#define BAKE_MAX_TIME 1e9       /* |--time| */
#define BAKE_MAX_FRAME_TIME 1e6

void bake_opts_init(bake_opts *o, const char *cmd, double time, double frame_time)
{
    memset(o, 0, sizeof *o);
    o->cmd = cmd;
    o->width = o->height = 1024;
    o->time = time;
    o->frame_time = frame_time;
}

static int read_frames(const char *cmd, const cli_opt *opt, const char *text, void *dst)
{
    (void)opt;
    bake_opts *o = dst;
    char *end = NULL;
    errno = 0;
    long a = strtol(text, &end, 10), b = a;
    if (end != text && *end == '-') {
        const char *second = end + 1;
        b = strtol(second, &end, 10);
        if (end == second) end = (char *)text;
    }
    if (end == text || *end != '\0' || errno == ERANGE || a < 0 || b < a || b > MAX_FRAME_NUMBER ||
        b - a >= MAX_FRAMES) {
        cli_error(cmd, "--frames: expected A-B with 0 <= A <= B <= %d and at most %d frames, got '%s'",
                  MAX_FRAME_NUMBER, MAX_FRAMES, text);
        return 0;
    }
    o->first = a;
    o->last = b;
    o->have_frames = 1;
    return 1;
}

#define F(field) CLI_FIELD(bake_opts, field)
const cli_opt bake_image_opts[] = {
    {"--output", "-o", CLI_OPT_STRING, F(output), .meta = "PATH",
     .help = "output map: .exr (half), .png/.tif (16-bit linear), .tx"},
    {"--width", NULL, CLI_OPT_SIZE, .ihi = SOAK_BAKE_MAX_SIZE, F(width), CLI_SEEN(bake_opts, have_width),
     .meta = "N", .help = "image width, %R (default 1024)"},
    {"--height", NULL, CLI_OPT_SIZE, .ihi = SOAK_BAKE_MAX_SIZE, F(height), CLI_SEEN(bake_opts, have_height),
     .meta = "N", .help = "image height, %R (default 1024)"},
    {"--seed", NULL, CLI_OPT_INT, .ilo = 0, .ihi = INT64_MAX, F(seed), .meta = "N",
     .help = "seed (default 0); same seed, same map on any thread count"},
    {"--threads", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_BAKE_MAX_THREADS, F(threads), .meta = "N",
     .help = "worker threads, %R (default: every core)"},
};
const size_t bake_image_opts_n = sizeof bake_image_opts / sizeof bake_image_opts[0];

const cli_opt bake_sequence_opts[] = {
    {"--float", NULL, CLI_OPT_FLAG, .flag = 1, F(float_exr), .help = "32-bit EXR instead of half"},
    {"--frames", NULL, CLI_OPT_CUSTOM, .parse = read_frames, .meta = "A-B",
     .help = "image sequence; -o must hold a pattern such as wet.%04d.exr"},
    {"--time", NULL, CLI_OPT_DOUBLE, .lo = -BAKE_MAX_TIME, .hi = BAKE_MAX_TIME, F(time), .meta = "T",
     .help = "time of frame F (default above)"},
    {"--frame-time", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = BAKE_MAX_FRAME_TIME, F(frame_time), .meta = "DT",
     .help = "time between frames (default above): frame f is at T + (f-F) DT"},
    {"--frame-origin", NULL, CLI_OPT_INT, .ilo = 0, .ihi = MAX_FRAME_NUMBER, F(origin),
     CLI_SEEN(bake_opts, have_origin), .meta = "F",
     .help = "frame baked at time T (default A); give the sequence's first\n"
             "frame to bake it in chunks (--frames 11-20 ...) that equal one run"},
};
const size_t bake_sequence_opts_n = sizeof bake_sequence_opts / sizeof bake_sequence_opts[0];
#undef F

size_t bake_table_help(const cli_opt *src, size_t n, cli_opt *dst, const char *name, const char *help)
{
    n = n < BAKE_SHARED_OPTS_MAX ? n : BAKE_SHARED_OPTS_MAX;
    for (size_t k = 0; k < n; ++k) {
        dst[k] = src[k];
        if (strcmp(src[k].name, name) == 0) dst[k].help = help;
    }
    return n;
}

#define N(field) CLI_FIELD(soak_turbulence_params, field)
const cli_opt bake_noise_opts[] = {
    {"--turbulence", NULL, CLI_OPT_FLAG, .flag = SOAK_NOISE_TURBULENCE, N(sum),
     .help = "sum of |noise| (turbulence) instead of noise (fBm)"},
    {"--octaves", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_NOISE_MAX_OCTAVES, N(octaves), .meta = "N",
     .help = "%R (default 6)"},
    {"--frequency", NULL, CLI_OPT_DOUBLE, .lo = BAKE_MIN_POSITIVE, .hi = SOAK_NOISE_MAX_FREQUENCY, N(frequency),
     .meta = "F", .help = "noise cells across the width (a volume: across SX) at octave 0\n(default 4)"},
    {"--lacunarity", NULL, CLI_OPT_DOUBLE, .lo = 1, .hi = SOAK_NOISE_MAX_LACUNARITY, N(lacunarity), .meta = "L",
     .help = "frequency ratio between octaves, %R (default 2)"},
    {"--gain", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, N(gain), .meta = "G",
     .help = "amplitude ratio between octaves, %R (default 0.5)"},
    {"--threshold", NULL, CLI_OPT_DOUBLE, .lo = -SOAK_NOISE_MAX_THRESHOLD, .hi = SOAK_NOISE_MAX_THRESHOLD, N(threshold),
     CLI_SEEN(soak_turbulence_params, thresholded), .meta = "T",
     .help = "output smoothstep(T - S, T + S, value) instead of the value"},
    {"--softness", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_NOISE_MAX_SOFTNESS, N(softness), .meta = "S",
     .help = "half width of that transition, 0 = hard edge (default 0.1)"},
};
const size_t bake_noise_opts_n = sizeof bake_noise_opts / sizeof bake_noise_opts[0];
#undef N

/* Path of frame f for a pattern, or the path itself when it has no
 * conversion. */
static int expand(const bake_opts *o, const char *path, long frame, char *out, size_t outlen)
{
    int kind = soak_bake_pattern_kind(path);
    if (strlen(path) + 16 >= outlen) {
        cli_error(o->cmd, "'%.64s...': a path of %zu bytes is longer than the %zu a path may have (with 16 for the "
                          "frame number or the temporary's suffix)",
                  path, strlen(path), outlen - 17);
        return 0;
    }
    if (kind == 0 || frame < 0) {
        snprintf(out, outlen, "%s", path);
        return 1;
    }
    if (kind < 0 || soak_bake_frame_path(path, (int)frame, out, outlen) != SOAK_OK) {
        cli_error(o->cmd, "'%s': bad frame pattern (use one %%d, %%4d or %%04d)", path);
        return 0;
    }
    return 1;
}

int bake_opts_check(const bake_opts *o, const char *const *inputs, int n_inputs)
{
    if (!o->output) {
        cli_error(o->cmd, "-o/--output is required (see --help)");
        return SOAK_EXIT_USAGE;
    }
    int kind = soak_bake_pattern_kind(o->output);
    if (kind < 0) {
        cli_error(o->cmd, "-o '%s': bad frame pattern (use one %%d, %%4d or %%04d; %%%% for a literal %%)", o->output);
        return SOAK_EXIT_USAGE;
    }
    if (o->have_frames && kind != 1) {
        cli_error(o->cmd, "--frames needs a frame pattern in -o, e.g. wet.%%04d.exr (got '%s')", o->output);
        return SOAK_EXIT_USAGE;
    }
    if (!o->have_frames && kind == 1) {
        cli_error(o->cmd, "-o '%s' is a frame pattern: give --frames A-B", o->output);
        return SOAK_EXIT_USAGE;
    }
    if (o->have_origin && !o->have_frames) {
        cli_error(o->cmd, "--frame-origin %ld needs an image sequence: give --frames A-B", o->origin);
        return SOAK_EXIT_USAGE;
    }
    long first = o->have_frames ? o->first : -1, last = o->have_frames ? o->last : -1;
    for (long f = first; f <= last; ++f) {
        char out[4096], err[4352];
        const char *expanded[BAKE_MAX_INPUTS];
        char buf[BAKE_MAX_INPUTS][4096];
        int n = n_inputs < BAKE_MAX_INPUTS ? n_inputs : BAKE_MAX_INPUTS;
        if (!expand(o, o->output, f, out, sizeof out)) return SOAK_EXIT_USAGE;
        for (int k = 0; k < n; ++k) {
            if (!expand(o, inputs[k], f, buf[k], sizeof buf[k])) return SOAK_EXIT_USAGE;
            expanded[k] = buf[k];
        }
        soak_status st = soak_bake_check_output(out, expanded, n, err, sizeof err);
        if (st != SOAK_OK) {
            cli_error(o->cmd, "%s", err);
            return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
        }
    }
    if (o->plan_later) return 0;
    bake_output outs[1] = {{o->output_option ? o->output_option : "-o", o->output}}, ins[BAKE_MAX_INPUTS];
    int n = n_inputs < BAKE_MAX_INPUTS ? n_inputs : BAKE_MAX_INPUTS;
    for (int k = 0; k < n; ++k) ins[k] = (bake_output){"input", inputs[k]};
    return bake_plan_check(o, outs, 1, ins, n);
}

int bake_fail(const char *cmd, soak_status st, const char *err)
{
    if (err && *err) cli_error(cmd, "%s", err);
    else cli_error(cmd, "%s", soak_status_str(st));
    return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
}

double bake_frame_time(const bake_opts *o, long f)
{
    if (!o->have_frames || f < 0) return o->time;
    long origin = o->have_origin ? o->origin : o->first;
    /* Two rounded steps, one per statement, so no compiler fuses them: the
     * farm job types rely on this exact double for every chunk. */
    double offset = (double)(f - origin) * o->frame_time;
    return o->time + offset;
}

int bake_check_times(const bake_opts *o, double lo, double hi)
{
    long ends[2] = {o->have_frames ? o->first : -1, o->have_frames ? o->last : -1};
    for (int k = 0; k < 2; ++k) {
        double t = bake_frame_time(o, ends[k]);
        if (t >= lo && t <= hi) continue;
        char label[32];
        cli_error(o->cmd, "%s is at time %g s, outside %g..%g s (set by %s); nothing was written",
                  bake_frame_label(ends[k], label, sizeof label), t, lo, hi,
                  o->have_frames ? "--frames, --time, --frame-time or --fps, --frame-origin" : "--time");
        return SOAK_EXIT_USAGE;
    }
    return 0;
}

typedef struct progress_state {
    cli_progress bar;
    double base; /* frames already done */
} progress_state;

static void on_progress(void *user, double fraction)
{
    progress_state *p = user;
    cli_progress_update(&p->bar, p->base + fraction);
}

int bake_run_staged(const bake_opts *o, bake_frame_staged_fn fn, void *ctx)
{
    long first = o->have_frames ? o->first : -1, last = o->have_frames ? o->last : -1;
    progress_state prog;
    cli_progress_start(&prog.bar, o->cmd, (double)(last - first + 1));
    soak_bake_exec exec = {(int)o->threads, on_progress, &prog};
    for (long f = first; f <= last; ++f) {
        char path[4096], err[4352] = "";
        if (!expand(o, o->output, f, path, sizeof path)) return SOAK_EXIT_USAGE;
        prog.base = (double)(f - first);
        double time = bake_frame_time(o, f);
        soak_image img = {0, 0, 0, NULL};
        soak_staged stage;
        soak_staged_init(&stage);
        soak_status st = fn(ctx, (int)f, time, &exec, &img, &stage, err, sizeof err);
        if (st == SOAK_OK) st = soak_bake_stage(&stage, path, &img, o->float_exr, err, sizeof err);
        if (st == SOAK_OK) st = soak_staged_commit(&stage, err, sizeof err);
        else soak_staged_abort(&stage);
        soak_image_free(&img);
        if (st != SOAK_OK) {
            if (prog.bar.enabled) fputc('\n', stderr);
            return bake_fail(o->cmd, st, err);
        }
    }
    cli_progress_finish(&prog.bar);
    return SOAK_EXIT_OK;
}

typedef struct plain_frame {
    bake_frame_fn fn;
    void *ctx;
} plain_frame;

static soak_status plain(void *ctx, int frame, double time, const soak_bake_exec *exec, soak_image *out,
                         struct soak_staged *extra, char *err, size_t errlen)
{
    (void)extra;
    const plain_frame *p = ctx;
    return p->fn(p->ctx, frame, time, exec, out, err, errlen);
}

int bake_run(const bake_opts *o, bake_frame_fn fn, void *ctx)
{
    plain_frame p = {fn, ctx};
    return bake_run_staged(o, plain, &p);
}
