/* `soak report`'s error statistics (soak/report.h): per model, the relative
 * and absolute albedo errors against a reference model and the error of the
 * wet/dry luminance ratio. */
#include <math.h>
#include <string.h>

#include "report_internal.h"

/* The dry cell (state 0) of the same preset, liquid and angle. */
static int dry_of(const soak_report *r, int ci)
{
    const report_cell *c = &r->cells[ci];
    for (int j = 0; j < r->n_cells; ++j) {
        const report_cell *d = &r->cells[j];
        if (d->preset == c->preset && d->liquid == c->liquid && d->angle_deg == c->angle_deg && d->state == 0) return j;
    }
    return -1;
}

/* |wet/dry ratio of model k - that of model ref_k| for cell ci, added to s
 * when both dry cells are valid and lit. */
static void add_ratio_error(const soak_report *r, int ci, int k, int ref_k, model_stats *s)
{
    const model_result *row = &r->res[(size_t)ci * r->n_models], *ref = row + ref_k, *m = row + k;
    int dj = r->cells[ci].state ? dry_of(r, ci) : -1;
    const model_result *drow = dj >= 0 ? &r->res[(size_t)dj * r->n_models] : NULL;
    if (drow && drow[ref_k].valid && drow[k].valid && soak_rgb_luminance(drow[k].est.value) > 0 &&
        soak_rgb_luminance(drow[ref_k].est.value) > 0) {
        double e = fabs(soak_rgb_luminance(m->est.value) / soak_rgb_luminance(drow[k].est.value) -
                        soak_rgb_luminance(ref->est.value) / soak_rgb_luminance(drow[ref_k].est.value));
        s->ratio_cells++;
        s->mean_ratio += e;
        s->worst_ratio = fmax(s->worst_ratio, e);
    }
}

model_stats report_stats_vs(const soak_report *r, int k, int ref_k)
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
        add_ratio_error(r, ci, k, ref_k, &s);
    }
    if (s.cells) {
        s.mean_abs /= s.cells;
        s.mean_rel /= s.cells;
        s.mean_se /= s.cells;
    }
    if (s.ratio_cells) s.mean_ratio /= s.ratio_cells;
    return s;
}

int report_exact_of(const soak_report *r, int k)
{
    if (k == 0 || !r->models[k]->exact) return -1;
    for (int j = 1; j < r->n_models; ++j)
        if (strcmp(r->models[j]->name, r->models[k]->exact) == 0) return j;
    return -1;
}
