/* soak export --target json: the generic interface for front ends
 * (schema: c_core/data/export.schema.json; contract: soak/export.h).
 * Column-oriented tables (one array per quantity, one entry per knot), SI
 * units named in the keys, numbers rounded to 7 significant digits
 * (soak/json_writer.h) so that the same input gives the same bytes on every
 * machine. */
#include <math.h>

#include "soak/export.h"
#include "soak/film.h"
#include "soak/fresnel.h"
#include "soak/json_writer.h"
#include "soak/preset_json.h"
#include "soak/sheet.h"

#define JSON_DIGITS 7

/* Mean free path 1 / sigma_t in metres; 0 where the medium does not
 * interact (no scattering, no absorption). */
static soak_rgb mean_free_path_m(soak_rgb ss, soak_rgb sa)
{
    soak_rgb m;
    for (int i = 0; i < 3; ++i) {
        double t = soak_rgb_at(ss, i) + soak_rgb_at(sa, i);
        soak_rgb_set(&m, i, t > 0.0 ? 1.0 / t : 0.0);
    }
    return m;
}

/* ---- per knot ------------------------------------------------------------ */

enum col_id {
    C_WETNESS, C_FILL, C_COVERAGE, C_ALBEDO, C_ALBEDO_TOTAL, C_ALBEDO_SUB, C_ALBEDO_FILM, C_ALPHA, C_ROUGHNESS,
    C_SPEC_W, C_WATER_SPEC_W, C_G1, C_G2, C_W, C_MEAN_COS, C_OMEGA, C_SIGMA_S, C_SIGMA_A, C_MFP, C_SHEET_T, C_VIEW,
    C_COUNT
};

static const char *const col_names[C_COUNT] = {
    "wetness", "pore_fill", "film_coverage", "albedo", "albedo_total", "albedo_subsurface", "albedo_film",
    "ggx_alpha", "roughness", "specular_weight", "water_specular_weight", "phase_g1", "phase_g2", "phase_w",
    "mean_cosine", "single_scattering_albedo", "sigma_s_per_m", "sigma_a_per_m", "mean_free_path_m",
    "sheet_transmittance", "view_factor"};

static int column_applies(int c, soak_material_kind kind)
{
    if (c == C_VIEW) return 1; /* conductors: all ones (normal-incidence model) */
    if (kind == SOAK_KIND_CONDUCTOR && c >= C_G1) return 0;
    if (c == C_SHEET_T) return kind == SOAK_KIND_THIN_SHEET;
    return 1;
}

static void push_view(soak_json *j, cJSON *col, const soak_rgb view[SOAK_EXPORT_VIEW_N])
{
    cJSON *row = soak_json_array(j, col, NULL);
    for (int i = 0; row && i < SOAK_EXPORT_VIEW_N; ++i) soak_json_rgb(j, row, NULL, view[i]);
}

static void push_row(soak_json *j, cJSON *cols[C_COUNT], const soak_wet_params *p, const soak_rgb *sheet_t,
                     const soak_rgb view[SOAK_EXPORT_VIEW_N])
{
    double scalars[C_COUNT] = {0};
    scalars[C_WETNESS] = p->wetness;
    scalars[C_FILL] = p->fill;
    scalars[C_COVERAGE] = p->film_coverage;
    scalars[C_ALPHA] = p->ggx_alpha;
    scalars[C_ROUGHNESS] = sqrt(p->ggx_alpha);
    scalars[C_SPEC_W] = p->specular_weight;
    scalars[C_WATER_SPEC_W] = p->water_specular_weight;
    scalars[C_G1] = p->phase.g1;
    scalars[C_G2] = p->phase.g2;
    scalars[C_W] = p->phase.w;
    scalars[C_MEAN_COS] = p->mean_cosine;
    for (int c = 0; c < C_COUNT; ++c) {
        if (!cols[c]) continue;
        switch (c) {
        case C_ALBEDO: soak_json_rgb(j, cols[c], NULL, p->albedo); break;
        case C_ALBEDO_TOTAL: soak_json_rgb(j, cols[c], NULL, p->albedo_total); break;
        case C_ALBEDO_SUB: soak_json_rgb(j, cols[c], NULL, p->albedo_subsurface); break;
        case C_ALBEDO_FILM: soak_json_rgb(j, cols[c], NULL, p->albedo_film); break;
        case C_OMEGA: soak_json_rgb(j, cols[c], NULL, p->omega); break;
        case C_SIGMA_S: soak_json_rgb(j, cols[c], NULL, p->sigma_s_per_m); break;
        case C_SIGMA_A: soak_json_rgb(j, cols[c], NULL, p->sigma_a_per_m); break;
        case C_MFP: soak_json_rgb(j, cols[c], NULL, mean_free_path_m(p->sigma_s_per_m, p->sigma_a_per_m)); break;
        case C_SHEET_T: soak_json_rgb(j, cols[c], NULL, *sheet_t); break;
        case C_VIEW: push_view(j, cols[c], view); break;
        default: soak_json_num(j, cols[c], NULL, scalars[c]);
        }
    }
}

static soak_status add_knot_table(soak_json *j, cJSON *o, const soak_preset *p, const soak_liquid *l)
{
    double knots[SOAK_EXPORT_KNOTS_MAX];
    int n = 0;
    soak_status st = soak_export_knots(p, l, -1.0, knots, SOAK_EXPORT_KNOTS_MAX, &n);
    if (st != SOAK_OK) return st;
    cJSON *t = soak_json_object(j, o, "knots");
    if (!t) return SOAK_ERR_NOMEM;
    cJSON *cols[C_COUNT] = {0};
    for (int c = 0; c < C_COUNT; ++c)
        if (column_applies(c, p->kind)) cols[c] = soak_json_array(j, t, col_names[c]);
    for (int i = 0; st == SOAK_OK && i < n; ++i) {
        soak_wet_input in = soak_wet_input_steady(p, knots[i]);
        soak_wet_params w;
        soak_rgb sheet_t = {0, 0, 0}, view[SOAK_EXPORT_VIEW_N];
        st = soak_wetness_eval(p, l, &in, &w);
        if (st == SOAK_OK && p->kind == SOAK_KIND_THIN_SHEET) st = soak_sheet_transmittance(&w, p->thickness_m, p->ior, &sheet_t);
        if (st == SOAK_OK) st = soak_export_view_factors(p, l, &w, view);
        if (st == SOAK_OK) push_row(j, cols, &w, &sheet_t, view);
    }
    return st;
}

/* ---- the wetness function for any base colour ------------------------------ */

static soak_status add_base_table(soak_json *j, cJSON *o, const soak_preset *p, const soak_liquid *l)
{
    double a[SOAK_EXPORT_KNOTS_MAX], w[SOAK_EXPORT_KNOTS_MAX];
    int na = 0, nw = 0;
    soak_status st = soak_export_base_nodes(p, l, a, SOAK_EXPORT_KNOTS_MAX, &na, w, SOAK_EXPORT_KNOTS_MAX, &nw);
    if (st != SOAK_OK) return st;
    cJSON *t = soak_json_object(j, o, "base_colour");
    if (!t) return SOAK_ERR_NOMEM;
    soak_json_num(j, t, "tolerance", SOAK_EXPORT_BASE_TOL);
    cJSON *ja = soak_json_array(j, t, "dry_albedo"), *jw = soak_json_array(j, t, "wetness");
    for (int i = 0; i < na; ++i) soak_json_num(j, ja, NULL, a[i]);
    for (int i = 0; i < nw; ++i) soak_json_num(j, jw, NULL, w[i]);
    const char *keys[2] = {"albedo", "albedo_total"};
    for (int k = 0; st == SOAK_OK && k < 2; ++k) {
        cJSON *per_channel = soak_json_array(j, t, keys[k]);
        for (int c = 0; st == SOAK_OK && c < 3; ++c) {
            cJSON *rows = soak_json_array(j, per_channel, NULL);
            if (!rows) return SOAK_ERR_NOMEM;
            for (int iw = 0; st == SOAK_OK && iw < nw; ++iw) {
                cJSON *row = soak_json_array(j, rows, NULL);
                if (!row) return SOAK_ERR_NOMEM;
                soak_wet_input in = soak_wet_input_steady(p, w[iw]);
                for (int ia = 0; st == SOAK_OK && ia < na; ++ia) {
                    soak_wet_params out;
                    st = soak_wet_params_for_base(p, l, &in, (soak_rgb){a[ia], a[ia], a[ia]}, &out);
                    if (st == SOAK_OK) soak_json_num(j, row, NULL, soak_rgb_at(k ? out.albedo_total : out.albedo, c));
                }
            }
        }
    }
    return st;
}

/* ---- materials and liquids ---------------------------------------------------- */

static soak_status add_material(soak_json *j, cJSON *list, const soak_preset_db *db, const soak_preset *p)
{
    cJSON *o = soak_json_object(j, list, NULL);
    if (!o) return SOAK_ERR_NOMEM;
    const int conductor = p->kind == SOAK_KIND_CONDUCTOR;
    soak_json_preset_optics(j, o, p, "dry_albedo", 0);
    soak_json_num(j, o, "t_fill", p->t_fill);
    soak_json_num(j, o, "film_thickness_m", p->film_thickness_m);
    soak_json_num(j, o, "sheet_thickness_m", p->thickness_m);
    cJSON *tables = soak_json_object(j, o, "liquids");
    if (!tables) return SOAK_ERR_NOMEM;
    soak_status st = SOAK_OK;
    for (int i = 0; st == SOAK_OK && i < soak_presets_liquid_count(db); ++i) {
        const soak_liquid *l = soak_presets_liquid_at(db, i);
        cJSON *t = soak_json_object(j, tables, l->name);
        if (!t) return SOAK_ERR_NOMEM;
        if (conductor) {
            /* the metal seen from inside the liquid: relative complex index */
            soak_json_rgb(j, t, "ior_n_under_liquid", soak_rgb_scale(p->ior_n, 1.0 / l->ior));
            soak_json_rgb(j, t, "ior_k_under_liquid", soak_rgb_scale(p->ior_k, 1.0 / l->ior));
        }
        st = add_knot_table(j, t, p, l);
        if (st == SOAK_OK) st = add_base_table(j, t, p, l);
    }
    return st != SOAK_OK ? st : (j->ok ? SOAK_OK : SOAK_ERR_NOMEM);
}

static void add_header(soak_json *j, cJSON *root, const soak_export_header *h)
{
    soak_json_str(j, root, "format", SOAK_EXPORT_FORMAT);
    soak_json_int(j, root, "format_version", h->format_version);
    soak_json_str(j, root, "generator", h->generator);
    soak_json_str(j, root, "materials_file", h->materials_file);
    soak_json_str(j, root, "materials_hash", h->materials_hash);
    soak_json_num(j, root, "knot_tolerance", SOAK_EXPORT_KNOT_TOL);
    soak_json_num(j, root, "base_colour_tolerance", SOAK_EXPORT_BASE_TOL);
    cJSON *view_cos = soak_json_array(j, root, "view_cos");
    for (int i = 0; view_cos && i < SOAK_EXPORT_VIEW_N; ++i) soak_json_num(j, view_cos, NULL, (double)i / (SOAK_EXPORT_VIEW_N - 1));
    cJSON *notes = soak_json_object(j, root, "notes");
    if (!notes) return;
    soak_json_str(j, notes, "interpolation",
        "materials[].liquids[L].knots: one array per quantity over the wetness knots (non-uniform, including "
        "the saturation wetness where the pores are full and a film starts); interpolate linearly in wetness. "
        "base_colour: the wetness function for any dry base colour, per channel [channel][wetness][dry_albedo]; "
        "interpolate bilinearly. knots.view_factor: per knot, the factor on the colour seen along a view "
        "direction with cos(view zenith) = view_cos[i] under uniform light (soak_wetness_view_factor: the liquid "
        "interface's angular transmission towards the viewer; cosine-weighted mean 1); interpolate linearly in "
        "view_cos and wetness.");
    soak_json_str(j, notes, "drying",
        "Tables are at steady state. The pore-filling schedule (Hnat et al. 2006) only scales the delivered "
        "liquid: L = wetness * clamp((time - t0) / t_fill, 0, 1) (a step at t0 when t_fill = 0); every quantity "
        "depends on wetness and time only through L, so look the tables up at L.");
    soak_json_str(j, notes, "units",
        "colours: linear RGB (Rec.709 primaries); lengths: m; coefficients: 1/m; roughness = sqrt(ggx_alpha).");
    soak_json_str(j, notes, "chain", "c_core/materials/include/soak/wetness.h (steps 1-6) and c_core/export/include/soak/export.h");
}

soak_status soak_export_write_json(const soak_preset_db *db, FILE *out, char *err, size_t errlen)
{
    soak_export_header h;
    soak_status st = soak_export_begin(db, out, err, errlen, &h);
    if (st != SOAK_OK) return st;
    cJSON *root = cJSON_CreateObject();
    if (!root) return SOAK_ERR_NOMEM;
    soak_json j = soak_json_writer(JSON_DIGITS, 0.0);
    add_header(&j, root, &h);
    cJSON *liquids = soak_json_array(&j, root, "liquids"), *materials = soak_json_array(&j, root, "materials");
    for (int i = 0; st == SOAK_OK && j.ok && i < soak_presets_liquid_count(db); ++i)
        st = soak_json_liquid(&j, liquids, soak_presets_liquid_at(db, i), SOAK_JSON_PER_M, 1);
    for (int i = 0; st == SOAK_OK && j.ok && i < soak_presets_count(db); ++i) {
        st = add_material(&j, materials, db, soak_presets_at(db, i));
        if (st != SOAK_OK) snprintf(err, errlen, "preset '%s': %s", soak_presets_at(db, i)->name, soak_status_str(st));
    }
    if (st == SOAK_OK) st = soak_json_write(&j, root, out);
    cJSON_Delete(root);
    if (st == SOAK_ERR_IO) snprintf(err, errlen, "write failed");
    return st;
}
