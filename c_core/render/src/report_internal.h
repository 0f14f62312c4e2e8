/* Private state of `soak report` (soak/report.h) shared by its grid,
 * statistics and writers. */
#ifndef SOAK_REPORT_INTERNAL_H
#define SOAK_REPORT_INTERNAL_H

#include <stdio.h>

#include "soak/accuracy.h"
#include "soak/models.h"
#include "soak/report.h"

#define REPORT_MAX_MODELS 32
#define REPORT_MAX_PRESETS 64
#define REPORT_N_ANGLES 4
#define REPORT_N_LIQUIDS 2
extern const char *const report_liquids[REPORT_N_LIQUIDS];

typedef struct report_cell {
    const soak_preset *preset;
    int liquid;
    double wetness, angle_deg;
    int state; /* 0 dry, 1 saturation, 2 soaked: for the wet/dry ratio */
} report_cell;

typedef struct model_result {
    int valid;
    soak_albedo_estimate est;
} model_result;

struct soak_report {
    soak_report_settings settings;
    const soak_model *models[REPORT_MAX_MODELS]; /* [0] = NULL: the full material */
    int n_models;
    report_cell *cells;
    int n_cells;
    model_result *res; /* n_cells x n_models */
    double eval_ns[REPORT_MAX_MODELS], sample_ns[REPORT_MAX_MODELS], ir[REPORT_MAX_MODELS];
    int have_ir;
    const char *skipped[REPORT_MAX_PRESETS];
    int n_skipped;
};

typedef struct model_stats {
    int cells, na;
    double mean_rel, worst_rel, mean_abs, worst_abs, mean_ratio, worst_ratio, mean_se;
    int ratio_cells, worst_cell;
} model_stats;

const char *report_model_name(const soak_report *r, int k);
/* Errors of model k against model ref_k (0: the full material). */
model_stats report_stats_vs(const soak_report *r, int k, int ref_k);
/* Index of a fast path's exact peer, or -1. */
int report_exact_of(const soak_report *r, int k);

void report_write_json(FILE *f, const soak_report *r);
void report_write_markdown(FILE *f, const soak_report *r);

#endif
