/* soak bake ripples: a looping, tiling normal-map flipbook of rain rings on
 * standing water (model in soak/bake_ripples.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_budget.h"
#include "bake_cli.h"
#include "cli.h"
#include "soak/bake_ripples.h"

#define CMD "bake ripples"

typedef struct ripples_job {
    soak_ripples_params p;
    const char *far_path;
    double far_px;
    soak_ripple_impact *impacts;
    size_t count;
} ripples_job;

#define F(field) CLI_FIELD(ripples_job, field)
static const cli_opt ripples_opts[] = {
    {"--rate", NULL, CLI_OPT_DOUBLE, .lo = 1e-6, .hi = 500, F(p.rate_mm_h), .meta = "MM_H",
     .help = "rain rate, (0, 500] mm/h (default 10)" BAKE_DELIVERED_RATE_HELP},
    {"--tile", NULL, CLI_OPT_DOUBLE, .lo = 1e-6, .hi = 100, F(p.tile_m), .meta = "M",
     .help = "side of the square tile in metres (default 0.5)"},
    {"--loop-frames", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_RIPPLES_MAX_FRAMES, F(p.frames), .meta = "N",
     .help = "frames per loop, %R (default 64); frame N is frame 0 again"},
    {"--period", NULL, CLI_OPT_DOUBLE, .lo = 1e-6, .hi = 1e4, F(p.period), .meta = "S",
     .help = "loop duration, seconds (default 2.56)"},
    {"--wavelength", NULL, CLI_OPT_DOUBLE, .lo = 1e-6, .hi = 10, F(p.wavelength_m), .meta = "M",
     .help = "ring carrier wavelength, m (default 2 pi sqrt(sigma / (rho g)) = 0.01713,\nthe slowest capillary-gravity wave, water at 20 C)"},
    {"--ring-width", NULL, CLI_OPT_DOUBLE, .lo = 1e-6, .hi = 10, F(p.width_m), .meta = "M",
     .help = "ring envelope standard deviation, m (default: half a wavelength)"},
    {"--lifetime", NULL, CLI_OPT_DOUBLE, .lo = 1e-6, .hi = 1e3, F(p.lifetime), .meta = "S",
     .help = "e-folding time of a ring's height, s (default 0.5)"},
    {"--amplitude", NULL, CLI_OPT_DOUBLE, .lo = 1e-12, .hi = 1, F(p.amplitude_m), .meta = "M",
     .help = "ring height at impact, m (default 0.0003)"},
    {"--min-drop", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 5.99, F(p.min_diameter_mm), .meta = "MM",
     .help = "drops that make rings, mm (default 1)"},
    {"--far", NULL, CLI_OPT_STRING, F(far_path), .meta = "PATH",
     .help = "also write the distance version (slopes low-passed), same pattern rules as -o"},
    {"--far-filter", NULL, CLI_OPT_DOUBLE, .lo = 1e-3, .hi = SOAK_BLUR_MAX_SIGMA, F(far_px), .meta = "PX",
     .help = "its Gaussian standard deviation in texels (default 4)"},
};
#undef F

#define RIPPLES_TABLES(o, j) {BAKE_IMAGE_TABLE(o), CLI_TABLE(ripples_opts, (j)), BAKE_SEQUENCE_TABLE(o)}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake ripples [options] --frames 0-63 -o ripples.%%04d.exr\n\n"
            "A normal-map flipbook of rain rings on standing water that tiles in space and loops\n"
            "in time. Drops of at least --min-drop from the Marshall-Palmer / Atlas et al. flux\n"
            "(see soak bake drops --help) hit the tile at random; each starts a ring whose radius\n"
            "grows at the group velocity of capillary-gravity waves (omega^2 = g k + sigma/rho k^3,\n"
            "Lamb 1932) at its wavelength and whose height decays over --lifetime. RGB = (n+1)/2,\n"
            "tangent space, v up (OpenGL/Blender); alpha = 0.5 + height / (4 amplitude) (POV-Ray\n"
            "bumps). --far writes the low-passed version for distant puddles. The tile is square:\n"
            "--width (default 512 here) sets its size; frame f is at f * period / loop-frames\n"
            "(--time, --frame-time and --frame-origin do not apply).\n\n"
            "options:\n");
    cli_opt img[BAKE_SHARED_OPTS_MAX];
    size_t n = bake_table_help(bake_image_opts, bake_image_opts_n, img, "--width", "tile side in texels, %R (default 512)");
    bake_table_help(img, n, img, "--height", "the same as --width if given (the tile is square)");
    const cli_opt_table tables[] = {{img, n, NULL}, CLI_TABLE(ripples_opts, NULL), BAKE_SEQUENCE_TABLE(NULL)};
    cli_opts_help(out, tables, sizeof tables / sizeof tables[0]);
    fprintf(out, "\nexample:\n"
                 "  soak bake ripples --rate 10 --width 512 --frames 0-63 -o ripples.%%04d.exr --far far.%%04d.exr\n");
}

static soak_status frame(void *vctx, int f, double time, const soak_bake_exec *exec, soak_image *out,
                         struct soak_staged *extra, char *err, size_t errlen)
{
    (void)time;
    ripples_job *j = vctx;
    long index = f < 0 ? 0 : f;
    soak_image far = {0, 0, 0, NULL};
    soak_status st = soak_ripples_frame(&j->p, j->impacts, j->count, index, j->far_path ? j->far_px : 0, exec, out,
                                        &far);
    if (st == SOAK_OK && j->far_path) {
        char path[4096];
        st = f < 0 ? (snprintf(path, sizeof path, "%s", j->far_path), SOAK_OK)
                   : soak_bake_frame_path(j->far_path, f, path, sizeof path);
        if (st == SOAK_OK) st = soak_bake_stage(extra, path, &far, 0, err, errlen);
    }
    soak_image_free(&far);
    char label[32];
    if (st != SOAK_OK && !err[0])
        snprintf(err, errlen, "%s: %s", bake_frame_label(f, label, sizeof label), soak_status_str(st));
    return st;
}

/* --far: a writable output of the same kind (pattern or not) as -o. */
static int check_far(const ripples_job *j, const bake_opts *o)
{
    if (!j->far_path) return 0;
    bake_opts far = *o;
    far.output = j->far_path;
    far.output_option = "--far";
    int rc = bake_opts_check(&far, NULL, 0);
    const bake_output outs[2] = {{"-o", o->output}, {"--far", j->far_path}};
    return rc ? rc : bake_plan_check(o, outs, 2, NULL, 0);
}

int soak_bake_ripples_main(int argc, char **argv)
{
    bake_opts o;
    bake_opts_init(&o, CMD, 0, 0);
    o.width = 512;
    ripples_job j;
    memset(&j, 0, sizeof j);
    soak_ripples_defaults(&j.p);
    j.far_px = 4;
    int ring_width_given = 0;
    for (int i = 1; i < argc; ++i) ring_width_given |= strcmp(argv[i], "--ring-width") == 0;
    const cli_spec spec = BAKE_SPEC(CMD, usage, NULL, &j);
    const cli_opt_table tables[] = RIPPLES_TABLES(&o, &j);
    int rc = cli_opts_parse(&spec, tables, sizeof tables / sizeof tables[0], argc, argv);
    if (rc >= 0) return rc;
    if (!ring_width_given) j.p.width_m = 0.5 * j.p.wavelength_m;
    if (!ring_width_given && !(j.p.width_m >= 1e-6)) {
        cli_error(CMD, "--wavelength %g m: the ring width it implies (half a wavelength, %g m) is under the floor "
                       "1e-6 m; give --ring-width or a wavelength of at least 2e-6 m",
                  j.p.wavelength_m, j.p.width_m);
        return SOAK_EXIT_USAGE;
    }
    if ((o.have_height && o.height != o.width) || o.time != 0 || o.frame_time != 0 || o.have_origin) {
        cli_error(CMD, "%s", o.have_height && o.height != o.width
                                 ? "the tile is square: give --width only"
                                 : "--time, --frame-time, --frame-origin do not apply: frame f is at f * period / "
                                   "loop-frames");
        return SOAK_EXIT_USAGE;
    }
    j.p.size = (int)o.width;
    j.p.seed = o.seed;
    o.plan_later = j.far_path != NULL; /* check_far plans -o and --far together */
    if ((rc = bake_opts_check(&o, NULL, 0)) != 0 || (rc = check_far(&j, &o)) != 0) return rc;
    o.plan_later = 0;
    if ((rc = bake_ripples_budget(CMD, &j.p, o.have_frames ? o.last - o.first + 1 : 1)) != 0) return rc;
    soak_status st = soak_ripples_impacts(&j.p, &j.impacts, &j.count);
    if (st != SOAK_OK) return bake_fail(CMD, st, "invalid ripple settings (too many impacts per loop?)");
    rc = bake_run_staged(&o, frame, &j);
    free(j.impacts);
    return rc;
}
