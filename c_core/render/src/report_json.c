/* `soak report`'s values as JSON (soak/report.h; docs/accuracy/report.json). */
#include <stdio.h>

#include "report_internal.h"

void report_write_json(FILE *f, const soak_report *r)
{
    fprintf(f, "{\n  \"format\": \"soak-accuracy\",\n  \"version\": 1,\n");
    fprintf(f, "  \"settings\": {\"samples\": %ld, \"seed\": %llu, \"quick\": %d, \"angles_deg\": [0, 30, 60, 80], "
               "\"liquids\": [\"water\", \"red_wine\"], \"measure\": \"directional albedo, renderer's BSDF sampling\"},\n",
            r->settings.samples, r->settings.seed, r->settings.quick);
    fprintf(f, "  \"models\": [\n");
    for (int k = 0; k < r->n_models; ++k) {
        model_stats s = report_stats_vs(r, k, 0);
        const char *exact = k > 0 && r->models[k]->exact ? r->models[k]->exact : "";
        fprintf(f,
                "    {\"name\": \"%s\", \"exact\": \"%s\", \"cells\": %d, \"not_applicable\": %d, "
                "\"mean_rel_error\": %.6f, \"worst_rel_error\": %.6f, \"mean_abs_error\": %.6f, \"worst_abs_error\": %.6f, "
                "\"mean_ratio_error\": %.6f, \"worst_ratio_error\": %.6f, \"mean_std_error\": %.6f, "
                "\"eval_ns\": %.1f, \"sample_ns\": %.1f, \"callgrind_ir_per_eval\": %.0f}%s\n",
                report_model_name(r, k), exact, s.cells, s.na, s.mean_rel, s.worst_rel, s.mean_abs, s.worst_abs, s.mean_ratio,
                s.worst_ratio, s.mean_se, r->eval_ns[k], r->sample_ns[k], r->ir[k], k + 1 < r->n_models ? "," : "");
    }
    fprintf(f, "  ],\n  \"fast_paths\": [\n");
    int first_fp = 1;
    for (int k = 1; k < r->n_models; ++k) {
        int j = report_exact_of(r, k);
        if (j < 0) continue;
        model_stats s = report_stats_vs(r, k, j);
        fprintf(f, "%s    {\"name\": \"%s\", \"exact\": \"%s\", \"cells\": %d, \"mean_rel_error\": %.6f, \"worst_rel_error\": %.6f, "
                   "\"mean_ratio_error\": %.6f, \"worst_ratio_error\": %.6f, \"speedup_eval\": %.3f}",
                first_fp ? "" : ",\n", report_model_name(r, k), report_model_name(r, j), s.cells, s.mean_rel, s.worst_rel, s.mean_ratio,
                s.worst_ratio, r->eval_ns[k] > 0 ? r->eval_ns[j] / r->eval_ns[k] : 0.0);
        first_fp = 0;
    }
    fprintf(f, "\n  ],\n  \"cells\": [\n");
    int first = 1;
    for (int ci = 0; ci < r->n_cells; ++ci)
        for (int k = 0; k < r->n_models; ++k) {
            const report_cell *c = &r->cells[ci];
            const model_result *m = &r->res[(size_t)ci * r->n_models + k];
            if (!m->valid) continue;
            fprintf(f,
                    "%s    {\"preset\": \"%s\", \"liquid\": \"%s\", \"wetness\": %.6g, \"angle_deg\": %g, \"model\": \"%s\", "
                    "\"albedo\": [%.6f, %.6f, %.6f], \"std_error\": [%.6f, %.6f, %.6f]}",
                    first ? "" : ",\n", c->preset->name, report_liquids[c->liquid], c->wetness, c->angle_deg, report_model_name(r, k),
                    m->est.value.r, m->est.value.g, m->est.value.b, m->est.std_error.r, m->est.std_error.g,
                    m->est.std_error.b);
            first = 0;
        }
    fprintf(f, "\n  ]\n}\n");
}
