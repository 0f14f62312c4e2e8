/* soak report: every model of soak_models() against the full description of
 * each preset on a fixed grid (soak/accuracy.h), and what each costs;
 * writes docs/ACCURACY.md and docs/accuracy/report.json. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "soak/accuracy.h"
#include "soak/hash.h"
#include "soak/models.h"
#include "soak/preset.h"
#include "soak/staged.h"

static const char *CMD = "report";

#define MAX_MODELS 32
#define MAX_PRESETS 64
#define N_ANGLES 4
static const double ANGLES[N_ANGLES] = {0, 30, 60, 80};
static const char *const LIQUIDS[] = {"water", "red_wine"};
#define N_LIQUIDS 2
static const char *const QUICK_PRESETS[] = {"sand", "marble", "copper"};
#define N_QUICK 3
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

/* ---- The grid ---- */
typedef struct cell {
    const soak_preset *preset;
    int liquid;
    double wetness, angle_deg;
    int state; /* 0 dry, 1 saturation, 2 soaked: for the wet/dry ratio */
} cell;

typedef struct model_result {
    int valid;
    soak_albedo_estimate est;
} model_result;

typedef struct report {
    const soak_model *models[MAX_MODELS]; /* [0] = NULL: the full material */
    int n_models;
    cell *cells;
    int n_cells;
    model_result *res; /* n_cells x n_models */
    double eval_ns[MAX_MODELS], sample_ns[MAX_MODELS], ir[MAX_MODELS];
    int have_ir;
    const char *skipped[MAX_PRESETS];
    int n_skipped;
} report;

static const char *model_name(const report *r, int k) { return k == 0 ? "full" : r->models[k]->name; }

static int in_quick(const char *name)
{
    for (int i = 0; i < N_QUICK; ++i)
        if (strcmp(name, QUICK_PRESETS[i]) == 0) return 1;
    return 0;
}

static int build_grid(const soak_preset_db *db, int quick, report *r)
{
    int n = soak_presets_count(db);
    r->cells = calloc((size_t)n * 3 * N_ANGLES * N_LIQUIDS, sizeof *r->cells);
    if (!r->cells) return 0;
    for (int i = 0; i < n; ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        if (p->kind == SOAK_KIND_THIN_SHEET) {
            if (r->n_skipped < MAX_PRESETS) r->skipped[r->n_skipped++] = p->name;
            continue;
        }
        if (quick && !in_quick(p->name)) continue;
        double sat = soak_material_kind_porous(p->kind) ? p->porosity : 0.0;
        double wet[3] = {0, sat, 1};
        for (int l = 0; l < (quick ? 1 : N_LIQUIDS); ++l)
            for (int s = 0; s < 3; ++s) {
                if (s == 1 && !(sat > 0 && sat < 1)) continue;
                for (int a = 0; a < N_ANGLES; ++a) {
                    if (quick && !(a == 0 || a == 2)) continue;
                    cell *c = &r->cells[r->n_cells++];
                    c->preset = p;
                    c->liquid = l;
                    c->wetness = wet[s];
                    c->angle_deg = ANGLES[a];
                    c->state = s;
                }
            }
    }
    return 1;
}

/* Each cell's seed depends on what the cell is, not on its place in the
 * grid: --quick gives the same numbers as the full grid's cells. */
static uint64_t cell_seed(uint64_t base, const cell *c, const char *model)
{
    uint32_t h = soak_seed_key(base);
    for (const char *s = c->preset->name; *s; ++s) h = soak_mix32(h + (uint32_t)*s);
    for (const char *s = LIQUIDS[c->liquid]; *s; ++s) h = soak_mix32(h + (uint32_t)*s);
    for (const char *s = model; *s; ++s) h = soak_mix32(h + (uint32_t)*s);
    h = soak_hash_key2(h, (int32_t)lround(c->wetness * 1e6), (int32_t)lround(c->angle_deg * 1e3));
    return h;
}

static int run_cell(const report_args *a, report *r, int ci)
{
    const cell *c = &r->cells[ci];
    soak_scene scene;
    char err[1024];
    if (soak_accuracy_preset_scene(c->preset->name, LIQUIDS[c->liquid], c->wetness, &scene, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "preset '%s': %s", c->preset->name, err);
        return 0;
    }
    soak_material full = scene.materials[0];
    double cos_o = cos(c->angle_deg * SOAK_PI / 180.0);
    if (cos_o < 1e-6) cos_o = 1e-6;
    for (int k = 0; k < r->n_models; ++k) {
        model_result *mr = &r->res[(size_t)ci * r->n_models + k];
        scene.materials[0] = full;
        if (k > 0 && soak_scene_set_model(&scene, "m", r->models[k]->name, err, sizeof err) != SOAK_OK) continue;
        soak_status st = soak_material_albedo(&scene.materials[0], 1.0, cos_o, (int)a->samples,
                                              cell_seed(a->seed, c, model_name(r, k)), 0, &mr->est);
        mr->valid = st == SOAK_OK;
    }
    scene.materials[0] = full;
    soak_scene_free(&scene);
    return 1;
}

static double median(double *v, int n)
{
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && v[j - 1] > v[j]; --j) {
            double t = v[j];
            v[j] = v[j - 1];
            v[j - 1] = t;
        }
    return n == 0 ? 0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

/* Median over the grid's presets (wet state, water) of each model's cost. */
static void measure_costs(const report *r, report *out)
{
    double ev[MAX_PRESETS], sa[MAX_PRESETS];
    for (int k = 0; k < r->n_models; ++k) {
        int n = 0;
        const soak_preset *last = NULL;
        for (int ci = 0; ci < r->n_cells && n < MAX_PRESETS; ++ci) {
            const cell *c = &r->cells[ci];
            if (c->preset == last || c->liquid != 0 || c->state != 2) continue;
            last = c->preset;
            soak_scene scene;
            char err[512];
            if (soak_accuracy_preset_scene(c->preset->name, "water", 1.0, &scene, err, sizeof err) != SOAK_OK) continue;
            if (k == 0 || soak_scene_set_model(&scene, "m", r->models[k]->name, err, sizeof err) == SOAK_OK) {
                if (soak_material_cost(&scene.materials[0], 100, &ev[n], &sa[n]) == SOAK_OK) ++n;
            }
            soak_scene_free(&scene);
        }
        int m = 0; /* the traced films' zeros left out */
        for (int i = 0; i < n; ++i)
            if (ev[i] > 0) ev[m++] = ev[i];
        out->eval_ns[k] = median(ev, m);
        out->sample_ns[k] = median(sa, n);
    }
}

static void read_callgrind(const char *path, report *r)
{
    FILE *f = fopen(path, "r");
    if (!f) return;
    char name[128];
    double ir;
    while (fscanf(f, "%127s %lf", name, &ir) == 2)
        for (int k = 0; k < r->n_models; ++k)
            if (strcmp(model_name(r, k), name) == 0) {
                r->ir[k] = ir;
                r->have_ir = 1;
            }
    fclose(f);
}

/* ---- Error statistics ---- */
typedef struct model_stats {
    int cells, na;
    double mean_rel, worst_rel, mean_abs, worst_abs, mean_ratio, worst_ratio, mean_se;
    int ratio_cells, worst_cell;
} model_stats;

static double lum(soak_rgb c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

/* The dry cell (state 0) of the same preset, liquid and angle. */
static int dry_of(const report *r, int ci)
{
    const cell *c = &r->cells[ci];
    for (int j = 0; j < r->n_cells; ++j) {
        const cell *d = &r->cells[j];
        if (d->preset == c->preset && d->liquid == c->liquid && d->angle_deg == c->angle_deg && d->state == 0) return j;
    }
    return -1;
}

/* Errors of model k against model ref (0: the full material). */
static model_stats stats_vs(const report *r, int k, int ref_k)
{
    model_stats s;
    memset(&s, 0, sizeof s);
    s.worst_cell = -1;
    for (int ci = 0; ci < r->n_cells; ++ci) {
        const model_result *row = &r->res[(size_t)ci * r->n_models], *ref = row + ref_k, *m = row + k;
        if (!ref->valid || !m->valid) {
            s.na++;
            continue;
        }
        double worst_abs = 0, worst_rel = 0;
        for (int ch = 0; ch < 3; ++ch) {
            double d = fabs(soak_rgb_at(m->est.value, ch) - soak_rgb_at(ref->est.value, ch));
            worst_abs = fmax(worst_abs, d);
            worst_rel = fmax(worst_rel, d / fmax(soak_rgb_at(ref->est.value, ch), 0.01));
            s.mean_se += soak_rgb_at(m->est.std_error, ch) / 3;
        }
        s.cells++;
        s.mean_abs += worst_abs;
        s.mean_rel += worst_rel;
        s.worst_abs = fmax(s.worst_abs, worst_abs);
        if (worst_rel > s.worst_rel) {
            s.worst_rel = worst_rel;
            s.worst_cell = ci;
        }
        int dj = r->cells[ci].state ? dry_of(r, ci) : -1;
        const model_result *drow = dj >= 0 ? &r->res[(size_t)dj * r->n_models] : NULL;
        if (drow && drow[ref_k].valid && drow[k].valid && lum(drow[k].est.value) > 0 && lum(drow[ref_k].est.value) > 0) {
            double e = fabs(lum(m->est.value) / lum(drow[k].est.value) - lum(ref->est.value) / lum(drow[ref_k].est.value));
            s.ratio_cells++;
            s.mean_ratio += e;
            s.worst_ratio = fmax(s.worst_ratio, e);
        }
    }
    if (s.cells) {
        s.mean_abs /= s.cells;
        s.mean_rel /= s.cells;
        s.mean_se /= s.cells;
    }
    if (s.ratio_cells) s.mean_ratio /= s.ratio_cells;
    return s;
}

static model_stats stats_of(const report *r, int k) { return stats_vs(r, k, 0); }

/* Index of a fast path's exact peer, or -1. */
static int exact_of(const report *r, int k)
{
    if (k == 0 || !r->models[k]->exact) return -1;
    for (int j = 1; j < r->n_models; ++j)
        if (strcmp(r->models[j]->name, r->models[k]->exact) == 0) return j;
    return -1;
}

/* ---- Outputs ---- */
static void write_json(FILE *f, const report_args *a, const report *r)
{
    fprintf(f, "{\n  \"format\": \"soak-accuracy\",\n  \"version\": 1,\n");
    fprintf(f, "  \"settings\": {\"samples\": %ld, \"seed\": %llu, \"quick\": %d, \"angles_deg\": [0, 30, 60, 80], "
               "\"liquids\": [\"water\", \"red_wine\"], \"measure\": \"directional albedo, renderer's BSDF sampling\"},\n",
            a->samples, a->seed, a->quick);
    fprintf(f, "  \"models\": [\n");
    for (int k = 0; k < r->n_models; ++k) {
        model_stats s = stats_of(r, k);
        const char *exact = k > 0 && r->models[k]->exact ? r->models[k]->exact : "";
        fprintf(f,
                "    {\"name\": \"%s\", \"exact\": \"%s\", \"cells\": %d, \"not_applicable\": %d, "
                "\"mean_rel_error\": %.6f, \"worst_rel_error\": %.6f, \"mean_abs_error\": %.6f, \"worst_abs_error\": %.6f, "
                "\"mean_ratio_error\": %.6f, \"worst_ratio_error\": %.6f, \"mean_std_error\": %.6f, "
                "\"eval_ns\": %.1f, \"sample_ns\": %.1f, \"callgrind_ir_per_eval\": %.0f}%s\n",
                model_name(r, k), exact, s.cells, s.na, s.mean_rel, s.worst_rel, s.mean_abs, s.worst_abs, s.mean_ratio,
                s.worst_ratio, s.mean_se, r->eval_ns[k], r->sample_ns[k], r->ir[k], k + 1 < r->n_models ? "," : "");
    }
    fprintf(f, "  ],\n  \"fast_paths\": [\n");
    int first_fp = 1;
    for (int k = 1; k < r->n_models; ++k) {
        int j = exact_of(r, k);
        if (j < 0) continue;
        model_stats s = stats_vs(r, k, j);
        fprintf(f, "%s    {\"name\": \"%s\", \"exact\": \"%s\", \"cells\": %d, \"mean_rel_error\": %.6f, \"worst_rel_error\": %.6f, "
                   "\"mean_ratio_error\": %.6f, \"worst_ratio_error\": %.6f, \"speedup_eval\": %.3f}",
                first_fp ? "" : ",\n", model_name(r, k), model_name(r, j), s.cells, s.mean_rel, s.worst_rel, s.mean_ratio,
                s.worst_ratio, r->eval_ns[k] > 0 ? r->eval_ns[j] / r->eval_ns[k] : 0.0);
        first_fp = 0;
    }
    fprintf(f, "\n  ],\n  \"cells\": [\n");
    int first = 1;
    for (int ci = 0; ci < r->n_cells; ++ci)
        for (int k = 0; k < r->n_models; ++k) {
            const cell *c = &r->cells[ci];
            const model_result *m = &r->res[(size_t)ci * r->n_models + k];
            if (!m->valid) continue;
            fprintf(f,
                    "%s    {\"preset\": \"%s\", \"liquid\": \"%s\", \"wetness\": %.6g, \"angle_deg\": %g, \"model\": \"%s\", "
                    "\"albedo\": [%.6f, %.6f, %.6f], \"std_error\": [%.6f, %.6f, %.6f]}",
                    first ? "" : ",\n", c->preset->name, LIQUIDS[c->liquid], c->wetness, c->angle_deg, model_name(r, k),
                    m->est.value.r, m->est.value.g, m->est.value.b, m->est.std_error.r, m->est.std_error.g,
                    m->est.std_error.b);
            first = 0;
        }
    fprintf(f, "\n  ]\n}\n");
}

/* Title and what the numbers are. */
static void md_intro(FILE *f, const report_args *a)
{
    fprintf(f,
            "# Accuracy and cost of Soak's models\n\n"
            "Generated by `soak report%s` (scripts/accuracy_report.sh adds the callgrind\n"
            "column and the plots); do not edit by hand. Values: `docs/accuracy/report.json`;\n"
            "`tests/cli/report.sh` fails when they are stale.\n\n",
            a->quick ? " --quick" : "");
    fprintf(f,
            "## What is measured\n\n"
            "For each preset of `soak materials` (thin sheets excepted), wetness {0, pore\n"
            "saturation (= porosity, porous kinds only), 1}, incidence {0, 30, 60, 80} deg and\n"
            "liquid {water, red_wine}, the preset is loaded as `soak render` loads a\n"
            "`{\"type\": \"preset\"}` material. The **full** material is what the tracer renders for\n"
            "it (the chain's subsurface albedo as a Lambert base under the liquid's film over\n"
            "the chain's interface area; conductors: GGX under the film, traced through the\n"
            "film). Each model of `soak eval --list` renders the same material through\n"
            "`soak_scene_set_model` (its own dry/wet states from the preset's model parameters).\n"
            "The quantity is the directional albedo R(theta_o) (RGB, delta lobes included) of\n"
            "the BSDFs the renderer sets up, by Monte Carlo with the renderer's own sampling,\n"
            "%ld samples per state and cell, fixed seeds (reproducible). Under uniform light the\n"
            "radiance is proportional to R, so a relative error in R is the relative radiance\n"
            "error of that material in an image.\n\n"
            "- *rel.*: per cell the largest channel error |R_model - R_full| / max(R_full, 0.01);\n"
            "  mean and worst over the cells where the model accepts the material.\n"
            "- *abs.*: the same without the division (albedo units).\n"
            "- *wet/dry*: |ratio_model - ratio_full| of the luminance ratio R(w)/R(0) at the\n"
            "  same angle and liquid (cells with w > 0).\n"
            "- *MC noise*: the mean standard error of a model's R (the floor of every error).\n"
            "- *cost*: `soak_bsdf_eval_cost_ns` (one RGB eval with pdf, CPU time, median over\n"
            "  the presets' wet state) and one `soak_bsdf_sample_dir` (for a traced film: one\n"
            "  whole walk through it); *Ir/eval*: valgrind callgrind instructions per eval\n"
            "  (scripts/accuracy_report.sh). Timings are from one machine; never asserted.\n\n",
            a->samples);
}

/* Every model against the full material. */
static void md_models(FILE *f, const report *r)
{
    fprintf(f, "## Models\n\n![error vs cost](accuracy/pareto.png)\n\n");
    fprintf(f, "| model | fast path of | cells (n/a) | rel. mean | rel. worst | abs. mean | abs. worst | wet/dry mean | "
               "wet/dry worst | MC noise | eval ns | sample ns | Ir/eval | worst cell |\n");
    fprintf(f, "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < r->n_models; ++k) {
        model_stats s = stats_of(r, k);
        char worst[160] = "";
        if (s.worst_cell >= 0) {
            const cell *c = &r->cells[s.worst_cell];
            snprintf(worst, sizeof worst, "%s w=%.2g %s %g deg", c->preset->name, c->wetness, LIQUIDS[c->liquid],
                     c->angle_deg);
        }
        char ir[32] = "-";
        if (r->ir[k] > 0) snprintf(ir, sizeof ir, "%.0f", r->ir[k]);
        fprintf(f, "| %s | %s | %d (%d) | %.1f %% | %.1f %% | %.4f | %.4f | %.3f | %.3f | %.4f | %.0f | %.0f | %s | %s |\n",
                model_name(r, k), k > 0 && r->models[k]->exact ? r->models[k]->exact : "", s.cells, s.na,
                100 * s.mean_rel, 100 * s.worst_rel, s.mean_abs, s.worst_abs, s.mean_ratio, s.worst_ratio, s.mean_se,
                r->eval_ns[k], r->sample_ns[k], ir, worst);
    }
    fprintf(f, "\nA model is *n/a* on a cell when its set-up rejects the preset's parameters\n"
               "(e.g. `ggx-conductor` on a dielectric) or the material has no model view.\n\n");
}

static void md_fast_paths(FILE *f, const report *r)
{
    fprintf(f, "## Fast paths against their exact model\n\n| fast path | exact | cells | rel. mean | rel. worst | "
               "wet/dry mean | wet/dry worst | eval speed-up |\n|---|---|---|---|---|---|---|---|\n");
    for (int k = 1; k < r->n_models; ++k) {
        int j = exact_of(r, k);
        if (j < 0) continue;
        model_stats s = stats_vs(r, k, j);
        fprintf(f, "| %s | %s | %d | %.1f %% | %.1f %% | %.3f | %.3f | %.2fx |\n", model_name(r, k), model_name(r, j),
                s.cells, 100 * s.mean_rel, 100 * s.worst_rel, s.mean_ratio, s.worst_ratio,
                r->eval_ns[k] > 0 ? r->eval_ns[j] / r->eval_ns[k] : 0.0);
    }
}

static void md_reading(FILE *f)
{
    fprintf(f, "\n## Reading the numbers\n\n"
               "- The full material of a dielectric preset is what the tracer renders: a Lambert\n"
               "  base with no dry specular lobe, under the liquid's smooth film. Models with a\n"
               "  GGX base (`ww`, `ww-triace`, `ggx-*`, `porous-ggx`) add the material's own\n"
               "  specular, which is most of their error at 80 degrees on dark presets (asphalt).\n"
               "- `film` and `film-ctx` are the same Lekner-Dorf film over Lambert as the full\n"
               "  material (its mirror lobe included): within a few per cent on the dielectric\n"
               "  presets (the per-preset table; part of it is the Monte Carlo noise of the\n"
               "  models' generic cosine + GGX sampling, the rest is largest at 80 degrees);\n"
               "  on conductors they have no metal base. `lambert` has neither film nor\n"
               "  specular: at grazing incidence a wet surface is mostly the film's mirror, so\n"
               "  its wet/dry errors are largest there (the full material's ratio reaches about\n"
               "  8 on asphalt at 80 degrees).\n"
               "- `porous` and `porous-ggx` darken the dry albedo with their own pore model\n"
               "  (seed 002) instead of the chain's calibrated subsurface albedo and interface\n"
               "  (soak/wetness.h steps 4-5): their error is the difference between the two\n"
               "  wetting models, largest soaked.\n"
               "- Conductors: `ggx-conductor` is the dry base; `ww`/`ww-triace` model the film\n"
               "  over it; the others have no conductor base (error ~100 %%).\n"
               "- Costs: one eval is what next-event estimation pays per light sample; one\n"
               "  sample what the path pays per bounce. The full material's cost is that of the\n"
               "  closed-form film over Lambert (dielectric presets); over a GGX base the film is\n"
               "  traced (a walk per sample, no eval), so its eval column leaves the conductors out.\n\n");
}

/* Mean relative error per preset and model. */
static void md_per_preset(FILE *f, const report *r)
{
    fprintf(f, "## Per preset (relative error, mean over wetness, angles and liquids)\n\n| preset |");
    for (int k = 1; k < r->n_models; ++k) fprintf(f, " %s |", model_name(r, k));
    fprintf(f, "\n|---|");
    for (int k = 1; k < r->n_models; ++k) fprintf(f, "---|");
    fprintf(f, "\n");
    const soak_preset *last = NULL;
    for (int ci = 0; ci < r->n_cells; ++ci) {
        if (r->cells[ci].preset == last) continue;
        last = r->cells[ci].preset;
        fprintf(f, "| %s |", last->name);
        for (int k = 1; k < r->n_models; ++k) {
            double sum = 0;
            int n = 0;
            for (int cj = ci; cj < r->n_cells && r->cells[cj].preset == last; ++cj) {
                const model_result *ref = &r->res[(size_t)cj * r->n_models], *m = ref + k;
                if (!ref->valid || !m->valid) continue;
                double e = 0;
                for (int ch = 0; ch < 3; ++ch)
                    e = fmax(e, fabs(soak_rgb_at(m->est.value, ch) - soak_rgb_at(ref->est.value, ch)) /
                                    fmax(soak_rgb_at(ref->est.value, ch), 0.01));
                sum += e;
                ++n;
            }
            if (n) fprintf(f, " %.1f %% |", 100 * sum / n);
            else fprintf(f, " n/a |");
        }
        fprintf(f, "\n");
    }
}

static void md_not_traced(FILE *f, const report *r)
{
    fprintf(f, "\n## Not traced here\n\n");
    fprintf(f, "- Thin sheets (");
    for (int i = 0; i < r->n_skipped; ++i) fprintf(f, "%s%s", i ? ", " : "", r->skipped[i]);
    fprintf(f, "): their full description is a traced medium under a smooth boundary; no\n"
               "  BSDF reproduces it, so no directional albedo of the same kind is computed.\n"
               "- Front ends (POV-Ray, Blender Cycles/EEVEE, OSL): their errors against `soak render`\n"
               "  are published by their own tests and READMEs (povray/README.md,\n"
               "  blender_addon/README.md, osl/README.md); `soak report` does not run them (they need\n"
               "  their renderers and minutes per image) and this table does not include them. The\n"
               "  OSL shaders' table is the output of CI runs: `osl_render_vs_soak` with OSL 1.13.12,\n"
               "  which CI's set-up (`.ci/run`) provides; a CI run in which it skips fails.\n"
               "- Angular shape: R integrates over the lighting hemisphere; a model with the\n"
               "  right albedo and a wrong lobe shape scores well here (see `soak advise`, which\n"
               "  measures rendered images).\n");
}

static void write_markdown(FILE *f, const report_args *a, const report *r)
{
    md_intro(f, a);
    md_models(f, r);
    md_fast_paths(f, r);
    md_reading(f);
    md_per_preset(f, r);
    md_not_traced(f, r);
}

static int write_outputs(const report_args *a, const report *r)
{
    soak_staged st;
    FILE *fj = NULL, *fm = NULL;
    char err[1024];
    soak_staged_init(&st);
    if (soak_staged_open(&st, a->json, &fj, err, sizeof err) != SOAK_OK ||
        soak_staged_open(&st, a->markdown, &fm, err, sizeof err) != SOAK_OK) {
        if (fj) fclose(fj);
        soak_staged_abort(&st);
        cli_error(CMD, "%s", err);
        return SOAK_EXIT_FAIL;
    }
    write_json(fj, a, r);
    write_markdown(fm, a, r);
    soak_status s1 = soak_staged_close(fj, a->json, err, sizeof err);
    soak_status s2 = soak_staged_close(fm, a->markdown, s1 == SOAK_OK ? err : err + 512, 512);
    if (s1 != SOAK_OK || s2 != SOAK_OK || soak_staged_commit(&st, err, sizeof err) != SOAK_OK) {
        if (s1 != SOAK_OK || s2 != SOAK_OK) soak_staged_abort(&st);
        cli_error(CMD, "%s", err);
        return SOAK_EXIT_FAIL;
    }
    return SOAK_EXIT_OK;
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
    static report r;
    memset(&r, 0, sizeof r);
    size_t nm;
    const soak_model *all = soak_models(&nm);
    r.n_models = 1;
    for (size_t i = 0; i < nm && r.n_models < MAX_MODELS; ++i) r.models[r.n_models++] = &all[i];
    rc = SOAK_EXIT_FAIL;
    if (!build_grid(db, a.quick, &r) || !(r.res = calloc((size_t)r.n_cells * r.n_models, sizeof *r.res))) {
        cli_error(CMD, "out of memory");
        goto done;
    }
    cli_progress prog;
    cli_progress_start(&prog, "report", r.n_cells);
    for (int ci = 0; ci < r.n_cells; ++ci) {
        if (!run_cell(&a, &r, ci)) goto done;
        cli_progress_update(&prog, ci + 1);
    }
    cli_progress_finish(&prog);
    if (!a.no_cost) measure_costs(&r, &r);
    if (a.callgrind) read_callgrind(a.callgrind, &r);
    rc = write_outputs(&a, &r);
    if (rc == SOAK_EXIT_OK) printf("%d cells x %d models: %s, %s\n", r.n_cells, r.n_models, a.json, a.markdown);
done:
    free(r.cells);
    free(r.res);
    soak_presets_free(db);
    return rc;
}
