/* soak advise: the cheapest model per material of a scene within a
 * tolerance (soak/advise.h). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "soak/advise.h"
#include "soak/scene.h"

static const char *CMD = "advise";

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak advise SCENE.json --tol T [options]\n\n"
            "For each material of the scene, the cheapest model of `soak eval --list` whose\n"
            "error against the material's full description stays under T at the angles and\n"
            "wetness the camera sees (primary rays on a grid; directional albedo by Monte\n"
            "Carlo with the renderer's BSDFs; error = relative RMS over the visible hits,\n"
            "the Monte Carlo noise subtracted). Prints the choice, the predicted error and\n"
            "the speed-up of one shading (eval + sample). `soak render --auto-model T`\n"
            "renders with these choices. Kept: dielectrics, emitters, subsurface media (no\n"
            "model renders them) and materials the camera does not see.\n\n"
            "options:\n"
            "  --tol T             relative RMS error allowed, (0, 10] (0.02 = 2 %%; required)\n"
            "  --grid WxH          primary rays (default 32x24)\n"
            "  --samples N         albedo samples per state and hit, [16, 1e6] (default 256)\n"
            "  --seed S            (default 1)\n"
            "  --all               also every model's predicted error and cost per material\n\n"
            "output: one line per material: name, choice (or 'full'), predicted error,\n"
            "speed-up, visible hits, mean wetness and viewing cosine, note.\n\n"
            "example:\n"
            "  soak advise scenes/default_wet_dry.json --tol 0.02\n");
}

void cli_advise_print(FILE *f, const soak_advice *a, int n, double tol)
{
    fprintf(f, "# tolerance %.4g (relative RMS)\n", tol);
    fprintf(f, "%-16s %-14s %9s %8s %6s %7s %6s  %s\n", "material", "model", "error", "speedup", "hits", "wetness",
            "cos", "note");
    for (int i = 0; i < n; ++i) {
        double speed = a[i].model && a[i].model_ns > 0 ? a[i].full_ns / a[i].model_ns : 1.0;
        fprintf(f, "%-16s %-14s %8.2f%% %7.2fx %6d %7.2f %6.2f  %s\n", a[i].material,
                a[i].model ? a[i].model->name : "full", 100 * a[i].error, isfinite(speed) ? speed : 1.0, a[i].hits,
                a[i].mean_wetness, a[i].mean_cos, a[i].note);
    }
}

int soak_cmd_advise(int argc, char **argv)
{
    const char *scene_path = NULL;
    double tol = -1;
    int all = 0;
    soak_advise_options o;
    soak_advise_options_default(&o);
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v;
        long n;
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            usage(stdout);
            return SOAK_EXIT_OK;
        } else if (strcmp(a, "--all") == 0) {
            all = 1;
        } else if (cli_is(a, "--tol")) {
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_double(CMD, "--tol", v, 1e-9, 10, &tol))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--samples")) {
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_int(CMD, "--samples", v, 16, 1000000, &n))
                return SOAK_EXIT_USAGE;
            o.samples = (int)n;
        } else if (cli_is(a, "--seed")) {
            if (!(v = cli_value(CMD, argc, argv, &i)) || !cli_parse_int(CMD, "--seed", v, 0, 2147483647L, &n))
                return SOAK_EXIT_USAGE;
            o.seed = (uint64_t)n;
        } else if (cli_is(a, "--grid")) {
            int w, h;
            char tail;
            if (!(v = cli_value(CMD, argc, argv, &i))) return SOAK_EXIT_USAGE;
            if (sscanf(v, "%dx%d%c", &w, &h, &tail) != 2 || w < 1 || h < 1 || w > 1024 || h > 1024) {
                cli_error(CMD, "--grid: expected WxH with W, H in [1, 1024], got '%s'", v);
                return SOAK_EXIT_USAGE;
            }
            o.grid_w = w;
            o.grid_h = h;
        } else if (a[0] == '-' && a[1] != '\0') {
            cli_error(CMD, "unknown option '%s' (see soak advise --help)", a);
            return SOAK_EXIT_USAGE;
        } else if (!scene_path) {
            scene_path = a;
        } else {
            cli_error(CMD, "unexpected argument '%s': only one scene file", a);
            return SOAK_EXIT_USAGE;
        }
    }
    if (!scene_path) {
        cli_error(CMD, "SCENE.json: missing scene file (see soak advise --help)");
        return SOAK_EXIT_USAGE;
    }
    if (tol < 0) {
        cli_error(CMD, "--tol: missing (the relative error allowed, e.g. --tol 0.02)");
        return SOAK_EXIT_USAGE;
    }
    soak_scene scene;
    char err[4096];
    if (soak_scene_load(scene_path, &scene, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "%s", err);
        return SOAK_EXIT_FAIL;
    }
    soak_advice *adv = NULL;
    int n = 0;
    err[0] = '\0';
    soak_status st = soak_advise_scene(&scene, tol, &o, &adv, &n, err, sizeof err);
    soak_scene_free(&scene);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    printf("# %s\n", scene_path);
    cli_advise_print(stdout, adv, n, tol);
    if (all) {
        printf("\n%-16s %-14s %9s %10s\n", "material", "model", "error", "shading ns");
        for (int i = 0; i < n; ++i) {
            printf("%-16s %-14s %9s %10.0f\n", adv[i].material, "full", "0", adv[i].full_ns);
            for (int k = 0; k < adv[i].n_tried; ++k)
                printf("%-16s %-14s %8.2f%% %10.0f\n", adv[i].material, adv[i].tried[k].model->name,
                       100 * adv[i].tried[k].error, adv[i].tried[k].ns);
        }
    }
    free(adv);
    return SOAK_EXIT_OK;
}
