/* soak export --target blender: the data the Blender add-on ships
 * (blender_addon/soak/soak_data.json).
 *
 * Blender's native nodes interpolate images bilinearly between pixel centres
 * on a uniform grid, so the wetness function for any base colour
 * (soak_wet_params_for_base) is resampled here onto a grid the add-on only
 * copies into a float image datablock:
 *   columns: s = 1 - sqrt(1 - a) uniform in [0, 1] (a the dry albedo of one
 *            channel; the square root crowds columns towards a = 1, where the
 *            van de Hulst inversion is steep);
 *   rows:    the delivered liquid L: q = sqrt(L / w_sat) uniform in [0, 1]
 *            below saturation (rows_below intervals; an absorbing liquid in
 *            the pores of a bright base darkens it like sqrt(L)), L uniform
 *            over [w_sat, 1] above (rows_above intervals), so that the
 *            saturation kink lies on a row.
 * A second image holds per-row parameters (roughness, film coverage, ...).
 * The writer refines both grids until bilinear interpolation stays within
 * half of SOAK_EXPORT_BASE_TOL of the core at cell midpoints, and writes the
 * worst error it then finds at cell centres and quarter points. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "soak/export.h"
#include "soak/sheet.h"
#include "soak/wet_specular.h"

#define BL_FORMAT "soak-blender"
#define BL_FORMAT_VERSION 3
#define BL_MAX_COLS 257
#define BL_MAX_ROWS 257
#define BL_PARAM_COLS 4 /* see param_pixel */

typedef struct bl_grid {
    const soak_preset *p;
    const soak_liquid *l;
    double w_sat;
    int na, n1, n2; /* columns; intervals below and above saturation */
} bl_grid;

static double col_albedo(const bl_grid *g, double j)
{
    double s = j / (g->na - 1);
    double a = 1.0 - (1.0 - s) * (1.0 - s);
    return a < 0.0 ? 0.0 : (a > 1.0 ? 1.0 : a);
}

static double row_liquid(const bl_grid *g, double r)
{
    if (g->n1 > 0 && r <= g->n1) return g->w_sat * (r / g->n1) * (r / g->n1);
    double t = (r - g->n1) / g->n2;
    double L = g->w_sat + (1.0 - g->w_sat) * t;
    return L < 0.0 ? 0.0 : (L > 1.0 ? 1.0 : L);
}

static int grid_rows(const bl_grid *g) { return g->n1 + g->n2 + 1; }

/* The wet albedo (under a separate coat lobe) of all three channels for a
 * grey dry albedo a: channel c of the result is the function for channel c. */
static soak_status albedo_pixel(const bl_grid *g, double a, double L, double px[3])
{
    soak_wet_input in = soak_wet_input_steady(g->p, L);
    soak_wet_params out;
    soak_status st = soak_wet_params_for_base(g->p, g->l, &in, (soak_rgb){a, a, a}, &out);
    if (st != SOAK_OK) return st;
    for (int c = 0; c < 3; ++c) px[c] = soak_rgb_at(out.albedo, c);
    return SOAK_OK;
}

/* Per-row parameters, four RGB pixels:
 *   0: roughness (= sqrt GGX alpha), film coverage, water specular weight;
 *   1: pore fill, material specular weight, 0;
 *   2: thin-sheet diffuse transmittance (0 for other kinds);
 *   3: soak/wet_specular.h: the base's own specular over its dry value, the
 *      liquid mirror's weight (interface area), apparent roughness over its
 *      dry value (sqrt apparent GGX alpha: conductors seen through the film;
 *      the ratio scales the user's own roughness). */
static soak_status param_pixel(const bl_grid *g, double L, double px[BL_PARAM_COLS * 3])
{
    soak_wet_input in = soak_wet_input_steady(g->p, L);
    soak_wet_params w;
    soak_status st = soak_wetness_eval(g->p, g->l, &in, &w);
    soak_rgb T = {0.0, 0.0, 0.0};
    if (st == SOAK_OK && g->p->kind == SOAK_KIND_THIN_SHEET) st = soak_sheet_transmittance(&w, g->p->thickness_mm, g->p->ior, &T);
    soak_wet_specular s;
    if (st == SOAK_OK) st = soak_wet_specular_eval(g->p, g->l, &w, &s);
    if (st != SOAK_OK) return st;
    double rough_dry = sqrt(g->p->ggx_alpha_dry);
    double ratio = rough_dry > 0.0 ? sqrt(s.ggx_alpha) / rough_dry : 1.0;
    double v[BL_PARAM_COLS * 3] = {sqrt(w.ggx_alpha), w.film_coverage, w.water_specular_weight,
                                   w.fill, w.specular_weight, 0.0, T.r, T.g, T.b,
                                   s.base_factor, s.interface_area, ratio};
    memcpy(px, v, sizeof v);
    return SOAK_OK;
}

static double max_abs_diff(const double *a, const double *b, int n)
{
    double e = 0.0;
    for (int i = 0; i < n; ++i)
        if (fabs(a[i] - b[i]) > e) e = fabs(a[i] - b[i]);
    return e;
}

/* Worst error of interpolating along one axis at fraction t of each interval:
 * along columns (axis 0, at every row) or rows (axis 1; params included). */
static soak_status axis_error(const bl_grid *g, int axis, double t, int rows_lo, int rows_hi, double *err)
{
    *err = 0.0;
    double a0[3], a1[3], am[3], mid[3];
    if (axis == 0) {
        for (int r = 0; r < grid_rows(g); ++r) {
            double L = row_liquid(g, r);
            for (int j = 0; j + 1 < g->na; ++j) {
                soak_status st = albedo_pixel(g, col_albedo(g, j), L, a0);
                if (st == SOAK_OK) st = albedo_pixel(g, col_albedo(g, j + 1), L, a1);
                if (st == SOAK_OK) st = albedo_pixel(g, col_albedo(g, j + t), L, am);
                if (st != SOAK_OK) return st;
                for (int c = 0; c < 3; ++c) mid[c] = a0[c] + (a1[c] - a0[c]) * t;
                double e = max_abs_diff(mid, am, 3);
                if (e > *err) *err = e;
            }
        }
        return SOAK_OK;
    }
    double p0[BL_PARAM_COLS * 3], p1[BL_PARAM_COLS * 3], pm[BL_PARAM_COLS * 3], pi[BL_PARAM_COLS * 3];
    for (int r = rows_lo; r < rows_hi; ++r) {
        double L0 = row_liquid(g, r), L1 = row_liquid(g, r + 1), Lm = row_liquid(g, r + t);
        soak_status st = param_pixel(g, L0, p0);
        if (st == SOAK_OK) st = param_pixel(g, L1, p1);
        if (st == SOAK_OK) st = param_pixel(g, Lm, pm);
        if (st != SOAK_OK) return st;
        for (int k = 0; k < BL_PARAM_COLS * 3; ++k) pi[k] = p0[k] + (p1[k] - p0[k]) * t;
        double e = max_abs_diff(pi, pm, BL_PARAM_COLS * 3);
        if (e > *err) *err = e;
        for (int j = 0; j < g->na; ++j) {
            double a = col_albedo(g, j);
            st = albedo_pixel(g, a, L0, a0);
            if (st == SOAK_OK) st = albedo_pixel(g, a, L1, a1);
            if (st == SOAK_OK) st = albedo_pixel(g, a, Lm, am);
            if (st != SOAK_OK) return st;
            for (int c = 0; c < 3; ++c) mid[c] = a0[c] + (a1[c] - a0[c]) * t;
            e = max_abs_diff(mid, am, 3);
            if (e > *err) *err = e;
        }
    }
    return SOAK_OK;
}

/* Doubles each axis until its midpoint error is within half the tolerance. */
static soak_status refine(bl_grid *g)
{
    const double goal = 0.5 * SOAK_EXPORT_BASE_TOL;
    double e = 0.0;
    soak_status st;
    while ((st = axis_error(g, 0, 0.5, 0, 0, &e)) == SOAK_OK && e > goal && 2 * g->na - 1 <= BL_MAX_COLS)
        g->na = 2 * g->na - 1;
    if (st != SOAK_OK) return st;
    if (e > goal) return SOAK_ERR_NUMERIC;
    while (g->n1 > 0 && (st = axis_error(g, 1, 0.5, 0, g->n1, &e)) == SOAK_OK && e > goal && 2 * g->n1 + g->n2 + 1 <= BL_MAX_ROWS)
        g->n1 *= 2;
    if (st != SOAK_OK) return st;
    if (g->n1 > 0 && e > goal) return SOAK_ERR_NUMERIC;
    while ((st = axis_error(g, 1, 0.5, g->n1, g->n1 + g->n2, &e)) == SOAK_OK && e > goal && g->n1 + 2 * g->n2 + 1 <= BL_MAX_ROWS)
        g->n2 *= 2;
    if (st != SOAK_OK) return st;
    return e > goal ? SOAK_ERR_NUMERIC : SOAK_OK;
}

/* Bilinear error at cell centres and quarter points (what the add-on gets). */
static soak_status bilinear_error(const bl_grid *g, double *err)
{
    *err = 0.0;
    static const double ts[] = {0.25, 0.5, 0.75};
    int rows = grid_rows(g);
    for (int r = 0; r + 1 < rows; ++r)
        for (int j = 0; j + 1 < g->na; ++j) {
            double c00[3], c01[3], c10[3], c11[3];
            double a0 = col_albedo(g, j), a1 = col_albedo(g, j + 1);
            double L0 = row_liquid(g, r), L1 = row_liquid(g, r + 1);
            soak_status st = albedo_pixel(g, a0, L0, c00);
            if (st == SOAK_OK) st = albedo_pixel(g, a1, L0, c01);
            if (st == SOAK_OK) st = albedo_pixel(g, a0, L1, c10);
            if (st == SOAK_OK) st = albedo_pixel(g, a1, L1, c11);
            for (int u = 0; st == SOAK_OK && u < 3; ++u)
                for (int v = 0; st == SOAK_OK && v < 3; ++v) {
                    double core[3] = {0.0, 0.0, 0.0}, bi[3];
                    st = albedo_pixel(g, col_albedo(g, j + ts[u]), row_liquid(g, r + ts[v]), core);
                    if (st != SOAK_OK) break;
                    for (int c = 0; c < 3; ++c) {
                        double lo = c00[c] + (c01[c] - c00[c]) * ts[u];
                        double hi = c10[c] + (c11[c] - c10[c]) * ts[u];
                        bi[c] = lo + (hi - lo) * ts[v];
                    }
                    double e = max_abs_diff(bi, core, 3);
                    if (e > *err) *err = e;
                }
            if (st != SOAK_OK) return st;
        }
    return SOAK_OK;
}

/* Deterministic numbers: 6 significant digits, no "-0". */
static void put_num(FILE *out, double x)
{
    if (fabs(x) < 5e-13) x = 0.0;
    fprintf(out, "%.6g", x);
}

static void put_str(FILE *out, const char *s)
{
    fputc('"', out);
    for (; s && *s; ++s) {
        if (*s == '"' || *s == '\\') fputc('\\', out);
        if ((unsigned char)*s < 0x20) fprintf(out, "\\u%04x", (unsigned char)*s);
        else fputc(*s, out);
    }
    fputc('"', out);
}

static void put_rgb(FILE *out, soak_rgb c)
{
    fputc('[', out);
    for (int i = 0; i < 3; ++i) {
        if (i) fputc(',', out);
        put_num(out, soak_rgb_at(c, i));
    }
    fputc(']', out);
}

/* Node programs: the coordinate warps and the fill schedule as data, so the
 * add-on derives no formula. A program is a list of Blender Math node
 * operations [op, a, b, c, clamp]; an argument is a number, the program's
 * input ("x" or a named input) or "#k", the result of operation k; the last
 * operation's result is the program's output. */
typedef struct bl_op {
    const char *op;
    const char *ref[3]; /* NULL: the number num[i] */
    double num[3];
    int nargs, clamp;
} bl_op;

static void put_prog_num(FILE *out, double x)
{
    if (fabs(x) < 5e-16) x = 0.0;
    fprintf(out, "%.10g", x);
}

static void put_program(FILE *out, const char *key, const bl_op *ops, int n)
{
    fprintf(out, "\"%s\": [", key);
    for (int i = 0; i < n; ++i) {
        fprintf(out, "%s[\"%s\"", i ? ", " : "", ops[i].op);
        for (int k = 0; k < ops[i].nargs; ++k) {
            fputs(", ", out);
            if (ops[i].ref[k]) put_str(out, ops[i].ref[k]);
            else put_prog_num(out, ops[i].num[k]);
        }
        fputs(ops[i].clamp ? ", true]" : ", false]", out);
    }
    fputc(']', out);
}

/* Column position t = j/(columns-1) of dry albedo x: t = 1 - sqrt(1 - x)
 * (col_albedo inverted). Row position t = r/(rows-1) of delivered liquid x
 * (row_liquid inverted): sqrt(x/w_sat) over the rows below saturation plus
 * (x - w_sat)/(1 - w_sat) over the rows above. */
static void put_coordinate_programs(FILE *out, const bl_grid *g)
{
    const bl_op col[] = {{"SUBTRACT", {NULL, "x"}, {1.0}, 2, 0},
                         {"SQRT", {"#0"}, {0.0}, 1, 0},
                         {"MULTIPLY_ADD", {"#1"}, {0.0, -1.0, 1.0}, 3, 0}};
    put_program(out, "column_program", col, 3);
    fputs(",\n      ", out);
    double n = g->n1 + g->n2, ws = g->w_sat;
    if (g->n1 > 0) {
        const bl_op row[] = {{"MULTIPLY", {"x"}, {0.0, 1.0 / ws}, 2, 1},
                             {"SQRT", {"#0"}, {0.0}, 1, 0},
                             {"MULTIPLY_ADD", {"x"}, {0.0, 1.0 / (1.0 - ws), -ws / (1.0 - ws)}, 3, 1},
                             {"MULTIPLY", {"#2"}, {0.0, g->n2 / n}, 2, 0},
                             {"MULTIPLY_ADD", {"#1", NULL, "#3"}, {0.0, g->n1 / n, 0.0}, 3, 0}};
        put_program(out, "row_program", row, 5);
    } else {
        const bl_op row[] = {{"MULTIPLY_ADD", {"x"}, {0.0, 1.0 / (1.0 - ws), -ws / (1.0 - ws)}, 3, 1}};
        put_program(out, "row_program", row, 1);
    }
}

/* The fill schedule of soak_fill_fraction (soak/porous.h):
 * P = clamp((time - start_time) / fill_time, 0, 1), right-continuous: a zero
 * fill time is the step to 1 at start_time. Written as
 * clamp((time - start_time + d) / (fill_time + d)) with d = 1e-9 s: 1 at
 * start_time for a zero fill time, off by d / fill_time otherwise. */
static void put_schedule_program(FILE *out)
{
    const bl_op ops[] = {{"SUBTRACT", {"time", "start_time"}, {0.0}, 2, 0},
                         {"ADD", {"#0"}, {0.0, 1e-9}, 2, 0},
                         {"ADD", {"fill_time"}, {0.0, 1e-9}, 2, 0},
                         {"DIVIDE", {"#1", "#2"}, {0.0}, 2, 1}};
    put_program(out, "schedule_program", ops, 4);
}

static soak_status write_pixels(FILE *out, const bl_grid *g)
{
    int rows = grid_rows(g);
    double px[BL_PARAM_COLS * 3];
    fputs("      \"albedo\": [\n", out);
    for (int r = 0; r < rows; ++r) {
        fputs("        [", out);
        for (int j = 0; j < g->na; ++j) {
            soak_status st = albedo_pixel(g, col_albedo(g, j), row_liquid(g, r), px);
            if (st != SOAK_OK) return st;
            for (int c = 0; c < 3; ++c) {
                if (j || c) fputc(',', out);
                put_num(out, px[c]);
            }
        }
        fputs(r + 1 < rows ? "],\n" : "]\n", out);
    }
    fputs("      ],\n      \"params\": [\n", out);
    for (int r = 0; r < rows; ++r) {
        soak_status st = param_pixel(g, row_liquid(g, r), px);
        if (st != SOAK_OK) return st;
        fputs("        [", out);
        for (int k = 0; k < BL_PARAM_COLS * 3; ++k) {
            if (k) fputc(',', out);
            put_num(out, px[k]);
        }
        fputs(r + 1 < rows ? "],\n" : "]\n", out);
    }
    fputs("      ]\n", out);
    return SOAK_OK;
}

static soak_status write_table(FILE *out, const soak_preset *p, const soak_liquid *l, int last)
{
    bl_grid g = {p, l, soak_material_kind_porous(p->kind) ? p->porosity : 0.0, 17, 0, 1};
    if (g.w_sat > 0.0) g.n1 = 4;
    soak_status st = refine(&g);
    double err = 0.0;
    if (st == SOAK_OK) st = bilinear_error(&g, &err);
    if (st != SOAK_OK) return st;
    fputs("     ", out);
    put_str(out, l->name);
    fprintf(out, ": {\n      \"columns\": %d, \"rows_below\": %d, \"rows_above\": %d, \"saturation\": ", g.na, g.n1,
            g.n2);
    put_num(out, g.w_sat);
    fputs(", \"max_error\": ", out);
    put_num(out, err);
    fputs(",\n      ", out);
    put_coordinate_programs(out, &g);
    fputs(",\n", out);
    st = write_pixels(out, &g);
    fputs(last ? "     }\n" : "     },\n", out);
    return st;
}

static soak_status write_material(FILE *out, const soak_preset_db *db, const soak_preset *p, int last, char *err,
                                  size_t errlen)
{
    fputs("  {\"name\": ", out);
    put_str(out, p->name);
    fputs(", \"display_name\": ", out);
    put_str(out, p->display_name);
    fputs(", \"kind\": ", out);
    put_str(out, soak_material_kind_name(p->kind));
    fputs(",\n   \"dry_albedo\": ", out);
    put_rgb(out, p->albedo);
    fputs(", \"roughness_dry\": ", out);
    put_num(out, sqrt(p->ggx_alpha_dry));
    fputs(", \"ior\": ", out);
    put_num(out, p->ior);
    fputs(", \"porosity\": ", out);
    put_num(out, p->porosity);
    fputs(", \"t_fill\": ", out);
    put_num(out, p->t_fill);
    fputs(", \"sheet_thickness_m\": ", out);
    put_num(out, 1e-3 * p->thickness_mm);
    fputs(",\n   \"liquids\": {\n", out);
    int nl = soak_presets_liquid_count(db);
    for (int i = 0; i < nl; ++i) {
        const soak_liquid *l = soak_presets_liquid_at(db, i);
        soak_status st = write_table(out, p, l, i + 1 == nl);
        if (st != SOAK_OK) {
            snprintf(err, errlen, "preset '%s', liquid '%s': %s", p->name, l->name, soak_status_str(st));
            return st;
        }
    }
    fputs(last ? "   }}\n" : "   }},\n", out);
    return SOAK_OK;
}

static void write_header(FILE *out, const soak_export_header *h)
{
    fputs("{\n \"format\": \"" BL_FORMAT "\", \"format_version\": ", out);
    fprintf(out, "%d", BL_FORMAT_VERSION);
    fputs(", \"generator\": ", out);
    put_str(out, h->generator);
    fputs(",\n \"materials_file\": ", out);
    put_str(out, h->materials_file);
    fputs(", \"materials_hash\": ", out);
    put_str(out, h->materials_hash);
    fputs(", \"tolerance\": ", out);
    put_num(out, SOAK_EXPORT_BASE_TOL);
    fputs(",\n \"layout\": ", out);
    put_str(out,
            "per material and liquid: albedo[row][3*column+channel] and params[row][3*pixel+channel]. Column j: "
            "s = j/(columns-1), dry albedo a = 1-(1-s)^2. Row r: delivered liquid L = saturation*(r/rows_below)^2 "
            "for r <= rows_below, else saturation+(1-saturation)*(r-rows_below)/rows_above. Channel c of the "
            "albedo pixel is the wet albedo of channel c (under a coat of the liquid's IOR weighted by the film "
            "coverage) for dry albedo a. params pixels: 0 = (roughness, film coverage, water specular weight), "
            "1 = (pore fill, specular weight, 0), 2 = thin-sheet transmittance, 3 = (the base's own specular under the "
            "liquid over its dry value, the liquid mirror's weight = interface area, apparent roughness: conductors "
            "seen through the film; see soak/wet_specular.h). Interpolate bilinearly between "
            "pixel centres; max_error is the worst error of that against the core.");
    fputs(",\n ", out);
    put_schedule_program(out);
    fputs(",\n \"liquids\": [\n", out);
}

soak_status soak_export_write_blender(const soak_preset_db *db, FILE *out, char *err, size_t errlen)
{
    if (!db || !out || !err) return SOAK_ERR_NULL;
    soak_export_header h;
    soak_status st = soak_export_header_make(db, &h);
    if (st != SOAK_OK) {
        snprintf(err, errlen, "%s: cannot read the preset file to hash it", soak_presets_path(db));
        return st;
    }
    write_header(out, &h);
    int nl = soak_presets_liquid_count(db), np = soak_presets_count(db);
    for (int i = 0; i < nl; ++i) {
        const soak_liquid *l = soak_presets_liquid_at(db, i);
        fputs("  {\"name\": ", out);
        put_str(out, l->name);
        fputs(", \"display_name\": ", out);
        put_str(out, l->display_name);
        fputs(", \"ior\": ", out);
        put_num(out, l->ior);
        fputs(i + 1 < nl ? "},\n" : "}\n", out);
    }
    fputs(" ],\n \"materials\": [\n", out);
    for (int i = 0; st == SOAK_OK && i < np; ++i) st = write_material(out, db, soak_presets_at(db, i), i + 1 == np, err, errlen);
    if (st != SOAK_OK) return st;
    fputs(" ]\n}\n", out);
    if (ferror(out)) {
        snprintf(err, errlen, "write failed");
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}
