/* soak bake drying: a wet region drying from its borders ([Hnat06] sec. 3.3)
 * or by evaporation and capillary diffusion. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"

#define CMD "bake drying"

typedef struct drying_job {
    soak_drying_params p;
    soak_image mask; /* pixels NULL without a mask */
    int width, height;
    int start_map;
    const char *mask_path;
} drying_job;

static const cli_choice modes[] = {{"schedule", SOAK_DRYING_SCHEDULE, 0}, {"diffusion", SOAK_DRYING_DIFFUSION, 0},
                                   {NULL, 0, 0}};

#define F(field) CLI_FIELD(drying_job, field)
static const cli_opt drying_opts[] = {
    {"--mode", NULL, CLI_OPT_CHOICE, .choices = modes, F(p.mode), .meta = "MODE",
     .help = "schedule (default) or diffusion"},
    {"--threshold", NULL, CLI_OPT_DOUBLE, .lo = -SOAK_DRYING_MAX_THRESHOLD, .hi = SOAK_DRYING_MAX_THRESHOLD,
     F(p.threshold), .meta = "V", .help = "mask level above which a texel is wet (default 0.5)"},
    {"--t-fill", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(p.t_fill), .meta = "F",
     .help = "pore emptying time, %R, 0 = sharp step (default 0.2)"},
    {"--noise", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(p.noise_amount), .meta = "A",
     .help = "fraction of fBm in the start time, %R (default 0)"},
    {"--noise-frequency", NULL, CLI_OPT_DOUBLE, .lo = BAKE_MIN_POSITIVE, .hi = SOAK_NOISE_MAX_FREQUENCY,
     F(p.noise_frequency), .meta = "F", .help = "noise cells across the width (default 8)"},
    {"--noise-octaves", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_NOISE_MAX_OCTAVES, F(p.noise_octaves), .meta = "N",
     .help = "%R (default 4)"},
    {"--start-map", NULL, CLI_OPT_FLAG, .flag = 1, F(start_map),
     .help = "write the start-time texture 1 - t0 instead (wet texels; seed\n"
             "002's wet-texture convention, value 1 = first)"},
    {"--drying-time", NULL, CLI_OPT_DOUBLE, .lo = 1e-9, .hi = SOAK_DRYING_MAX_TIME, F(p.drying_time), .meta = "T",
     .help = "diffusion: time for a unit film to evaporate (default 1)"},
    {"--diffusion-length", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_DRYING_MAX_LENGTH, F(p.diffusion_length),
     .meta = "L", .help = "diffusion: spreading length over the drying time, pixels (default 8)"},
    {"--steps", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_DRYING_MAX_STEPS, F(p.steps), .meta = "N",
     .help = "diffusion: implicit steps per frame, %R (default 32)"},
};
#undef F

#define DRYING_TABLES(o, j) {BAKE_IMAGE_TABLE(o), CLI_TABLE(drying_opts, (j)), BAKE_SEQUENCE_TABLE(o)}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake drying [MASK] [options] -o OUT\n\n"
            "Wetness of a drying region. MASK is any image OpenImageIO reads (luma of RGB); texels\n"
            "above --threshold start wet. Without MASK the whole --width x --height surface is wet\n"
            "and only --noise decides the drying order; with MASK, --width/--height must match it.\n\n"
            "  --mode schedule   (default) Hnat et al. 2006's pore schedule run as emptying: texel drying\n"
            "                    starts at t0 = (1 - t_fill) * d/d_max (d = exact Euclidean distance\n"
            "                    to the nearest dry texel, so borders dry first), optionally mixed\n"
            "                    with fBm noise; wetness = 1 - fill_fraction(t, t0, t_fill); the whole\n"
            "                    region is dry at t = 1.\n"
            "  --mode diffusion  water depth with evaporation at the surface and lateral capillary\n"
            "                    diffusion, solved implicitly (stable for any step): puddles spread a\n"
            "                    little and shrink from their edges; a unit film dries in --drying-time.\n"
            "Sequences: --time 0.5 and --frame-time 0.01 by default.\n\n"
            "options:\n");
    const cli_opt_table tables[] = DRYING_TABLES(NULL, NULL);
    cli_opts_help(out, tables, sizeof tables / sizeof tables[0]);
    fprintf(out, "\nexample:\n"
                 "  soak bake drying splash_mask.png --t-fill 0.2 --noise 0.3 --frames 0-100 -o dry.%%04d.exr\n");
}

static int mask_arg(void *ctx, const char *arg)
{
    drying_job *j = ctx;
    if (j->mask_path) {
        cli_error(CMD, "one mask image only (got '%s' and '%s')", j->mask_path, arg);
        return 0;
    }
    j->mask_path = arg;
    return 1;
}

static soak_status start_map(const drying_job *j, soak_image *out)
{
    size_t n = (size_t)j->mask.width * j->mask.height;
    double *t0 = malloc(sizeof(double) * n);
    unsigned char *wet = malloc(n);
    soak_status st = (t0 && wet) ? soak_drying_start_times(&j->mask, &j->p, t0, wet) : SOAK_ERR_NOMEM;
    if (st == SOAK_OK) st = soak_image_alloc(out, j->mask.width, j->mask.height, 1);
    if (st == SOAK_OK)
        for (size_t i = 0; i < n; ++i) out->pixels[i] = wet[i] ? (float)(1 - t0[i]) : 0.0f;
    free(t0);
    free(wet);
    return st;
}

static soak_status frame(void *vctx, int f, double time, const soak_bake_exec *exec, soak_image *out, char *err,
                         size_t errlen)
{
    const drying_job *j = vctx;
    soak_drying_params p = j->p;
    if (!(time >= 0)) {
        if (f < 0) snprintf(err, errlen, "--time: drying time must be >= 0, got %g", time);
        else snprintf(err, errlen, "--time/--frame-time/--frame-origin: frame %d at drying time %g (< 0)", f, time);
        return SOAK_ERR_ARG;
    }
    p.time = time;
    if (j->start_map) return start_map(j, out);
    soak_status st = soak_bake_drying(j->mask.pixels ? &j->mask : NULL, j->width, j->height, &p, exec, out);
    if (st == SOAK_ERR_ARG) snprintf(err, errlen, "invalid drying settings at time %g", time);
    return st;
}

/* Reads --mask into j->mask, the same size as --width/--height when given.
 * Returns 0 or the exit code. */
static int read_mask(drying_job *j, const bake_opts *o)
{
    char err[4352] = "";
    /* The frame's working memory, from the header, before any pixel is
     * decoded (a 1.16 MB PNG declaring 16384^2 took 5.6 GB). */
    soak_image_info info;
    soak_status st = soak_image_probe(j->mask_path, &info, err, sizeof err);
    if (st == SOAK_OK) {
        char what[4200];
        snprintf(what, sizeof what, "%s: drying a %dx%d mask", j->mask_path, info.width, info.height);
        double mask_bytes = (double)info.width * info.height * info.channels * sizeof(float);
        st = soak_memory_check(what, mask_bytes + soak_drying_peak_bytes(info.width, info.height, &j->p),
                               info.payload_bytes, err, sizeof err);
    }
    if (st == SOAK_OK) st = soak_image_read(j->mask_path, &j->mask, err, sizeof err);
    if (st != SOAK_OK) return bake_fail(CMD, st == SOAK_ERR_ARG ? SOAK_ERR_IO : st, err);
    if (soak_bake_check_size(j->mask.width, j->mask.height) != SOAK_OK) {
        cli_error(CMD, "%s: %dx%d is larger than %d in a direction", j->mask_path, j->mask.width, j->mask.height,
                  SOAK_BAKE_MAX_SIZE);
        return SOAK_EXIT_FAIL;
    }
    if ((o->have_width && o->width != j->mask.width) || (o->have_height && o->height != j->mask.height)) {
        cli_error(CMD, "--width/--height %ldx%ld do not match the mask %s (%dx%d)", o->width, o->height, j->mask_path,
                  j->mask.width, j->mask.height);
        return SOAK_EXIT_USAGE;
    }
    return 0;
}

int soak_bake_drying_main(int argc, char **argv)
{
    bake_opts o;
    bake_opts_init(&o, CMD, 0.5, 0.01);
    drying_job j;
    memset(&j, 0, sizeof j);
    soak_drying_defaults(&j.p);
    const cli_spec spec = BAKE_SPEC(CMD, usage, mask_arg, &j);
    const cli_opt_table tables[] = DRYING_TABLES(&o, &j);
    int rc = cli_opts_parse(&spec, tables, sizeof tables / sizeof tables[0], argc, argv);
    if (rc >= 0) return rc;
    if (j.start_map && !j.mask_path) {
        cli_error(CMD, "--start-map needs a MASK image");
        return SOAK_EXIT_USAGE;
    }
    j.p.seed = o.seed;
    j.width = (int)o.width;
    j.height = (int)o.height;
    if ((rc = bake_opts_check(&o, &j.mask_path, j.mask_path ? 1 : 0)) != 0 || (rc = bake_check_times(&o, 0, HUGE_VAL)))
        return rc;
    if (!j.mask_path || (rc = read_mask(&j, &o)) == 0) rc = bake_run(&o, frame, &j);
    soak_image_free(&j.mask);
    return rc;
}
