/* soak bake waves: beach wetness left by the last waves (seed 000 sec. 4.2). */
#include <stdio.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"

#define CMD "bake waves"

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake waves [options] -o OUT\n\n"
            "Wet sand left by the last N waves on a beach: bands behind turbulence-perturbed fronts,\n"
            "each drying with its age and its height up the beach, saturated below the water line.\n"
            "Lengths are in image widths from the image centre; times in any unit (default seconds).\n\n"
            "options:\n"
            "  -o, --output PATH       .exr (half; --float for 32-bit), .png/.tif (16-bit linear), .tx\n"
            "  --width N, --height N   image size, 1..16384 (default 1024)\n"
            "  --seed N                seed of the wave reaches and fronts (default 0)\n"
            "  --threads N             worker threads (default: every core)\n"
            "  --waves N               waves still visible, 1..64 (default 4, as in seed 000)\n"
            "  --direction DEG         inland direction, degrees from +x towards the image bottom (default 90)\n"
            "  --shore S               still-water line offset from the centre along it (default -0.2)\n"
            "  --reach-min R, --reach-max R  run-up beyond the water line (default 0.05 .. 0.3)\n"
            "  --period P              time between waves (default 8)\n"
            "  --dry-time T            e-folding time of a wave's water (default 20)\n"
            "  --dry-length L          e-folding distance inland of that water (default 0.5)\n"
            "  --fringe F              capillary fringe height above the water line (default 0.03)\n"
            "  --front-amplitude A     turbulence displacement of the fronts (default 0.04)\n"
            "  --front-frequency F     turbulence cells per width along the shore (default 3)\n"
            "  --front-octaves N       1..16 (default 4)\n"
            "  --edge E                soft edge width of each front, 0 = sharp (default 0.01)\n"
            "  --frames A-B            image sequence; -o must hold a pattern such as wet.%%04d.exr\n"
            "  --time T                time of frame F (default 0); wave j arrives at j*P\n"
            "  --frame-time DT         time between frames (default 1/24): frame f is at T + (f-F) DT\n"
            "  --frame-origin F        frame baked at time T (default A); give the sequence's first\n"
            "                          frame to bake it in chunks (--frames 11-20 ...) that equal one run\n\n"
            "example:\n"
            "  soak bake waves --waves 4 --direction 90 --shore 0.2 --seed 3 --width 2048 --height 1024 -o beach.exr\n");
}

typedef struct waves_job {
    soak_waves_params p;
    int width, height;
} waves_job;

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

typedef struct num_opt {
    const char *name;
    double lo, hi;
    double *dst;
} num_opt;

int soak_bake_waves_main(int argc, char **argv)
{
    bake_opts o;
    bake_opts_init(&o, CMD, 0, 1.0 / 24);
    waves_job j;
    soak_waves_defaults(&j.p);
    const num_opt nums[] = {
        {"--direction", -3600, 3600, &j.p.direction_deg}, {"--shore", -10, 10, &j.p.shore},
        {"--reach-min", 0, 10, &j.p.reach_min},           {"--reach-max", 0, 10, &j.p.reach_max},
        {"--period", 1e-6, 1e6, &j.p.period},             {"--dry-time", 1e-6, 1e9, &j.p.dry_time},
        {"--dry-length", 1e-6, 100, &j.p.dry_length},     {"--fringe", 1e-6, 100, &j.p.fringe},
        {"--front-amplitude", 0, 10, &j.p.front_amplitude}, {"--front-frequency", 1e-6, 4096, &j.p.front_frequency},
        {"--edge", 0, 10, &j.p.edge},
    };
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v;
        long n;
        int r = bake_opts_parse(&o, argc, argv, &i);
        if (r < 0) return SOAK_EXIT_USAGE;
        if (r > 0) continue;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            return SOAK_EXIT_OK;
        }
        if (cli_is(a, "--waves") || cli_is(a, "--front-octaves")) {
            int waves = cli_is(a, "--waves");
            const char *name = waves ? "--waves" : "--front-octaves";
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_int(CMD, name, v, 1, waves ? 64 : 16, &n))
                return SOAK_EXIT_USAGE;
            if (waves) j.p.waves = (int)n;
            else j.p.front_octaves = (int)n;
            continue;
        }
        int matched = 0;
        for (size_t k = 0; k < sizeof nums / sizeof nums[0] && !matched; ++k) {
            if (!cli_is(a, nums[k].name)) continue;
            matched = 1;
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_double(CMD, nums[k].name, v, nums[k].lo, nums[k].hi, nums[k].dst))
                return SOAK_EXIT_USAGE;
        }
        if (!matched) {
            cli_error(CMD, "unknown option '%s' (see --help)", a);
            return SOAK_EXIT_USAGE;
        }
    }
    if (j.p.reach_max < j.p.reach_min) {
        cli_error(CMD, "--reach-max (%g) must be >= --reach-min (%g)", j.p.reach_max, j.p.reach_min);
        return SOAK_EXIT_USAGE;
    }
    j.width = (int)o.width;
    j.height = (int)o.height;
    j.p.seed = o.seed;
    int rc = bake_opts_check(&o, NULL, 0);
    if (rc) return rc;
    return bake_run(&o, frame, &j);
}
