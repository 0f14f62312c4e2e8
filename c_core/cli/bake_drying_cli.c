/* soak bake drying: a wet region drying from its borders (seed 002 sec. 3.3)
 * or by evaporation and capillary diffusion. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"

#define CMD "bake drying"

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake drying [MASK] [options] -o OUT\n\n"
            "Wetness of a drying region. MASK is any image OpenImageIO reads (luma of RGB); texels\n"
            "above --threshold start wet. Without MASK the whole --width x --height surface is wet\n"
            "and only --noise decides the drying order.\n\n"
            "  --mode schedule   (default) seed 002's pore schedule run as emptying: texel drying\n"
            "                    starts at t0 = (1 - t_fill) * d/d_max (d = exact Euclidean distance\n"
            "                    to the nearest dry texel, so borders dry first), optionally mixed\n"
            "                    with fBm noise; wetness = 1 - fill_fraction(t, t0, t_fill); the whole\n"
            "                    region is dry at t = 1.\n"
            "  --mode diffusion  water depth with evaporation at the surface and lateral capillary\n"
            "                    diffusion, solved implicitly (stable for any step): puddles spread a\n"
            "                    little and shrink from their edges; a unit film dries in --drying-time.\n\n"
            "options:\n"
            "  -o, --output PATH        .exr (half; --float for 32-bit), .png/.tif (16-bit linear), .tx\n"
            "  --width N, --height N    size without MASK (default 1024); with MASK they must match it\n"
            "  --seed N                 noise seed (default 0)\n"
            "  --threads N              worker threads (default: every core)\n"
            "  --threshold V            mask level above which a texel is wet (default 0.5)\n"
            "  --t-fill F               pore emptying time, 0..1, 0 = sharp step (default 0.2)\n"
            "  --noise A                fraction of fBm in the start time, 0..1 (default 0)\n"
            "  --noise-frequency F      noise cells across the width (default 8)\n"
            "  --noise-octaves N        1..24 (default 4)\n"
            "  --start-map              write the start-time texture 1 - t0 instead (wet texels; seed\n"
            "                           002's wet-texture convention, value 1 = first)\n"
            "  --drying-time T          diffusion: time for a unit film to evaporate (default 1)\n"
            "  --diffusion-length L     diffusion: spreading length over the drying time, pixels (default 8)\n"
            "  --steps N                diffusion: implicit steps per frame, 1..100000 (default 32)\n"
            "  --frames A-B             image sequence; -o must hold a pattern such as dry.%%04d.exr\n"
            "  --time T                 time of frame F (default 0.5)\n"
            "  --frame-time DT          time between frames (default 0.01): frame f is at T + (f-F) DT\n"
            "  --frame-origin F         frame baked at time T (default A); give the sequence's first\n"
            "                           frame to bake it in chunks (--frames 11-20 ...) that equal one run\n\n"
            "example:\n"
            "  soak bake drying splash_mask.png --t-fill 0.2 --noise 0.3 --frames 0-100 -o dry.%%04d.exr\n");
}

typedef struct drying_job {
    soak_drying_params p;
    soak_image mask; /* pixels NULL without a mask */
    int width, height;
    int start_map;
} drying_job;

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

typedef struct num_opt {
    const char *name;
    double lo, hi;
    double *dst;
} num_opt;

static int parse(drying_job *j, bake_opts *o, int argc, char **argv, const char **mask_path)
{
    const num_opt nums[] = {
        {"--threshold", -1e6, 1e6, &j->p.threshold},       {"--t-fill", 0, 1, &j->p.t_fill},
        {"--noise", 0, 1, &j->p.noise_amount},             {"--noise-frequency", 1e-6, 8192, &j->p.noise_frequency},
        {"--drying-time", 1e-9, 1e12, &j->p.drying_time}, {"--diffusion-length", 0, 1e6, &j->p.diffusion_length},
    };
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v;
        long n;
        int r = bake_opts_parse(o, argc, argv, &i);
        if (r < 0) return SOAK_EXIT_USAGE;
        if (r > 0) continue;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            return -1;
        } else if (cli_is(a, "--mode")) {
            if (!(v = cli_value(CMD, argc, argv, &i))) return SOAK_EXIT_USAGE;
            if (strcmp(v, "schedule") == 0) j->p.mode = SOAK_DRYING_SCHEDULE;
            else if (strcmp(v, "diffusion") == 0) j->p.mode = SOAK_DRYING_DIFFUSION;
            else {
                cli_error(CMD, "--mode: expected schedule or diffusion, got '%s'", v);
                return SOAK_EXIT_USAGE;
            }
        } else if (cli_is(a, "--start-map")) {
            j->start_map = 1;
        } else if (cli_is(a, "--noise-octaves") || cli_is(a, "--steps")) {
            int oct = cli_is(a, "--noise-octaves");
            const char *name = oct ? "--noise-octaves" : "--steps";
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_int(CMD, name, v, 1, oct ? 24 : 100000, &n))
                return SOAK_EXIT_USAGE;
            if (oct) j->p.noise_octaves = (int)n;
            else j->p.steps = (int)n;
        } else if (a[0] == '-' && a[1] != '\0') {
            int matched = 0;
            for (size_t k = 0; k < sizeof nums / sizeof nums[0] && !matched; ++k) {
                if (!cli_is(a, nums[k].name)) continue;
                matched = 1;
                if (!(v = cli_value(CMD, argc, argv, &i)) ||
                    !cli_parse_double(CMD, nums[k].name, v, nums[k].lo, nums[k].hi, nums[k].dst))
                    return SOAK_EXIT_USAGE;
            }
            if (!matched) {
                cli_error(CMD, "unknown option '%s' (see --help)", a);
                return SOAK_EXIT_USAGE;
            }
        } else if (!*mask_path) {
            *mask_path = a;
        } else {
            cli_error(CMD, "one mask image only (got '%s' and '%s')", *mask_path, a);
            return SOAK_EXIT_USAGE;
        }
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
    const char *mask_path = NULL;
    int rc = parse(&j, &o, argc, argv, &mask_path);
    if (rc) return rc < 0 ? SOAK_EXIT_OK : rc;
    if (j.start_map && !mask_path) {
        cli_error(CMD, "--start-map needs a MASK image");
        return SOAK_EXIT_USAGE;
    }
    j.p.seed = o.seed;
    j.width = (int)o.width;
    j.height = (int)o.height;
    if ((rc = bake_opts_check(&o, &mask_path, mask_path ? 1 : 0)) != 0) return rc;
    if (mask_path) {
        char err[4352] = "";
        soak_status st = soak_image_read(mask_path, &j.mask, err, sizeof err);
        if (st != SOAK_OK) return bake_fail(CMD, st == SOAK_ERR_ARG ? SOAK_ERR_IO : st, err);
        if (soak_bake_check_size(j.mask.width, j.mask.height) != SOAK_OK) {
            cli_error(CMD, "%s: %dx%d is larger than %d in a direction", mask_path, j.mask.width, j.mask.height,
                      SOAK_BAKE_MAX_SIZE);
            soak_image_free(&j.mask);
            return SOAK_EXIT_FAIL;
        }
        if ((o.have_width && o.width != j.mask.width) || (o.have_height && o.height != j.mask.height)) {
            cli_error(CMD, "--width/--height %ldx%ld do not match the mask %s (%dx%d)", o.width, o.height, mask_path,
                      j.mask.width, j.mask.height);
            soak_image_free(&j.mask);
            return SOAK_EXIT_USAGE;
        }
    }
    rc = bake_run(&o, frame, &j);
    soak_image_free(&j.mask);
    return rc;
}
