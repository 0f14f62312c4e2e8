/* `soak materials --json [--table N]`: the presets, with their sources, and
 * optionally their wetness tables at uniform wetness, for people and scripts
 * (no front end reads it: they read `soak export`). Field names carry their
 * units, those of materials.json (mm, 1/mm: converted from the core's SI here,
 * soak/units.h) or SI where the key says _m; numbers are the doubles as
 * computed (soak/json_writer.h, digits 0). */
#include <stdlib.h>
#include <string.h>

#include "soak/json_writer.h"
#include "soak/preset_json.h"
#include "soak/units.h"
#include "soak/wetness.h"

static void add_phase(soak_json *j, cJSON *o, const char *key, const soak_hg2 *ph)
{
    cJSON *p = soak_json_object(j, o, key);
    if (!p) return;
    soak_json_num(j, p, "g1", ph->g1);
    soak_json_num(j, p, "g2", ph->g2);
    soak_json_num(j, p, "w", ph->w);
    soak_json_num(j, p, "mean_cosine", soak_hg2_mean_cosine(ph));
}

static void add_row(soak_json *j, cJSON *rows, const soak_wet_params *r, int conductor)
{
    cJSON *o = soak_json_object(j, rows, NULL);
    if (!o) return;
    soak_json_num(j, o, "wetness", r->wetness);
    soak_json_num(j, o, "fill", r->fill);
    soak_json_num(j, o, "film_coverage", r->film_coverage);
    soak_json_rgb(j, o, "albedo", r->albedo);
    soak_json_rgb(j, o, "albedo_total", r->albedo_total);
    soak_json_rgb(j, o, "albedo_subsurface", r->albedo_subsurface);
    soak_json_rgb(j, o, "albedo_film", r->albedo_film);
    soak_json_num(j, o, "ggx_alpha", r->ggx_alpha);
    if (!conductor) {
        add_phase(j, o, "phase", &r->phase);
        soak_json_rgb(j, o, "omega", r->omega);
        soak_json_rgb(j, o, "sigma_s_per_mm", soak_rgb_per_mm_from_per_m(r->sigma_s_per_m));
        soak_json_rgb(j, o, "sigma_a_per_mm", soak_rgb_per_mm_from_per_m(r->sigma_a_per_m));
    }
    soak_json_num(j, o, "specular_weight", r->specular_weight);
    soak_json_num(j, o, "water_specular_weight", r->water_specular_weight);
    soak_json_num(j, o, "film_ior", r->film_ior);
    soak_json_num(j, o, "film_thickness_m", r->film_thickness_m);
    soak_json_rgb(j, o, "film_absorption_per_m", r->film_absorption_per_m);
}

static soak_status add_material(soak_json *j, cJSON *arr, const soak_preset *p, const soak_liquid *liq, int table_n,
                                soak_wet_params *rows)
{
    cJSON *o = soak_json_object(j, arr, NULL);
    if (!o) return SOAK_ERR_NOMEM;
    const int conductor = p->kind == SOAK_KIND_CONDUCTOR;
    const int porous = soak_material_kind_porous(p->kind);
    soak_json_preset_optics(j, o, p, "albedo", 1);
    soak_json_num(j, o, "s_p", p->s_p);
    if (porous) soak_json_str(j, o, "porosity_source", p->porosity_source);
    if (!conductor) {
        soak_json_rgb(j, o, "sigma_t_per_mm", soak_rgb_per_mm_from_per_m(p->sigma_t_per_m));
        soak_json_rgb(j, o, "sigma_s_per_mm", soak_rgb_per_mm_from_per_m(p->sigma_s_dry_per_m));
        soak_json_rgb(j, o, "sigma_a_per_mm", soak_rgb_per_mm_from_per_m(p->sigma_a_dry_per_m));
        soak_json_rgb(j, o, "omega", p->omega_dry);
        soak_json_str(j, o, "medium_source", p->medium_source);
        add_phase(j, o, "phase_dry", &p->phase_dry);
        add_phase(j, o, "phase_wet", &p->phase_wet);
        soak_json_str(j, o, "phase_source", p->phase_source);
    }
    soak_json_num(j, o, "t_fill", p->t_fill);
    soak_json_num(j, o, "film_thickness_mm", soak_mm_from_m(p->film_thickness_m));
    soak_json_str(j, o, "wetting_source", p->wetting_source);
    soak_json_num(j, o, "thickness_mm", soak_mm_from_m(p->thickness_m));
    if (p->kind == SOAK_KIND_THIN_SHEET) soak_json_str(j, o, "sheet_source", p->sheet_source);
    if (table_n >= 2) {
        soak_status st = soak_wetness_table(p, liq, table_n, -1.0, rows);
        if (st != SOAK_OK) return st;
        cJSON *t = soak_json_array(j, o, "wetness_table");
        if (!t) return SOAK_ERR_NOMEM;
        for (int i = 0; i < table_n; ++i) add_row(j, t, &rows[i], conductor);
    }
    return j->ok ? SOAK_OK : SOAK_ERR_NOMEM;
}

static soak_status build(soak_json *j, cJSON *root, const soak_preset_db *db, const soak_liquid *liq, int table_n)
{
    soak_json_str(j, root, "format", "soak-materials-export");
    soak_json_int(j, root, "version", 1);
    /* the file name only: an absolute build-machine path would make the
     * output differ between machines */
    const char *path = soak_presets_path(db), *slash = strrchr(path, '/');
    soak_json_str(j, root, "materials_file", slash ? slash + 1 : path);
    soak_json_str(j, root, "table_liquid", liq->name);
    soak_json_int(j, root, "table_rows", table_n >= 2 ? table_n : 0);
    soak_json_str(j, root, "table_note",
            "rows at wetness i/(rows-1), steady state (progress 1), preset film thickness; interpolate "
            "linearly in wetness. Each material's saturation_wetness (pores full, film starts) is a kink "
            "of the curves: use enough rows (17 or more). Chain documented in c_core/materials/include/soak/wetness.h.");
    cJSON *mats = soak_json_array(j, root, "materials");
    cJSON *liqs = soak_json_array(j, root, "liquids");
    if (!j->ok || !mats || !liqs) return SOAK_ERR_NOMEM;
    soak_wet_params *rows = NULL;
    if (table_n >= 2) {
        rows = malloc((size_t)table_n * sizeof *rows);
        if (!rows) return SOAK_ERR_NOMEM;
    }
    soak_status st = SOAK_OK;
    for (int i = 0; st == SOAK_OK && i < soak_presets_count(db); ++i)
        st = add_material(j, mats, soak_presets_at(db, i), liq, table_n, rows);
    for (int i = 0; st == SOAK_OK && i < soak_presets_liquid_count(db); ++i)
        st = soak_json_liquid(j, liqs, soak_presets_liquid_at(db, i), SOAK_JSON_PER_MM, 0);
    free(rows);
    return st;
}

soak_status soak_wetness_export_json(const soak_preset_db *db, const char *liquid_name, int table_n, char **json)
{
    if (!db || !json) return SOAK_ERR_NULL;
    if (table_n != 0 && (table_n < 2 || table_n > SOAK_WET_TABLE_MAX)) return SOAK_ERR_ARG;
    const soak_liquid *liq = soak_presets_find_liquid(db, liquid_name ? liquid_name : "water");
    if (!liq) return SOAK_ERR_NOT_FOUND;
    cJSON *root = cJSON_CreateObject();
    if (!root) return SOAK_ERR_NOMEM;
    soak_json j = soak_json_writer(0, 0.0);
    soak_status st = build(&j, root, db, liq, table_n);
    if (st == SOAK_OK) st = soak_json_print(&j, root, json);
    cJSON_Delete(root);
    return st;
}
