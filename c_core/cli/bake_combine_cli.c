/* soak bake combine: per-texel operations on maps of the same size. */
#include <stdio.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"

#define CMD "bake combine"

typedef struct combine_job {
    const bake_opts *o;
    const char *op;
    const char *inputs[BAKE_MAX_INPUTS];
    int n_inputs;
    double lo, hi, sigma, in_lo, in_hi, out_lo, out_hi;
    int wrap, clamp;
} combine_job;

/* Map values: any finite number (the CLI's bound of "finite"). */
#define COMBINE_MAX_VALUE 1e30
/* --sigma's floor (the library takes any sigma > 0): the kernel is the
 * identity well before it. */
#define COMBINE_MIN_SIGMA 1e-3

#define F(field) CLI_FIELD(combine_job, field)
#define VALUE(name, field, help_)                                                                                      \
    {name, NULL, CLI_OPT_DOUBLE, .lo = -COMBINE_MAX_VALUE, .hi = COMBINE_MAX_VALUE, F(field), .meta = "V",           \
     .help = help_}
static const cli_opt combine_opts[] = {
    VALUE("--lo", lo, "clamp: the low end (default 0)"),
    VALUE("--hi", hi, "clamp: the high end (default 1)"),
    {"--sigma", NULL, CLI_OPT_DOUBLE, .lo = COMBINE_MIN_SIGMA, .hi = SOAK_BLUR_MAX_SIGMA, F(sigma), .meta = "S",
     .help = "blur: Gaussian sigma, %R pixels (default 1)"},
    {"--wrap", NULL, CLI_OPT_FLAG, .flag = 1, F(wrap), .help = "blur: wrap around the edges (tileable maps)"},
    VALUE("--in-lo", in_lo, "remap: input value mapped to --out-lo (default 0)"),
    VALUE("--in-hi", in_hi, "remap: input value mapped to --out-hi (default 1)"),
    VALUE("--out-lo", out_lo, "remap: (default 0)"),
    VALUE("--out-hi", out_hi, "remap: (default 1)"),
    {"--clamp", NULL, CLI_OPT_FLAG, .flag = 1, F(clamp), .help = "remap: clamp to the output range"},
};
#undef VALUE
#undef F

#define COMBINE_TABLES(o, j) {BAKE_IMAGE_TABLE(o), CLI_TABLE(combine_opts, (j)), BAKE_SEQUENCE_TABLE(o)}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake combine OP INPUT... [options] -o OUT\n\n"
            "Combines maps texel by texel; inputs must have the same width, height and channels.\n"
            "  max | min | multiply | add   two or more inputs, folded left to right\n"
            "  clamp                        one input, to [--lo, --hi] (default 0..1)\n"
            "  blur                         one input, separable Gaussian of --sigma pixels\n"
            "                               (edges clamp; --wrap for tileable maps)\n"
            "  remap                        one input, [--in-lo, --in-hi] -> [--out-lo, --out-hi]\n"
            "                               linearly (defaults 0..1 -> 0..1), --clamp to the output range\n"
            "--width and --height are an optional check: the inputs must have this size. --frames\n"
            "bakes sequences: inputs and -o may hold a pattern such as wet.%%04d.exr. --seed,\n"
            "--time, --frame-time and --frame-origin are accepted for uniformity; unused.\n\n"
            "options:\n");
    const cli_opt_table tables[] = COMBINE_TABLES(NULL, NULL);
    cli_opts_help(out, tables, sizeof tables / sizeof tables[0]);
    fprintf(out, "\nexample:\n"
                 "  soak bake combine max waves.exr puddles.exr -o wet.exr\n"
                 "  soak bake combine blur wet.exr --sigma 2.5 -o wet_soft.exr\n");
}

/* OP, then the inputs. */
static int op_or_input(void *ctx, const char *arg)
{
    combine_job *j = ctx;
    if (!j->op) {
        j->op = arg;
    } else if (j->n_inputs < BAKE_MAX_INPUTS) {
        j->inputs[j->n_inputs++] = arg;
    } else {
        cli_error(CMD, "at most %d inputs", BAKE_MAX_INPUTS);
        return 0;
    }
    return 1;
}

static const char *const binary_ops[] = {"max", "min", "multiply", "add"};

static int binary_op(const char *op)
{
    for (int k = 0; k < 4; ++k)
        if (strcmp(op, binary_ops[k]) == 0) return k;
    return -1;
}

static soak_status read_input(const combine_job *j, int k, int frame, soak_image *img, char *err, size_t errlen)
{
    char path[4096];
    const char *p = j->inputs[k];
    if (frame >= 0 && soak_bake_pattern_kind(p) == 1) {
        if (soak_bake_frame_path(p, frame, path, sizeof path) != SOAK_OK) return SOAK_ERR_ARG;
        p = path;
    }
    /* Working memory from the header before decoding: the running result,
     * this input and their combination (3 images), and the encoding (10
     * bytes per pixel, as bake drying's estimate). */
    soak_image_info info;
    soak_status st = soak_image_probe(p, &info, err, errlen);
    if (st == SOAK_OK) {
        char what[4200];
        snprintf(what, sizeof what, "%s: combining %dx%d images", p, info.width, info.height);
        double px = (double)info.width * info.height;
        st = soak_memory_check(what, px * (3.0 * info.channels * sizeof(float) + 10.0), info.payload_bytes, err,
                               errlen);
    }
    if (st == SOAK_OK) st = soak_image_read(p, img, err, errlen);
    if (st != SOAK_OK) return st == SOAK_ERR_ARG ? SOAK_ERR_IO : st;
    if (soak_bake_check_size(img->width, img->height) != SOAK_OK) {
        snprintf(err, errlen, "%s: %dx%d is larger than %d in a direction", p, img->width, img->height,
                 SOAK_BAKE_MAX_SIZE);
        soak_image_free(img);
        return SOAK_ERR_IO;
    }
    if ((j->o->have_width && j->o->width != img->width) || (j->o->have_height && j->o->height != img->height)) {
        snprintf(err, errlen, "%s: size %dx%d does not match --width/--height", p, img->width, img->height);
        soak_image_free(img);
        return SOAK_ERR_ARG;
    }
    return SOAK_OK;
}

static soak_status frame(void *vctx, int f, double time, const soak_bake_exec *exec, soak_image *out, char *err,
                         size_t errlen)
{
    (void)time;
    const combine_job *j = vctx;
    soak_image acc;
    soak_status st = read_input(j, 0, f, &acc, err, errlen);
    if (st != SOAK_OK) return st;
    int op = binary_op(j->op);
    if (op >= 0) {
        for (int k = 1; k < j->n_inputs && st == SOAK_OK; ++k) {
            soak_image next, res;
            if ((st = read_input(j, k, f, &next, err, errlen)) != SOAK_OK) break;
            st = soak_map_combine((soak_combine_op)op, &acc, &next, &res);
            if (st == SOAK_ERR_ARG)
                snprintf(err, errlen, "%s (%dx%d, %d channels) does not match %s (%dx%d, %d channels)", j->inputs[k],
                         next.width, next.height, next.channels, j->inputs[0], acc.width, acc.height, acc.channels);
            soak_image_free(&next);
            if (st == SOAK_OK) {
                soak_image_free(&acc);
                acc = res;
            }
        }
        if (st == SOAK_OK) *out = acc;
        else soak_image_free(&acc);
        return st;
    }
    if (strcmp(j->op, "clamp") == 0) st = soak_map_clamp(&acc, j->lo, j->hi, out);
    else if (strcmp(j->op, "blur") == 0) st = soak_map_blur(&acc, j->sigma, j->wrap, exec, out);
    else st = soak_map_remap(&acc, j->in_lo, j->in_hi, j->out_lo, j->out_hi, j->clamp, out);
    if (st == SOAK_ERR_ARG) snprintf(err, errlen, "%s: invalid parameters for %s", j->inputs[0], j->op);
    soak_image_free(&acc);
    return st;
}

/* OP and its inputs and settings agree. Returns 0 or the exit code. */
static int validate(const combine_job *j)
{
    if (!j->op) {
        cli_error(CMD, "missing OP: max, min, multiply, add, clamp, blur or remap (see --help)");
        return SOAK_EXIT_USAGE;
    }
    int binary = binary_op(j->op) >= 0;
    if (!binary && strcmp(j->op, "clamp") != 0 && strcmp(j->op, "blur") != 0 && strcmp(j->op, "remap") != 0) {
        cli_error(CMD, "unknown OP '%s': expected max, min, multiply, add, clamp, blur or remap", j->op);
        return SOAK_EXIT_USAGE;
    }
    if (binary ? j->n_inputs < 2 : j->n_inputs != 1) {
        cli_error(CMD, "%s takes %s, got %d", j->op, binary ? "two or more inputs" : "exactly one input", j->n_inputs);
        return SOAK_EXIT_USAGE;
    }
    if (strcmp(j->op, "clamp") == 0 && !(j->lo <= j->hi)) {
        cli_error(CMD, "--lo (%g) must be <= --hi (%g)", j->lo, j->hi);
        return SOAK_EXIT_USAGE;
    }
    if (strcmp(j->op, "remap") == 0 && j->in_lo == j->in_hi) {
        cli_error(CMD, "--in-lo and --in-hi must differ (both %g)", j->in_lo);
        return SOAK_EXIT_USAGE;
    }
    return 0;
}

int soak_bake_combine_main(int argc, char **argv)
{
    bake_opts o;
    bake_opts_init(&o, CMD, 0, 1);
    combine_job j = {.o = &o, .lo = 0, .hi = 1, .sigma = 1, .in_lo = 0, .in_hi = 1, .out_lo = 0, .out_hi = 1};
    const cli_spec spec = BAKE_SPEC(CMD, usage, op_or_input, &j);
    const cli_opt_table tables[] = COMBINE_TABLES(&o, &j);
    int rc = cli_opts_parse(&spec, tables, sizeof tables / sizeof tables[0], argc, argv);
    if (rc >= 0) return rc;
    if ((rc = validate(&j)) != 0 || (rc = bake_opts_check(&o, j.inputs, j.n_inputs)) != 0) return rc;
    return bake_run(&o, frame, &j);
}
