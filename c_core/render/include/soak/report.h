/* `soak report`'s measurement and writers: every model of soak_models()
 * against the full description of each preset on a fixed grid
 * (soak/accuracy.h), what each costs, and the tables (Markdown) and values
 * (JSON) that docs/ACCURACY.md and docs/accuracy/report.json hold.
 *
 * The grid: each preset (thin sheets excepted: their full description is a
 * traced medium) x wetness {0, pore saturation, 1} x incidence {0, 30, 60,
 * 80} degrees x liquid {water, red_wine}; --quick keeps sand, marble and
 * copper, water, 0 and 60 degrees, with the same values as the full grid's
 * cells (each cell's seed depends on what the cell is, not on its place).
 *
 * Usage: soak_report_create, soak_report_run_cell for every cell (the caller
 * shows progress), optionally soak_report_measure_costs and
 * soak_report_read_callgrind, then soak_report_write; soak_report_free. */
#ifndef SOAK_REPORT_H
#define SOAK_REPORT_H

#include <stddef.h>

#include "soak/preset.h"
#include "soak/status.h"

typedef struct soak_report soak_report;

typedef struct soak_report_settings {
    long samples;            /* Monte Carlo samples per state and cell, in [1, 1e8] */
    unsigned long long seed; /* base seed; each cell's seed derives from it */
    int quick;               /* the subset grid (see above) */
} soak_report_settings;

/* The grid over db's presets (db must outlive the report). SOAK_ERR_NOMEM
 * when it cannot be allocated. */
soak_status soak_report_create(const soak_preset_db *db, const soak_report_settings *settings, soak_report **out);
void soak_report_free(soak_report *r);

int soak_report_cell_count(const soak_report *r);
/* The models compared, the full material included. */
int soak_report_model_count(const soak_report *r);

/* Measures cell ci with every model; on error (the preset's scene cannot be
 * built) err holds "preset '<name>': <reason>". */
soak_status soak_report_run_cell(soak_report *r, int ci, char *err, size_t errlen);

/* Median CPU time per eval and per sample of each model over the presets'
 * wet state (timings: one machine, never asserted). */
void soak_report_measure_costs(soak_report *r);

/* Instruction counts per evaluation (TSV: model, Ir) from
 * scripts/accuracy_report.sh; a missing file leaves them out. */
void soak_report_read_callgrind(soak_report *r, const char *path);

/* Writes the values (JSON) and the tables (Markdown) together through one
 * staged set, or neither; err names the file on failure. */
soak_status soak_report_write(const soak_report *r, const char *json_path, const char *markdown_path, char *err,
                              size_t errlen);

#endif
