/* soak bake: dispatcher of the bake kinds. Each kind parses its own options
 * in bake_<kind>_cli.c; the maps themselves are computed by libsoak
 * (soak/bake.h, soak/bake_volume.h). */
#include <stdio.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"

typedef struct bake_kind {
    const char *name;
    const char *summary;
    int (*run)(int argc, char **argv);
} bake_kind;

static const bake_kind kinds[] = {
    {"turbulence", "fBm / turbulence noise wetness, thresholded or not, tileable, animated", soak_bake_turbulence_main},
    {"waves", "beach wetness left by the last waves along a shoreline", soak_bake_waves_main},
    {"drying", "a wet mask drying from its borders (pore schedule) or by evaporation + diffusion",
     soak_bake_drying_main},
    {"combine", "max / min / multiply / add / clamp / blur / remap of maps", soak_bake_combine_main},
    {"volume", "3D parameter volumes (sigma, phase) for subsurface scattering of wet materials",
     soak_bake_volume_main},
    {"rain", "rain wetting maps", soak_bake_rain_main},
};
static const int n_kinds = (int)(sizeof kinds / sizeof kinds[0]);

static void usage(FILE *out)
{
    fprintf(out, "usage: soak bake <kind> [options] -o OUT\n"
                 "       soak bake <kind> --help\n\n"
                 "Bakes wet maps (2D) and parameter volumes (3D). 2D maps: same seed, same bytes, on any\n"
                 "number of threads. Outputs are written atomically; an input is never overwritten.\n\n"
                 "kinds:\n");
    for (int i = 0; i < n_kinds; ++i) fprintf(out, "  %-11s %s\n", kinds[i].name, kinds[i].summary);
    fprintf(out, "\nexample:\n"
                 "  soak bake turbulence --octaves 6 --threshold 0.1 --softness 0.05 -o wet.exr\n"
                 "  soak bake drying splash.png --frames 1-120 -o dry.%%04d.exr\n");
}

int soak_cmd_bake(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return SOAK_EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return SOAK_EXIT_OK;
    }
    for (int i = 0; i < n_kinds; ++i)
        if (strcmp(argv[1], kinds[i].name) == 0) return kinds[i].run(argc - 1, argv + 1);
    cli_error("bake", "unknown kind '%s' (expected turbulence, waves, drying, combine, volume or rain)", argv[1]);
    return SOAK_EXIT_USAGE;
}
