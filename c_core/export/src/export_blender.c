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
 * A second image holds per-row parameters (roughness, film coverage, ...),
 * a third the view factor (soak_export_view_factors) per row on the core's
 * view cosines, so that the add-on's base colour follows the liquid
 * interface's transmission towards the viewer (it cannot follow the
 * light's). The writer refines both grids until bilinear interpolation
 * stays within half of SOAK_EXPORT_BASE_TOL of the core at cell midpoints (the view
 * factor's on the colour it scales included), and writes the worst errors it
 * then finds at cell centres and quarter points. JSON through
 * soak/json_writer.h: 6 significant digits (the images are 32-bit float; the
 * tolerance is 5e-3), 10 for the node programs' constants. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "soak/export.h"
#include "soak/fresnel.h"
#include "soak/json_writer.h"
#include "soak/sheet.h"
#include "soak/wet_specular.h"

#define BL_FORMAT "soak-blender"
#define BL_FORMAT_VERSION 4
#define BL_DIGITS 6             /* significant digits of pixels and facts */
#define BL_ZERO 5e-13           /* written as 0 below this */
#define BL_F0_IOR_FIRST 1.0     /* normal_reflectance table: indices 1.00 ... 3.00 */
#define BL_F0_IOR_STEP 0.01
#define BL_F0_N 201
#define BL_PROGRAM_DIGITS 10    /* node program constants: positions of rows */
#define BL_PROGRAM_ZERO 5e-16
#define BL_MAX_COLS 257
#define BL_MAX_ROWS 257
#define BL_PARAM_COLS 4 /* see param_pixel */
#define BL_VIEW_MAX_DEG 75.0    /* view_max_error covers views up to this zenith angle */

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
    if (st == SOAK_OK && g->p->kind == SOAK_KIND_THIN_SHEET) st = soak_sheet_transmittance(&w, g->p->thickness_m, g->p->ior, &T);
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

/* The view factor of the row's state on the view cosines i / (VIEW_N - 1). */
static soak_status view_row(const bl_grid *g, double L, soak_rgb f[SOAK_EXPORT_VIEW_N])
{
    soak_wet_input in = soak_wet_input_steady(g->p, L);
    soak_wet_params w;
    soak_status st = soak_wetness_eval(g->p, g->l, &in, &w);
    return st == SOAK_OK ? soak_export_view_factors(g->p, g->l, &w, f) : st;
}

static double max_abs_diff(const double *a, const double *b, int n)
{
    double e = 0.0;
    for (int i = 0; i < n; ++i)
        if (fabs(a[i] - b[i]) > e) e = fabs(a[i] - b[i]);
    return e;
}

/* Bilinear error of the view-factor image against the core in row interval
 * [r, r + 1] at fraction t, at the view columns (and their quarter points
 * with between_views: the core's fixed 17 view cosines, which the rows
 * cannot refine), over views
 * up to BL_VIEW_MAX_DEG (the json export's range), on the colour it
 * multiplies: times the wet albedo of a white dry colour, the brightest any
 * user's colour gets (coffee's black film makes the factor steep near L = 1,
 * where the colour it scales is near 0). */
static soak_status view_cell_error(const bl_grid *g, int r, double t, int between_views, double *err)
{
    static const double ts[] = {0.0, 0.25, 0.5, 0.75};
    const int nu = between_views ? 4 : 1;
    const double cos_min = cos(BL_VIEW_MAX_DEG * (SOAK_PI / 180.0));
    const int n = SOAK_EXPORT_VIEW_N - 1;
    soak_rgb f0[SOAK_EXPORT_VIEW_N], f1[SOAK_EXPORT_VIEW_N];
    soak_status st = view_row(g, row_liquid(g, r), f0);
    if (st == SOAK_OK) st = view_row(g, row_liquid(g, r + 1), f1);
    soak_wet_input in = soak_wet_input_steady(g->p, row_liquid(g, r + t));
    soak_wet_params w;
    double white[3];
    if (st == SOAK_OK) st = soak_wetness_eval(g->p, g->l, &in, &w);
    if (st == SOAK_OK) st = albedo_pixel(g, 1.0, row_liquid(g, r + t), white);
    *err = 0.0;
    for (int i = 0; st == SOAK_OK && i < n; ++i)
        for (int u = 0; st == SOAK_OK && u < nu; ++u) {
            double x = (i + ts[u]) / n;
            if (x < cos_min) continue;
            soak_rgb core;
            st = soak_wetness_view_factor(g->p, g->l, &w, x, &core);
            for (int c = 0; st == SOAK_OK && c < 3; ++c) {
                double lo = soak_rgb_at(f0[i], c) + (soak_rgb_at(f0[i + 1], c) - soak_rgb_at(f0[i], c)) * ts[u];
                double hi = soak_rgb_at(f1[i], c) + (soak_rgb_at(f1[i + 1], c) - soak_rgb_at(f1[i], c)) * ts[u];
                double e = white[c] * fabs(lo + (hi - lo) * t - soak_rgb_at(core, c));
                if (e > *err) *err = e;
            }
        }
    return st;
}

static soak_status view_error(const bl_grid *g, double *err)
{
    static const double ts[] = {0.25, 0.5, 0.75};
    *err = 0.0;
    for (int r = 0; r + 1 < grid_rows(g); ++r)
        for (int v = 0; v < 3; ++v) {
            double e;
            soak_status st = view_cell_error(g, r, ts[v], 1, &e);
            if (st != SOAK_OK) return st;
            if (e > *err) *err = e;
        }
    return SOAK_OK;
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
        st = view_cell_error(g, r, t, 0, &e);
        if (st != SOAK_OK) return st;
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

static void add_program(soak_json *j, cJSON *parent, const char *key, const bl_op *ops, int n)
{
    soak_json constants = soak_json_writer(BL_PROGRAM_DIGITS, BL_PROGRAM_ZERO);
    cJSON *program = soak_json_array(j, parent, key);
    for (int i = 0; program && i < n; ++i) {
        cJSON *op = soak_json_array(j, program, NULL);
        soak_json_str(j, op, NULL, ops[i].op);
        for (int k = 0; k < ops[i].nargs; ++k) {
            if (ops[i].ref[k]) soak_json_str(j, op, NULL, ops[i].ref[k]);
            else soak_json_num(&constants, op, NULL, ops[i].num[k]);
        }
        soak_json_bool(j, op, NULL, ops[i].clamp);
    }
    if (!constants.ok) j->ok = 0;
}

/* Column position t = j/(columns-1) of dry albedo x: t = 1 - sqrt(1 - x)
 * (col_albedo inverted). Row position t = r/(rows-1) of delivered liquid x
 * (row_liquid inverted): sqrt(x/w_sat) over the rows below saturation plus
 * (x - w_sat)/(1 - w_sat) over the rows above. */
static void add_coordinate_programs(soak_json *j, cJSON *table, const bl_grid *g)
{
    const bl_op col[] = {{"SUBTRACT", {NULL, "x"}, {1.0}, 2, 0},
                         {"SQRT", {"#0"}, {0.0}, 1, 0},
                         {"MULTIPLY_ADD", {"#1"}, {0.0, -1.0, 1.0}, 3, 0}};
    add_program(j, table, "column_program", col, 3);
    double n = g->n1 + g->n2, ws = g->w_sat;
    if (g->n1 > 0) {
        const bl_op row[] = {{"MULTIPLY", {"x"}, {0.0, 1.0 / ws}, 2, 1},
                             {"SQRT", {"#0"}, {0.0}, 1, 0},
                             {"MULTIPLY_ADD", {"x"}, {0.0, 1.0 / (1.0 - ws), -ws / (1.0 - ws)}, 3, 1},
                             {"MULTIPLY", {"#2"}, {0.0, g->n2 / n}, 2, 0},
                             {"MULTIPLY_ADD", {"#1", NULL, "#3"}, {0.0, g->n1 / n, 0.0}, 3, 0}};
        add_program(j, table, "row_program", row, 5);
    } else {
        const bl_op row[] = {{"MULTIPLY_ADD", {"x"}, {0.0, 1.0 / (1.0 - ws), -ws / (1.0 - ws)}, 3, 1}};
        add_program(j, table, "row_program", row, 1);
    }
}

/* The fill schedule of soak_fill_fraction (soak/porous.h):
 * P = clamp((time - start_time) / fill_time, 0, 1), right-continuous: a zero
 * fill time is the step to 1 at start_time. Written as
 * clamp((time - start_time + d) / (fill_time + d)) with d = 1e-9 s: 1 at
 * start_time for a zero fill time, off by d / fill_time otherwise. */
static void add_schedule_program(soak_json *j, cJSON *root)
{
    const bl_op ops[] = {{"SUBTRACT", {"time", "start_time"}, {0.0}, 2, 0},
                         {"ADD", {"#0"}, {0.0, 1e-9}, 2, 0},
                         {"ADD", {"fill_time"}, {0.0, 1e-9}, 2, 0},
                         {"DIVIDE", {"#1", "#2"}, {0.0}, 2, 1}};
    add_program(j, root, "schedule_program", ops, 4);
}

static soak_status add_pixels(soak_json *j, cJSON *table, const bl_grid *g)
{
    int rows = grid_rows(g);
    double px[BL_PARAM_COLS * 3];
    cJSON *albedo = soak_json_array(j, table, "albedo");
    for (int r = 0; r < rows; ++r) {
        cJSON *row = soak_json_array(j, albedo, NULL);
        for (int col = 0; col < g->na; ++col) {
            soak_status st = albedo_pixel(g, col_albedo(g, col), row_liquid(g, r), px);
            if (st != SOAK_OK) return st;
            for (int c = 0; c < 3; ++c) soak_json_num(j, row, NULL, px[c]);
        }
    }
    cJSON *params = soak_json_array(j, table, "params");
    for (int r = 0; r < rows; ++r) {
        soak_status st = param_pixel(g, row_liquid(g, r), px);
        if (st != SOAK_OK) return st;
        cJSON *row = soak_json_array(j, params, NULL);
        for (int k = 0; k < BL_PARAM_COLS * 3; ++k) soak_json_num(j, row, NULL, px[k]);
    }
    cJSON *view = soak_json_array(j, table, "view_factor");
    for (int r = 0; r < rows; ++r) {
        soak_rgb f[SOAK_EXPORT_VIEW_N];
        soak_status st = view_row(g, row_liquid(g, r), f);
        if (st != SOAK_OK) return st;
        cJSON *row = soak_json_array(j, view, NULL);
        for (int i = 0; i < SOAK_EXPORT_VIEW_N; ++i)
            for (int c = 0; c < 3; ++c) soak_json_num(j, row, NULL, soak_rgb_at(f[i], c));
    }
    return j->ok ? SOAK_OK : SOAK_ERR_NOMEM;
}

static soak_status add_table(soak_json *j, cJSON *liquids, const soak_preset *p, const soak_liquid *l)
{
    bl_grid g = {p, l, soak_material_kind_porous(p->kind) ? p->porosity : 0.0, 17, 0, 1};
    if (g.w_sat > 0.0) g.n1 = 4;
    soak_status st = refine(&g);
    double err = 0.0, view_err = 0.0;
    if (st == SOAK_OK) st = bilinear_error(&g, &err);
    if (st == SOAK_OK) st = view_error(&g, &view_err);
    if (st != SOAK_OK) return st;
    cJSON *table = soak_json_object(j, liquids, l->name);
    soak_json_int(j, table, "columns", g.na);
    soak_json_int(j, table, "rows_below", g.n1);
    soak_json_int(j, table, "rows_above", g.n2);
    soak_json_num(j, table, "saturation", g.w_sat);
    soak_json_num(j, table, "max_error", err);
    soak_json_num(j, table, "view_max_error", view_err);
    add_coordinate_programs(j, table, &g);
    return add_pixels(j, table, &g);
}

static soak_status add_material(soak_json *j, cJSON *materials, const soak_preset_db *db, const soak_preset *p,
                                char *err, size_t errlen)
{
    cJSON *m = soak_json_object(j, materials, NULL);
    soak_json_str(j, m, "name", p->name);
    soak_json_str(j, m, "display_name", p->display_name);
    soak_json_str(j, m, "kind", soak_material_kind_name(p->kind));
    soak_json_rgb(j, m, "dry_albedo", p->albedo);
    soak_json_num(j, m, "roughness_dry", sqrt(p->ggx_alpha_dry));
    soak_json_num(j, m, "ior", p->ior);
    soak_json_num(j, m, "porosity", p->porosity);
    soak_json_num(j, m, "t_fill", p->t_fill);
    soak_json_num(j, m, "sheet_thickness_m", p->thickness_m);
    cJSON *liquids = soak_json_object(j, m, "liquids");
    for (int i = 0; i < soak_presets_liquid_count(db); ++i) {
        const soak_liquid *l = soak_presets_liquid_at(db, i);
        soak_status st = add_table(j, liquids, p, l);
        if (st != SOAK_OK) {
            snprintf(err, errlen, "preset '%s', liquid '%s': %s", p->name, l->name, soak_status_str(st));
            return st;
        }
    }
    return SOAK_OK;
}

/* Fresnel's normal-incidence reflectance of a dielectric over the index, for
 * the add-on's conversions between a Principled BSDF's IOR and its specular
 * (3.x Specular, 4.x Specular IOR Level): read there by linear interpolation,
 * whose error at this step is below 1e-6 (F0'' < 0.1 on [1, 3]). */
static void add_normal_reflectance(soak_json *j, cJSON *root)
{
    cJSON *t = soak_json_object(j, root, "normal_reflectance");
    soak_json_num(j, t, "ior_first", BL_F0_IOR_FIRST);
    soak_json_num(j, t, "ior_step", BL_F0_IOR_STEP);
    cJSON *values = soak_json_array(j, t, "values");
    for (int i = 0; i < BL_F0_N; ++i) {
        double f0 = 0.0;
        if (soak_fresnel_r0(BL_F0_IOR_FIRST + i * BL_F0_IOR_STEP, 0.0, &f0) != SOAK_OK) j->ok = 0;
        soak_json_num(j, values, NULL, f0);
    }
}

static void add_header(soak_json *j, cJSON *root, const soak_export_header *h)
{
    soak_json_str(j, root, "format", BL_FORMAT);
    soak_json_int(j, root, "format_version", BL_FORMAT_VERSION);
    soak_json_str(j, root, "generator", h->generator);
    soak_json_str(j, root, "materials_file", h->materials_file);
    soak_json_str(j, root, "materials_hash", h->materials_hash);
    soak_json_num(j, root, "tolerance", SOAK_EXPORT_BASE_TOL);
    soak_json_int(j, root, "view_columns", SOAK_EXPORT_VIEW_N);
    soak_json_str(j, root, "layout",
                  "per material and liquid: albedo[row][3*column+channel] and params[row][3*pixel+channel]. Column "
                  "j: s = j/(columns-1), dry albedo a = 1-(1-s)^2. Row r: delivered liquid L = "
                  "saturation*(r/rows_below)^2 for r <= rows_below, else "
                  "saturation+(1-saturation)*(r-rows_below)/rows_above. Channel c of the albedo pixel is the wet "
                  "albedo of channel c (under a coat of the liquid's IOR weighted by the film coverage) for dry "
                  "albedo a. params pixels: 0 = (roughness, film coverage, water specular weight), 1 = (pore fill, "
                  "specular weight, 0), 2 = thin-sheet transmittance, 3 = (the base's own specular under the liquid "
                  "over its dry value, the liquid mirror's weight = interface area, apparent roughness: conductors "
                  "seen through the film; see soak/wet_specular.h). view_factor[row][3*i+channel]: the preset's view "
                  "factor (soak_wetness_view_factor) at cos(view zenith) = i/16, the factor on the wet colour seen "
                  "along that view under uniform light. Interpolate bilinearly between pixel centres; max_error is "
                  "the worst error of that against the core, view_max_error the view factor's (views up to 75 deg, "
                  "times the wet albedo of a white dry colour: the error on the colour).");
    add_schedule_program(j, root);
    add_normal_reflectance(j, root);
}

soak_status soak_export_write_blender(const soak_preset_db *db, FILE *out, char *err, size_t errlen)
{
    soak_export_header h;
    soak_status st = soak_export_begin(db, out, err, errlen, &h);
    if (st != SOAK_OK) return st;
    cJSON *root = cJSON_CreateObject();
    if (!root) return SOAK_ERR_NOMEM;
    soak_json j = soak_json_writer(BL_DIGITS, BL_ZERO);
    add_header(&j, root, &h);
    cJSON *liquids = soak_json_array(&j, root, "liquids");
    for (int i = 0; i < soak_presets_liquid_count(db); ++i) {
        const soak_liquid *l = soak_presets_liquid_at(db, i);
        cJSON *o = soak_json_object(&j, liquids, NULL);
        soak_json_str(&j, o, "name", l->name);
        soak_json_str(&j, o, "display_name", l->display_name);
        soak_json_num(&j, o, "ior", l->ior);
    }
    cJSON *materials = soak_json_array(&j, root, "materials");
    for (int i = 0; st == SOAK_OK && j.ok && i < soak_presets_count(db); ++i)
        st = add_material(&j, materials, db, soak_presets_at(db, i), err, errlen);
    if (st == SOAK_OK) st = soak_json_write(&j, root, out);
    cJSON_Delete(root);
    if (st == SOAK_ERR_IO) snprintf(err, errlen, "write failed");
    return st;
}
