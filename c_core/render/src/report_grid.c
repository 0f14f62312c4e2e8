/* `soak report`'s grid (soak/report.h): the cells, one Monte Carlo albedo per
 * cell and model, the models' costs and callgrind's instruction counts. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report_internal.h"
#include "soak/hash.h"

const char *const report_liquids[REPORT_N_LIQUIDS] = {"water", "red_wine"};
static const double ANGLES[REPORT_N_ANGLES] = {0, 30, 60, 80};
static const char *const QUICK_PRESETS[] = {"sand", "marble", "copper"};
#define N_QUICK 3

const char *report_model_name(const soak_report *r, int k) { return k == 0 ? "full" : r->models[k]->name; }

static int in_quick(const char *name)
{
    for (int i = 0; i < N_QUICK; ++i)
        if (strcmp(name, QUICK_PRESETS[i]) == 0) return 1;
    return 0;
}

static int build_grid(const soak_preset_db *db, int quick, soak_report *r)
{
    int n = soak_presets_count(db);
    r->cells = calloc((size_t)n * 3 * REPORT_N_ANGLES * REPORT_N_LIQUIDS, sizeof *r->cells);
    if (!r->cells) return 0;
    for (int i = 0; i < n; ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        if (p->kind == SOAK_KIND_THIN_SHEET) {
            if (r->n_skipped < REPORT_MAX_PRESETS) r->skipped[r->n_skipped++] = p->name;
            continue;
        }
        if (quick && !in_quick(p->name)) continue;
        double sat = soak_material_kind_porous(p->kind) ? p->porosity : 0.0;
        double wet[3] = {0, sat, 1};
        for (int l = 0; l < (quick ? 1 : REPORT_N_LIQUIDS); ++l)
            for (int s = 0; s < 3; ++s) {
                if (s == 1 && !(sat > 0 && sat < 1)) continue;
                for (int a = 0; a < REPORT_N_ANGLES; ++a) {
                    if (quick && !(a == 0 || a == 2)) continue;
                    report_cell *c = &r->cells[r->n_cells++];
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

soak_status soak_report_create(const soak_preset_db *db, const soak_report_settings *settings, soak_report **out)
{
    if (!db || !settings || !out) return SOAK_ERR_NULL;
    *out = NULL;
    soak_report *r = calloc(1, sizeof *r);
    if (!r) return SOAK_ERR_NOMEM;
    r->settings = *settings;
    size_t nm;
    const soak_model *all = soak_models(&nm);
    r->n_models = 1;
    for (size_t i = 0; i < nm && r->n_models < REPORT_MAX_MODELS; ++i) r->models[r->n_models++] = &all[i];
    if (!build_grid(db, settings->quick, r) || !(r->res = calloc((size_t)r->n_cells * r->n_models, sizeof *r->res))) {
        soak_report_free(r);
        return SOAK_ERR_NOMEM;
    }
    *out = r;
    return SOAK_OK;
}

void soak_report_free(soak_report *r)
{
    if (!r) return;
    free(r->cells);
    free(r->res);
    free(r);
}

int soak_report_cell_count(const soak_report *r) { return r ? r->n_cells : 0; }
int soak_report_model_count(const soak_report *r) { return r ? r->n_models : 0; }

/* Each cell's seed depends on what the cell is, not on its place in the
 * grid: --quick gives the same numbers as the full grid's cells. */
static uint64_t cell_seed(uint64_t base, const report_cell *c, const char *model)
{
    uint32_t h = soak_seed_key(base);
    for (const char *s = c->preset->name; *s; ++s) h = soak_mix32(h + (uint32_t)*s);
    for (const char *s = report_liquids[c->liquid]; *s; ++s) h = soak_mix32(h + (uint32_t)*s);
    for (const char *s = model; *s; ++s) h = soak_mix32(h + (uint32_t)*s);
    h = soak_hash_key2(h, (int32_t)lround(c->wetness * 1e6), (int32_t)lround(c->angle_deg * 1e3));
    return h;
}

soak_status soak_report_run_cell(soak_report *r, int ci, char *err, size_t errlen)
{
    if (!r) return SOAK_ERR_NULL;
    if (!(ci >= 0 && ci < r->n_cells)) return SOAK_ERR_ARG;
    const report_cell *c = &r->cells[ci];
    soak_scene scene;
    char msg[1024];
    soak_status st = soak_accuracy_preset_scene(c->preset->name, report_liquids[c->liquid], c->wetness, &scene, msg,
                                                sizeof msg);
    if (st != SOAK_OK) {
        if (err && errlen) snprintf(err, errlen, "preset '%s': %s", c->preset->name, msg);
        return st;
    }
    soak_material full = scene.materials[0];
    double cos_o = cos(c->angle_deg * SOAK_PI / 180.0);
    if (cos_o < 1e-6) cos_o = 1e-6;
    for (int k = 0; k < r->n_models; ++k) {
        model_result *mr = &r->res[(size_t)ci * r->n_models + k];
        scene.materials[0] = full;
        if (k > 0 && soak_scene_set_model(&scene, "m", r->models[k]->name, msg, sizeof msg) != SOAK_OK) continue;
        st = soak_material_albedo(&scene.materials[0], 1.0, cos_o, (int)r->settings.samples,
                                  cell_seed(r->settings.seed, c, report_model_name(r, k)), 0, &mr->est);
        mr->valid = st == SOAK_OK;
    }
    scene.materials[0] = full;
    soak_scene_free(&scene);
    return SOAK_OK;
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

/* Median over the grid's presets (wet state, water) of model k's cost. */
static void measure_model_cost(soak_report *r, int k)
{
    double ev[REPORT_MAX_PRESETS], sa[REPORT_MAX_PRESETS];
    int n = 0;
    const soak_preset *last = NULL;
    for (int ci = 0; ci < r->n_cells && n < REPORT_MAX_PRESETS; ++ci) {
        const report_cell *c = &r->cells[ci];
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
    int m = 0; /* a failed measurement's zeros left out */
    for (int i = 0; i < n; ++i)
        if (ev[i] > 0) ev[m++] = ev[i];
    r->eval_ns[k] = median(ev, m);
    r->sample_ns[k] = median(sa, n);
}

void soak_report_measure_costs(soak_report *r)
{
    if (!r) return;
    for (int k = 0; k < r->n_models; ++k) measure_model_cost(r, k);
}

void soak_report_read_callgrind(soak_report *r, const char *path)
{
    if (!r || !path) return;
    FILE *f = fopen(path, "r");
    if (!f) return;
    char name[128];
    double ir;
    while (fscanf(f, "%127s %lf", name, &ir) == 2)
        for (int k = 0; k < r->n_models; ++k)
            if (strcmp(report_model_name(r, k), name) == 0) {
                r->ir[k] = ir;
                r->have_ir = 1;
            }
    fclose(f);
}
