/* soak bake waves: beach wetness left by the last waves ([JLD99] sec. 4.2). */
#include <stdio.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"

#define CMD "bake waves"

typedef struct waves_job {
    soak_waves_params p;
    int width, height;
} waves_job;

#define F(field) CLI_FIELD(waves_job, field)
static const cli_opt waves_opts[] = {
    {"--waves", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_WAVES_MAX_WAVES, F(p.waves), .meta = "N",
     .help = "waves still visible, %R (default 4, as in Jensen et al. 1999)"},
    {"--direction", NULL, CLI_OPT_DOUBLE, .lo = -SOAK_WAVES_MAX_DIRECTION, .hi = SOAK_WAVES_MAX_DIRECTION,
     F(p.direction_deg), .meta = "DEG",
     .help = "inland direction, degrees from +x towards the image bottom (default 90)"},
    {"--shore", NULL, CLI_OPT_DOUBLE, .lo = -SOAK_WAVES_MAX_LENGTH, .hi = SOAK_WAVES_MAX_LENGTH, F(p.shore),
     .meta = "S", .help = "still-water line offset from the centre along it (default -0.2)"},
    {"--reach-min", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_WAVES_MAX_LENGTH, F(p.reach_min), .meta = "R",
     .help = "run-up beyond the water line: the least (default 0.05)"},
    {"--reach-max", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_WAVES_MAX_LENGTH, F(p.reach_max), .meta = "R",
     .help = "and the most (default 0.3)"},
    {"--period", NULL, CLI_OPT_DOUBLE, .lo = BAKE_MIN_POSITIVE, .hi = SOAK_WAVES_MAX_PERIOD, F(p.period), .meta = "P",
     .help = "time between waves (default 8)"},
    {"--dry-time", NULL, CLI_OPT_DOUBLE, .lo = BAKE_MIN_POSITIVE, .hi = SOAK_WAVES_MAX_DRY_TIME, F(p.dry_time),
     .meta = "T", .help = "e-folding time of a wave's water (default 20)"},
    {"--dry-length", NULL, CLI_OPT_DOUBLE, .lo = BAKE_MIN_POSITIVE, .hi = SOAK_WAVES_MAX_DRY_LENGTH, F(p.dry_length),
     .meta = "L", .help = "e-folding distance inland of that water (default 0.5)"},
    {"--fringe", NULL, CLI_OPT_DOUBLE, .lo = BAKE_MIN_POSITIVE, .hi = SOAK_WAVES_MAX_DRY_LENGTH, F(p.fringe),
     .meta = "F", .help = "capillary fringe height above the water line (default 0.03)"},
    {"--front-amplitude", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_WAVES_MAX_LENGTH, F(p.front_amplitude),
     .meta = "A", .help = "turbulence displacement of the fronts (default 0.04)"},
    {"--front-frequency", NULL, CLI_OPT_DOUBLE, .lo = BAKE_MIN_POSITIVE, .hi = SOAK_WAVES_MAX_FRONT_FREQUENCY,
     F(p.front_frequency), .meta = "F", .help = "turbulence cells per width along the shore (default 3)"},
    {"--front-octaves", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_WAVES_MAX_FRONT_OCTAVES, F(p.front_octaves),
     .meta = "N", .help = "%R (default 4)"},
    {"--edge", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_WAVES_MAX_LENGTH, F(p.edge), .meta = "E",
     .help = "soft edge width of each front, 0 = sharp (default 0.01)"},
};
#undef F

#define WAVES_TABLES(o, j) {BAKE_IMAGE_TABLE(o), CLI_TABLE(waves_opts, (j)), BAKE_SEQUENCE_TABLE(o)}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake waves [options] -o OUT\n\n"
            "Wet sand left by the last N waves on a beach: bands behind turbulence-perturbed fronts,\n"
            "each drying with its age and its height up the beach, saturated below the water line.\n"
            "Lengths are in image widths from the image centre; times in any unit (default seconds).\n"
            "Wave j arrives at time j*P. Sequences: --time 0 and --frame-time 1/24 by default.\n\n"
            "options:\n");
    const cli_opt_table tables[] = WAVES_TABLES(NULL, NULL);
    cli_opts_help(out, tables, sizeof tables / sizeof tables[0]);
    fprintf(out, "\nexample:\n"
                 "  soak bake waves --waves 4 --direction 90 --shore 0.2 --seed 3 --width 2048 --height 1024 -o beach.exr\n");
}

static soak_status frame(void *vctx, int f, double time, const soak_bake_exec *exec, soak_image *out, char *err,
                         size_t errlen)
{
    (void)f;
    const waves_job *j = vctx;
    soak_waves_params p = j->p;
    p.time = time;
    soak_status st = soak_bake_waves(&p, j->width, j->height, exec, out);
    if (st == SOAK_ERR_ARG) snprintf(err, errlen, "invalid wave settings at time %g", time);
    return st;
}

int soak_bake_waves_main(int argc, char **argv)
{
    bake_opts o;
    bake_opts_init(&o, CMD, 0, 1.0 / 24);
    waves_job j;
    soak_waves_defaults(&j.p);
    const cli_spec spec = BAKE_SPEC(CMD, usage, NULL, NULL);
    const cli_opt_table tables[] = WAVES_TABLES(&o, &j);
    int rc = cli_opts_parse(&spec, tables, sizeof tables / sizeof tables[0], argc, argv);
    if (rc >= 0) return rc;
    if (j.p.reach_max < j.p.reach_min) {
        cli_error(CMD, "--reach-max (%g) must be >= --reach-min (%g)", j.p.reach_max, j.p.reach_min);
        return SOAK_EXIT_USAGE;
    }
    j.width = (int)o.width;
    j.height = (int)o.height;
    j.p.seed = o.seed;
    if ((rc = bake_opts_check(&o, NULL, 0)) != 0) return rc;
    return bake_run(&o, frame, &j);
}
