/* soak bake turbulence: procedural wetness from fBm or turbulence noise. */
#include <stdio.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"

#define CMD "bake turbulence"

typedef struct turb_job {
    soak_turbulence_params p;
    double z0, evolve;
    int width, height;
} turb_job;

/* A rate, not bounded by the library: a frame's z (SOAK_NOISE_MAX_Z) is. */
#define TURB_MAX_EVOLVE 1e6

#define F(field) CLI_FIELD(turb_job, field)
#define SEEN_3D CLI_SEEN(turb_job, p.use_3d)
static const cli_opt turb_opts[] = {
    {"--fbm", NULL, CLI_OPT_FLAG, .flag = SOAK_NOISE_FBM, F(p.sum), .help = "sum of noise (the default)"},
    {"--tileable", NULL, CLI_OPT_FLAG, .flag = 1, F(p.tileable),
     .help = "periodic across the image edges (cell counts rounded per octave)"},
    {"--z", NULL, CLI_OPT_DOUBLE, .lo = -SOAK_NOISE_MAX_Z, .hi = SOAK_NOISE_MAX_Z, F(z0), SEEN_3D, .meta = "Z",
     .help = "slice of the 3D noise (switches to 3D noise)"},
    {"--evolve", NULL, CLI_OPT_DOUBLE, .lo = -TURB_MAX_EVOLVE, .hi = TURB_MAX_EVOLVE, F(evolve), SEEN_3D,
     .meta = "R",
     .help = "3D noise moving R octave-0 cells per time unit (animation):\nthe slice at time T is z = Z + R T"},
};
#undef F
#undef SEEN_3D

/* The shared options (bake_opts o), the noise (p = &j->p) and the kind's. */
#define TURB_TABLES(o, j, p)                                                                                           \
    {BAKE_IMAGE_TABLE(o), BAKE_NOISE_TABLE(p), CLI_TABLE(turb_opts, (j)), BAKE_SEQUENCE_TABLE(o)}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake turbulence [options] -o OUT\n\n"
            "Gradient-noise wetness map (improved Perlin noise, Jensen et al. 1999's procedural wetness):\n"
            "fBm (signed, about [-1,1]) or turbulence (sum of |noise|, [0,1]), normalised by the\n"
            "sum of octave amplitudes; optionally thresholded to a wet/dry mask with a soft edge.\n"
            "Sequences: --time 0 and --frame-time 1/24 by default.\n\n"
            "options:\n");
    const cli_opt_table tables[] = TURB_TABLES(NULL, NULL, NULL);
    cli_opts_help(out, tables, sizeof tables / sizeof tables[0]);
    fprintf(out, "\nexample:\n"
                 "  soak bake turbulence --turbulence --octaves 6 --frequency 6 --threshold 0.25 --softness 0.05 \\\n"
                 "       --width 2048 --height 2048 --seed 7 -o wet.exr\n");
}

static soak_status frame(void *vctx, int f, double time, const soak_bake_exec *exec, soak_image *out, char *err,
                         size_t errlen)
{
    (void)f;
    const turb_job *j = vctx;
    soak_turbulence_params p = j->p;
    if (p.use_3d) p.z = j->z0 + j->evolve * time;
    soak_status st = soak_bake_turbulence(&p, j->width, j->height, exec, out);
    if (st == SOAK_ERR_ARG)
        snprintf(err, errlen,
                 "invalid noise settings: frequency * lacunarity^(octaves-1) must be <= 20000 and |z| <= 1e6 "
                 "(z = %g at time %g)",
                 p.z, time);
    return st;
}

int soak_bake_turbulence_main(int argc, char **argv)
{
    bake_opts o;
    bake_opts_init(&o, CMD, 0, 1.0 / 24);
    turb_job j = {.z0 = 0, .evolve = 0};
    soak_turbulence_defaults(&j.p);
    const cli_spec spec = BAKE_SPEC(CMD, usage, NULL, NULL);
    const cli_opt_table tables[] = TURB_TABLES(&o, &j, &j.p);
    int rc = cli_opts_parse(&spec, tables, sizeof tables / sizeof tables[0], argc, argv);
    if (rc >= 0) return rc;
    j.width = (int)o.width;
    j.height = (int)o.height;
    j.p.seed = o.seed;
    j.p.z = j.z0;
    if (soak_turbulence_check(&j.p) != SOAK_OK) {
        cli_error(CMD, "frequency * lacunarity^(octaves-1) must be <= 20000 (finer than any pixel)");
        return SOAK_EXIT_USAGE;
    }
    if ((rc = bake_opts_check(&o, NULL, 0)) != 0) return rc;
    return bake_run(&o, frame, &j);
}
