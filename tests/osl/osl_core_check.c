/* Reads what the compiled OSL shaders computed under testshade
 * (tests/osl/osl_check.py writes one CSV row per shading point) and checks
 * every value against the core itself:
 *   WetColor      = soak_wetness_eval (preset colour) within the export's knot
 *                   tolerance, or soak_wet_params_for_base (UseBaseColor) within
 *                   the base-colour tolerance;
 *   Coverage      = soak_wet_interface_area, Roughness = sqrt(GGX alpha), both
 *                   within the knot tolerance;
 *   Transmittance = soak_sheet_transmittance within exp(10 tol) - 1 = 2.0 %
 *                   relative (the knots bound 0.1 ln T within the knot
 *                   tolerance; the shaders interpolate ln T).
 * usage: osl_core_check ROWS.csv MIN_ROWS. Exit 0 when every row agrees and
 * at least MIN_ROWS rows were read, else 1. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "soak/export.h"
#include "soak/preset.h"
#include "soak/sheet.h"
#include "soak/wetness.h"

#define FLOAT_EPS 1e-5 /* single-precision tables and arithmetic */
#define KNOT_TOL 0.002 /* soak_export_knots' guarantee */
#define BASE_TOL 0.005 /* soak_export_base_nodes' guarantee */
#define SHEET_FLOOR 1e-6 /* the shaders' tables floor T here */

typedef struct row {
    char shader[64], preset[64], liquid[64];
    int use_base;
    double base[3], wetness, wet[3], coverage, roughness, trans[3];
} row;

typedef struct worst {
    double colour, base_colour, coverage, roughness, trans_rel, trans_abs;
    int failed, rows;
} worst;

static int parse_row(const char *line, row *r)
{
    int n = sscanf(line, "%63[^,],%63[^,],%63[^,],%d,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", r->shader,
                   r->preset, r->liquid, &r->use_base, &r->base[0], &r->base[1], &r->base[2], &r->wetness, &r->wet[0],
                   &r->wet[1], &r->wet[2], &r->coverage, &r->roughness, &r->trans[0], &r->trans[1], &r->trans[2]);
    return n == 16;
}

static void note(worst *w, double *slot, double err, double tol, const row *r, const char *what)
{
    if (!(err <= tol)) {
        if (w->failed < 20)
            printf("FAIL %s %s/%s wetness %.4f base %.3f,%.3f,%.3f: %s off by %.6f (tolerance %.6f)\n", r->shader,
                   r->preset, r->liquid, r->wetness, r->base[0], r->base[1], r->base[2], what, err, tol);
        w->failed++;
    }
    if (err > *slot || err != err) *slot = err;
}

static int check_row(const soak_preset_db *db, const row *r, worst *w)
{
    const soak_preset *p = soak_presets_find(db, r->preset);
    const soak_liquid *l = soak_presets_find_liquid(db, r->liquid);
    if (!p || !l) {
        printf("FAIL unknown preset/liquid %s/%s\n", r->preset, r->liquid);
        return 0;
    }
    soak_wet_input in = soak_wet_input_steady(p, r->wetness);
    soak_wet_params o;
    soak_rgb base = soak_rgb3(r->base[0], r->base[1], r->base[2]);
    soak_status st = r->use_base ? soak_wet_params_for_base(p, l, &in, base, &o) : soak_wetness_eval(p, l, &in, &o);
    if (st != SOAK_OK) {
        printf("FAIL core refused %s/%s wetness %g: %s\n", r->preset, r->liquid, r->wetness, soak_status_str(st));
        return 0;
    }
    for (int c = 0; c < 3; ++c) {
        double err = fabs(r->wet[c] - soak_rgb_at(o.albedo, c));
        if (r->use_base)
            note(w, &w->base_colour, err, BASE_TOL + FLOAT_EPS, r, "WetColor (your colour)");
        else
            note(w, &w->colour, err, KNOT_TOL + FLOAT_EPS, r, "WetColor");
    }
    note(w, &w->coverage, fabs(r->coverage - soak_wet_interface_area(&o)), KNOT_TOL + FLOAT_EPS, r, "Coverage");
    note(w, &w->roughness, fabs(r->roughness - sqrt(o.ggx_alpha)), KNOT_TOL + FLOAT_EPS, r, "Roughness");
    if (p->kind == SOAK_KIND_THIN_SHEET && strcmp(r->shader, "soak_wet_sheet") == 0 && !r->use_base) {
        soak_rgb t;
        if (soak_sheet_transmittance(&o, p->thickness_m, p->ior, &t) != SOAK_OK) return 0;
        for (int c = 0; c < 3; ++c) {
            double ref = soak_rgb_at(t, c);
            if (ref <= SHEET_FLOOR) {
                note(w, &w->trans_abs, fabs(r->trans[c] - ref), SHEET_FLOOR, r, "Transmittance (below the floor)");
                continue;
            }
            note(w, &w->trans_rel, fabs(r->trans[c] - ref) / ref, exp(10.0 * KNOT_TOL) - 1.0 + FLOAT_EPS, r,
                 "Transmittance (rel.)");
        }
    }
    return 1;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: osl_core_check ROWS.csv MIN_ROWS\n");
        return 2;
    }
    FILE *f = fopen(argv[1], "r");
    if (!f) {
        perror(argv[1]);
        return 1;
    }
    char err[512];
    soak_preset_db *db = NULL;
    if (soak_presets_load(NULL, &db, err, sizeof err) != SOAK_OK) {
        printf("FAIL presets: %s\n", err);
        fclose(f);
        return 1;
    }
    worst w = {0};
    char line[1024];
    int bad = 0;
    while (fgets(line, sizeof line, f)) {
        row r;
        if (line[0] == '#' || line[0] == '\n') continue;
        if (!parse_row(line, &r) || !check_row(db, &r, &w)) {
            printf("FAIL row: %s", line);
            bad++;
            continue;
        }
        w.rows++;
    }
    fclose(f);
    soak_presets_free(db);
    printf("%d rows: worst WetColor %.6f (<= %.4f), your colour %.6f (<= %.4f), Coverage %.6f, Roughness %.6f "
           "(<= %.4f), sheet Transmittance %.2f %% (<= %.1f %%)\n",
           w.rows, w.colour, KNOT_TOL, w.base_colour, BASE_TOL, w.coverage, w.roughness, KNOT_TOL, 100 * w.trans_rel,
           100 * (exp(10.0 * KNOT_TOL) - 1.0));
    long min_rows = strtol(argv[2], NULL, 10);
    if (w.rows < min_rows) printf("FAIL only %d rows (expected at least %ld)\n", w.rows, min_rows);
    return (w.failed || bad || w.rows < min_rows) ? 1 : 0;
}
