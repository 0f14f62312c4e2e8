/* soak bake: dispatcher of the bake kinds. Each kind parses its own options
 * in bake_<kind>_cli.c; the maps themselves are computed by libsoak
 * (soak/bake.h, soak/bake_volume.h). */
#include <stdio.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"

static const soak_cli_command kinds[] = {
    {"turbulence", "fBm / turbulence noise wetness, thresholded or not, tileable, animated", soak_bake_turbulence_main},
    {"waves", "beach wetness left by the last waves along a shoreline", soak_bake_waves_main},
    {"drying", "a wet mask drying from its borders (pore schedule) or by evaporation + diffusion",
     soak_bake_drying_main},
    {"combine", "max / min / multiply / add / clamp / blur / remap of maps", soak_bake_combine_main},
    {"volume", "3D parameter volumes (sigma, phase) for subsurface scattering of wet materials",
     soak_bake_volume_main},
    {"rain", "rain wetting maps", soak_bake_rain_main},
    {"drops", "raindrop impacts wetting a surface over time, then drying (frame sequence)", soak_bake_drops_main},
    {"ripples", "rain rings on puddles: a tiling, looping normal-map flipbook", soak_bake_ripples_main},
    {"beads", "rain standing as beads by the contact angle: a normal + height map", soak_bake_beads_main},
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
    int rc = cli_dispatch_help(argc, argv, usage);
    if (rc >= 0) return rc;
    if (strcmp(argv[1], "--man") == 0) {
        cli_man_usage(stdout, "soak bake", usage);
        return cli_man_commands(kinds, n_kinds);
    }
    const soak_cli_command *kind = cli_find(kinds, n_kinds, argv[1]);
    if (kind) return kind->run(argc - 1, argv + 1);
    cli_error("bake", "unknown kind '%s' (expected turbulence, waves, drying, combine, volume, rain, drops, ripples or beads)", argv[1]);
    return SOAK_EXIT_USAGE;
}
