/* soak report: the options; the measurement and the writers are the
 * library's (soak/report.h). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "soak/accuracy.h"
#include "soak/models.h"
#include "soak/preset.h"
#include "soak/report.h"
#include "soak/staged.h"

static const char *CMD = "report";

/* The report's own ranges, narrower than soak_material_albedo's 1..1e8
 * samples. */
#define REPORT_MIN_SAMPLES 16
#define REPORT_MAX_SAMPLES 10000000
#define REPORT_MAX_EVALS 1000000000

typedef struct report_args {
    const char *markdown, *json, *callgrind, *model, *material;
    long samples, evals;
    unsigned long long seed;
    int quick, no_cost, cost_only;
} report_args;

#define F(field) CLI_FIELD(report_args, field)
static const cli_opt report_opts[] = {
    {"--markdown", NULL, CLI_OPT_STRING, F(markdown), .meta = "PATH", .help = "tables (default docs/ACCURACY.md)"},
    {"--json", NULL, CLI_OPT_STRING, F(json), .meta = "PATH", .help = "values (default docs/accuracy/report.json)"},
    {"--samples", NULL, CLI_OPT_INT, .ilo = REPORT_MIN_SAMPLES, .ihi = REPORT_MAX_SAMPLES, F(samples),
     .meta = "N", .help = "Monte Carlo samples per state and cell, %R (default 2048)"},
    {"--seed", NULL, CLI_OPT_INT, .ilo = 0, .ihi = INT32_MAX, F(seed), .meta = "S",
     .help = "base seed (default 1); each cell's seed derives from it"},
    {"--quick", NULL, CLI_OPT_FLAG, .flag = 1, F(quick),
     .help = "subset: presets sand, marble, copper; water; 0 and 60 degrees\n"
             "(the same values as the full grid's cells)"},
    {"--no-cost", NULL, CLI_OPT_FLAG, .flag = 1, F(no_cost), .help = "leave the timings out (zeros)"},
    {"--callgrind", NULL, CLI_OPT_STRING, F(callgrind), .meta = "PATH",
     .help = "instruction counts per evaluation (TSV: model, Ir) from\n"
             "scripts/accuracy_report.sh, shown beside the timings"},
    {"--cost-only", NULL, CLI_OPT_FLAG, .flag = 1, F(cost_only),
     .help = "run --evals evaluations of --model on --material's wet\n"
             "state and print a checksum (for valgrind --tool=callgrind)"},
    {"--model", NULL, CLI_OPT_STRING, F(model), .meta = "NAME",
     .help = "(--cost-only) a model of `soak eval --list`, or full"},
    {"--material", NULL, CLI_OPT_STRING, F(material), .meta = "NAME", .help = "(--cost-only) preset (default sand)"},
    {"--evals", NULL, CLI_OPT_INT, .ilo = 0, .ihi = REPORT_MAX_EVALS, F(evals), .meta = "N",
     .help = "(--cost-only) evaluations, %R (default 100000)"},
};
#undef F

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak report [options]\n\n"
            "Error against the full material and cost of every model and fast path of\n"
            "`soak eval --list`, on a fixed grid: each preset (thin sheets excepted: their\n"
            "full description is a traced medium) x wetness {0, pore saturation, 1} x\n"
            "incidence {0, 30, 60, 80} degrees x liquid {water, red_wine}. The measure is\n"
            "the directional albedo as the renderer shades the material (Monte Carlo with\n"
            "the renderer's own BSDF sampling, fixed seeds: reproducible). Writes the\n"
            "tables (Markdown) and the values (JSON) together, or neither.\n\n"
            "options:\n");
    const cli_opt_table tables[] = {CLI_TABLE(report_opts, NULL)};
    cli_opts_help(out, tables, 1);
    fprintf(out, "\nexamples:\n"
                 "  soak report\n"
                 "  soak report --quick --json /tmp/quick.json --markdown /tmp/quick.md\n"
                 "  scripts/accuracy_report.sh build/c_core/soak   # + callgrind and plots\n");
}

/* Returns -1 to go on, else the exit code. */
static int parse_args(int argc, char **argv, report_args *a)
{
    *a = (report_args){.markdown = "docs/ACCURACY.md", .json = "docs/accuracy/report.json", .samples = 2048,
                       .seed = 1, .evals = 100000, .material = "sand"};
    const cli_spec spec = {CMD, "option", "'soak report --help'", usage, NULL, NULL};
    const cli_opt_table tables[] = {CLI_TABLE(report_opts, a)};
    int rc = cli_opts_parse(&spec, tables, 1, argc, argv);
    if (rc >= 0) return rc;
    if (a->cost_only && !a->model) {
        cli_error(CMD, "--cost-only needs --model NAME (a model of `soak eval --list`, or full)");
        return SOAK_EXIT_USAGE;
    }
    if (a->model && !a->cost_only) {
        cli_error(CMD, "--model is for --cost-only");
        return SOAK_EXIT_USAGE;
    }
    if (a->model && strcmp(a->model, "full") != 0 && !soak_model_find(a->model)) {
        cli_error(CMD, "--model: no model named '%s' (see `soak eval --list`)", a->model);
        return SOAK_EXIT_USAGE;
    }
    return -1;
}

static int cost_only(const report_args *a)
{
    soak_scene scene;
    char err[1024];
    if (soak_accuracy_preset_scene(a->material, "water", 1.0, &scene, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "--material '%s': %s", a->material, err[0] ? err : "not a preset name");
        return SOAK_EXIT_USAGE;
    }
    int rc = SOAK_EXIT_OK;
    double sum = 0;
    if (strcmp(a->model, "full") != 0 && soak_scene_set_model(&scene, "m", a->model, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "--model '%s' on --material '%s': %s", a->model, a->material, err);
        rc = SOAK_EXIT_FAIL;
    } else if (soak_material_eval_loop(&scene.materials[0], a->evals, &sum) != SOAK_OK) {
        cli_error(CMD, "--model '%s' on --material '%s': no closed-form eval (traced film)", a->model, a->material);
        rc = SOAK_EXIT_FAIL;
    } else {
        printf("%s %s %ld evals checksum %.6g\n", a->model, a->material, a->evals, sum);
    }
    soak_scene_free(&scene);
    return rc;
}

/* Measures every cell with progress; the exit code. */
static int run_report(const report_args *a, soak_report *r)
{
    char err[1024];
    int n = soak_report_cell_count(r);
    cli_progress prog;
    cli_progress_start(&prog, "report", n);
    for (int ci = 0; ci < n; ++ci) {
        if (soak_report_run_cell(r, ci, err, sizeof err) != SOAK_OK) {
            cli_error(CMD, "%s", err);
            return SOAK_EXIT_FAIL;
        }
        cli_progress_update(&prog, ci + 1);
    }
    cli_progress_finish(&prog);
    if (!a->no_cost) soak_report_measure_costs(r);
    if (a->callgrind) soak_report_read_callgrind(r, a->callgrind);
    if (soak_report_write(r, a->json, a->markdown, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "%s", err);
        return SOAK_EXIT_FAIL;
    }
    printf("%d cells x %d models: %s, %s\n", n, soak_report_model_count(r), a->json, a->markdown);
    return SOAK_EXIT_OK;
}

int soak_cmd_report(int argc, char **argv)
{
    report_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc >= 0) return rc;
    if (a.cost_only) return cost_only(&a);
    char err[1024];
    if (soak_output_path_check(a.json, err, sizeof err) != SOAK_OK || soak_output_path_check(a.markdown, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "%s", err);
        return SOAK_EXIT_USAGE;
    }
    soak_preset_db *db = NULL;
    if (soak_presets_load(NULL, &db, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "%s", err);
        return SOAK_EXIT_FAIL;
    }
    const soak_report_settings settings = {a.samples, a.seed, a.quick};
    soak_report *r = NULL;
    if (soak_report_create(db, &settings, &r) != SOAK_OK) {
        cli_error(CMD, "out of memory");
        rc = SOAK_EXIT_FAIL;
    } else {
        rc = run_report(&a, r);
    }
    soak_report_free(r);
    soak_presets_free(db);
    return rc;
}
