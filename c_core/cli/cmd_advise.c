/* soak advise: the cheapest model per material of a scene within a
 * tolerance (soak/advise.h). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "soak/advise.h"
#include "soak/scene.h"

static const char *CMD = "advise";

typedef struct advise_args {
    const char *scene_path;
    double tol;
    int all;
    soak_advise_options o;
} advise_args;

/* --grid WxH: both sides in [1, SOAK_ADVISE_MAX_GRID]. */
static int read_grid(const char *cmd, const cli_opt *opt, const char *text, void *dst)
{
    (void)opt;
    advise_args *a = dst;
    int w, h;
    char tail;
    if (sscanf(text, "%dx%d%c", &w, &h, &tail) != 2 || w < 1 || h < 1 || w > SOAK_ADVISE_MAX_GRID ||
        h > SOAK_ADVISE_MAX_GRID) {
        cli_error(cmd, "--grid: expected WxH with W, H in [1, %d], got '%s'", SOAK_ADVISE_MAX_GRID, text);
        return 0;
    }
    a->o.grid_w = w;
    a->o.grid_h = h;
    return 1;
}

#define F(field) CLI_FIELD(advise_args, field)
static const cli_opt advise_opts[] = {
    {"--tol", NULL, CLI_OPT_DOUBLE, .lo = CLI_ADVISE_MIN_TOL, .hi = SOAK_ADVISE_MAX_TOL, F(tol), .meta = "T",
     .help = "relative RMS error allowed, %R (0.02 = 2 %; required)"},
    {"--grid", NULL, CLI_OPT_CUSTOM, .parse = read_grid, .meta = "WxH", .help = "primary rays (default 32x24)"},
    {"--samples", NULL, CLI_OPT_INT, .ilo = SOAK_ADVISE_MIN_SAMPLES, .ihi = SOAK_ADVISE_MAX_SAMPLES, F(o.samples),
     .meta = "N", .help = "albedo samples per state and hit, %R (default 256)"},
    {"--seed", NULL, CLI_OPT_INT, .ilo = 0, .ihi = INT32_MAX, F(o.seed), .meta = "S", .help = "(default 1)"},
    {"--all", NULL, CLI_OPT_FLAG, .flag = 1, F(all),
     .help = "also every model's predicted error and cost per material"},
};
#undef F

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
            "options:\n");
    const cli_opt_table tables[] = {CLI_TABLE(advise_opts, NULL)};
    cli_opts_help(out, tables, 1);
    fprintf(out,
            "\noutput: one line per material: name, choice (or 'full'), predicted error,\n"
            "speed-up, visible hits, mean wetness and viewing cosine, note.\n\n"
            "example:\n"
            "  soak advise scenes/default_wet_dry.json --tol 0.02\n");
}

static int scene_arg(void *ctx, const char *arg)
{
    advise_args *a = ctx;
    if (a->scene_path) {
        cli_error(CMD, "unexpected argument '%s': only one scene file", arg);
        return 0;
    }
    a->scene_path = arg;
    return 1;
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

/* Returns -1 to go on, else the exit code. */
static int parse_args(int argc, char **argv, advise_args *a)
{
    memset(a, 0, sizeof *a);
    a->tol = -1;
    soak_advise_options_default(&a->o);
    const cli_spec spec = {CMD, "option", "soak advise --help", usage, scene_arg, a};
    const cli_opt_table tables[] = {CLI_TABLE(advise_opts, a)};
    int rc = cli_opts_parse(&spec, tables, 1, argc, argv);
    if (rc >= 0) return rc;
    if (!a->scene_path) {
        cli_error(CMD, "SCENE.json: missing scene file (see soak advise --help)");
        return SOAK_EXIT_USAGE;
    }
    if (a->tol < 0) {
        cli_error(CMD, "--tol: missing (the relative error allowed, e.g. --tol 0.02)");
        return SOAK_EXIT_USAGE;
    }
    return -1;
}

/* --all: every model tried, per material. */
static void print_tried(const soak_advice *adv, int n)
{
    printf("\n%-16s %-14s %9s %10s\n", "material", "model", "error", "shading ns");
    for (int i = 0; i < n; ++i) {
        printf("%-16s %-14s %9s %10.0f\n", adv[i].material, "full", "0", adv[i].full_ns);
        for (int k = 0; k < adv[i].n_tried; ++k)
            printf("%-16s %-14s %8.2f%% %10.0f\n", adv[i].material, adv[i].tried[k].model->name,
                   100 * adv[i].tried[k].error, adv[i].tried[k].ns);
    }
}

int soak_cmd_advise(int argc, char **argv)
{
    advise_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc >= 0) return rc;
    soak_scene scene;
    char err[4096] = "";
    if (soak_scene_load(a.scene_path, &scene, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "%s", err);
        return SOAK_EXIT_FAIL;
    }
    soak_advice *adv = NULL;
    int n = 0;
    err[0] = '\0';
    soak_status st = soak_advise_scene(&scene, a.tol, &a.o, &adv, &n, err, sizeof err);
    soak_scene_free(&scene);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    printf("# %s\n", a.scene_path);
    cli_advise_print(stdout, adv, n, a.tol);
    if (a.all) print_tried(adv, n);
    free(adv);
    return SOAK_EXIT_OK;
}
