/* Option handling, output checks, frame loop and progress shared by the 2D
 * `soak bake` kinds. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"

#define MAX_FRAMES 100000
#define MAX_FRAME_NUMBER 9999999

void bake_opts_init(bake_opts *o, const char *cmd, double time, double frame_time)
{
    memset(o, 0, sizeof *o);
    o->cmd = cmd;
    o->width = o->height = 1024;
    o->time = time;
    o->frame_time = frame_time;
}

static int parse_frames(bake_opts *o, const char *text)
{
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
        cli_error(o->cmd, "--frames: expected A-B with 0 <= A <= B <= %d and at most %d frames, got '%s'",
                  MAX_FRAME_NUMBER, MAX_FRAMES, text);
        return -1;
    }
    o->first = a;
    o->last = b;
    o->have_frames = 1;
    return 1;
}

int bake_opts_parse(bake_opts *o, int argc, char **argv, int *i)
{
    const char *a = argv[*i], *v;
    long n;
    if (cli_is(a, "-o") || cli_is(a, "--output")) {
        if (!(v = cli_value(o->cmd, argc, argv, i))) return -1;
        o->output = v;
    } else if (cli_is(a, "--width") || cli_is(a, "--height")) {
        int w = cli_is(a, "--width");
        if (!(v = cli_value(o->cmd, argc, argv, i)) ||
            !cli_parse_size(o->cmd, w ? "--width" : "--height", v, SOAK_BAKE_MAX_SIZE, &n))
            return -1;
        if (w) o->width = n, o->have_width = 1;
        else o->height = n, o->have_height = 1;
    } else if (cli_is(a, "--seed")) {
        if (!(v = cli_value(o->cmd, argc, argv, i)) || !cli_parse_int(o->cmd, "--seed", v, 0, 0x7fffffffffffffffL, &n))
            return -1;
        o->seed = (uint64_t)n;
    } else if (cli_is(a, "--threads")) {
        if (!(v = cli_value(o->cmd, argc, argv, i)) ||
            !cli_parse_int(o->cmd, "--threads", v, 1, SOAK_BAKE_MAX_THREADS, &o->threads))
            return -1;
    } else if (cli_is(a, "--float")) {
        o->float_exr = 1;
    } else if (cli_is(a, "--frames")) {
        if (!(v = cli_value(o->cmd, argc, argv, i))) return -1;
        return parse_frames(o, v);
    } else if (cli_is(a, "--time")) {
        if (!(v = cli_value(o->cmd, argc, argv, i)) || !cli_parse_double(o->cmd, "--time", v, -1e9, 1e9, &o->time))
            return -1;
        o->have_time = 1;
    } else if (cli_is(a, "--frame-time")) {
        if (!(v = cli_value(o->cmd, argc, argv, i)) ||
            !cli_parse_double(o->cmd, "--frame-time", v, 0, 1e6, &o->frame_time))
            return -1;
    } else if (cli_is(a, "--frame-origin")) {
        if (!(v = cli_value(o->cmd, argc, argv, i)) ||
            !cli_parse_int(o->cmd, "--frame-origin", v, 0, MAX_FRAME_NUMBER, &o->origin))
            return -1;
        o->have_origin = 1;
    } else {
        return 0;
    }
    return 1;
}

/* Path of frame f for a pattern, or the path itself when it has no
 * conversion. */
static int expand(const bake_opts *o, const char *path, long frame, char *out, size_t outlen)
{
    int kind = soak_bake_pattern_kind(path);
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
    return 0;
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

typedef struct progress_state {
    cli_progress bar;
    double base; /* frames already done */
} progress_state;

static void on_progress(void *user, double fraction)
{
    progress_state *p = user;
    cli_progress_update(&p->bar, p->base + fraction);
}

int bake_run(const bake_opts *o, bake_frame_fn fn, void *ctx)
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
        soak_status st = fn(ctx, (int)f, time, &exec, &img, err, sizeof err);
        if (st == SOAK_OK) st = soak_bake_write(path, &img, o->float_exr, err, sizeof err);
        soak_image_free(&img);
        if (st != SOAK_OK) {
            if (prog.bar.enabled) fputc('\n', stderr);
            return bake_fail(o->cmd, st, err);
        }
    }
    cli_progress_finish(&prog.bar);
    return SOAK_EXIT_OK;
}
