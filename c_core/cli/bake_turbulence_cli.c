/* soak bake turbulence: procedural wetness from fBm or turbulence noise. */
#include <stdio.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"

#define CMD "bake turbulence"

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake turbulence [options] -o OUT\n\n"
            "Gradient-noise wetness map (improved Perlin noise, seed 000's procedural wetness):\n"
            "fBm (signed, about [-1,1]) or turbulence (sum of |noise|, [0,1]), normalised by the\n"
            "sum of octave amplitudes; optionally thresholded to a wet/dry mask with a soft edge.\n\n"
            "options:\n"
            "  -o, --output PATH     .exr (half; --float for 32-bit), .png/.tif (16-bit linear), .tx\n"
            "  --width N, --height N image size, 1..16384 (default 1024)\n"
            "  --seed N              noise seed (default 0); same seed, same map on any thread count\n"
            "  --threads N           worker threads (default: every core)\n"
            "  --fbm | --turbulence  sum of noise (default) or of |noise|\n"
            "  --octaves N           1..24 (default 6)\n"
            "  --frequency F         noise cells across the width at octave 0 (default 4)\n"
            "  --lacunarity L        frequency ratio between octaves, 1..16 (default 2)\n"
            "  --gain G              amplitude ratio between octaves, 0..1 (default 0.5)\n"
            "  --tileable            periodic across the image edges (cell counts rounded per octave)\n"
            "  --threshold T         output smoothstep(T - S, T + S, value) instead of the value\n"
            "  --softness S          half width of that transition, 0 = hard edge (default 0.1)\n"
            "  --z Z                 slice of the 3D noise (switches to 3D noise)\n"
            "  --evolve R            3D noise moving R octave-0 cells per time unit (animation)\n"
            "  --frames A-B          image sequence; -o must hold a pattern such as wet.%%04d.exr\n"
            "  --time T              time of frame F (default 0)\n"
            "  --frame-time DT       time between frames (default 1/24): frame f is at T + (f-F) DT\n"
            "                        and slices the 3D noise at z = Z + R * time\n"
            "  --frame-origin F      frame baked at time T (default A); give the sequence's first\n"
            "                        frame to bake it in chunks (--frames 11-20 ...) that equal one run\n\n"
            "example:\n"
            "  soak bake turbulence --turbulence --octaves 6 --frequency 6 --threshold 0.25 --softness 0.05 \\\n"
            "       --width 2048 --height 2048 --seed 7 -o wet.exr\n");
}

typedef struct turb_job {
    soak_turbulence_params p;
    double z0, evolve;
    int width, height;
} turb_job;

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
    turb_job j;
    soak_turbulence_defaults(&j.p);
    j.z0 = 0;
    j.evolve = 0;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v;
        long n;
        int r = bake_opts_parse(&o, argc, argv, &i);
        if (r < 0) return SOAK_EXIT_USAGE;
        if (r > 0) continue;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            return SOAK_EXIT_OK;
        } else if (cli_is(a, "--fbm")) {
            j.p.sum = SOAK_NOISE_FBM;
        } else if (cli_is(a, "--turbulence")) {
            j.p.sum = SOAK_NOISE_TURBULENCE;
        } else if (cli_is(a, "--tileable")) {
            j.p.tileable = 1;
        } else if (cli_is(a, "--octaves")) {
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_int(CMD, "--octaves", v, 1, 24, &n))
                return SOAK_EXIT_USAGE;
            j.p.octaves = (int)n;
        } else if (cli_is(a, "--frequency")) {
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_double(CMD, "--frequency", v, 1e-6, 8192, &j.p.frequency))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--lacunarity")) {
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_double(CMD, "--lacunarity", v, 1, 16, &j.p.lacunarity))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--gain")) {
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_double(CMD, "--gain", v, 0, 1, &j.p.gain))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--threshold")) {
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_double(CMD, "--threshold", v, -2, 2, &j.p.threshold))
                return SOAK_EXIT_USAGE;
            j.p.thresholded = 1;
        } else if (cli_is(a, "--softness")) {
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_double(CMD, "--softness", v, 0, 2, &j.p.softness))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--z")) {
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_double(CMD, "--z", v, -1e6, 1e6, &j.z0))
                return SOAK_EXIT_USAGE;
            j.p.use_3d = 1;
        } else if (cli_is(a, "--evolve")) {
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_double(CMD, "--evolve", v, -1e6, 1e6, &j.evolve))
                return SOAK_EXIT_USAGE;
            j.p.use_3d = 1;
        } else {
            cli_error(CMD, "unknown option '%s' (see --help)", a);
            return SOAK_EXIT_USAGE;
        }
    }
    j.width = (int)o.width;
    j.height = (int)o.height;
    j.p.seed = o.seed;
    j.p.z = j.z0;
    if (soak_turbulence_check(&j.p) != SOAK_OK) {
        cli_error(CMD, "frequency * lacunarity^(octaves-1) must be <= 20000 (finer than any pixel)");
        return SOAK_EXIT_USAGE;
    }
    int rc = bake_opts_check(&o, NULL, 0);
    if (rc) return rc;
    return bake_run(&o, frame, &j);
}
