/* JSON export of the presets and their wetness tables for the front ends
 * (`soak materials --json --table N`). Field names carry their units. */
#include <cjson/cJSON.h>
#include <stdlib.h>
#include <string.h>

#include "soak/wetness.h"

/* Every add returns NULL on allocation failure; the caller checks once
 * through `ok` so the builder code stays linear. */
typedef struct builder {
    int ok;
} builder;

static void add_num(builder *b, cJSON *o, const char *key, double v)
{
    if (!cJSON_AddNumberToObject(o, key, v)) b->ok = 0;
}

static void add_str(builder *b, cJSON *o, const char *key, const char *v)
{
    if (!cJSON_AddStringToObject(o, key, v ? v : "")) b->ok = 0;
}

static void add_rgb(builder *b, cJSON *o, const char *key, soak_rgb c)
{
    double v[3] = {c.r, c.g, c.b};
    cJSON *a = cJSON_CreateDoubleArray(v, 3);
    if (!a || !cJSON_AddItemToObject(o, key, a)) {
        cJSON_Delete(a);
        b->ok = 0;
    }
}

static void add_phase(builder *b, cJSON *o, const char *key, const soak_hg2 *ph)
{
    cJSON *p = cJSON_AddObjectToObject(o, key);
    if (!p) {
        b->ok = 0;
        return;
    }
    add_num(b, p, "g1", ph->g1);
    add_num(b, p, "g2", ph->g2);
    add_num(b, p, "w", ph->w);
    add_num(b, p, "mean_cosine", soak_hg2_mean_cosine(ph));
}

static void add_row(builder *b, cJSON *rows, const soak_wet_params *r, int conductor)
{
    cJSON *o = cJSON_CreateObject();
    if (!o || !cJSON_AddItemToArray(rows, o)) {
        cJSON_Delete(o);
        b->ok = 0;
        return;
    }
    add_num(b, o, "wetness", r->wetness);
    add_num(b, o, "fill", r->fill);
    add_num(b, o, "film_coverage", r->film_coverage);
    add_rgb(b, o, "albedo", r->albedo);
    add_rgb(b, o, "albedo_total", r->albedo_total);
    add_rgb(b, o, "albedo_subsurface", r->albedo_subsurface);
    add_rgb(b, o, "albedo_film", r->albedo_film);
    add_num(b, o, "ggx_alpha", r->ggx_alpha);
    if (!conductor) {
        add_phase(b, o, "phase", &r->phase);
        add_rgb(b, o, "omega", r->omega);
        add_rgb(b, o, "sigma_s_per_mm", r->sigma_s);
        add_rgb(b, o, "sigma_a_per_mm", r->sigma_a);
    }
    add_num(b, o, "specular_weight", r->specular_weight);
    add_num(b, o, "water_specular_weight", r->water_specular_weight);
    add_num(b, o, "film_ior", r->film_ior);
    add_num(b, o, "film_thickness_m", r->film_thickness_m);
    add_rgb(b, o, "film_absorption_per_m", r->film_absorption_per_m);
}

static soak_status add_material(builder *b, cJSON *arr, const soak_preset *p, const soak_liquid *liq, int table_n,
                                soak_wet_params *rows)
{
    cJSON *o = cJSON_CreateObject();
    if (!o || !cJSON_AddItemToArray(arr, o)) {
        cJSON_Delete(o);
        return SOAK_ERR_NOMEM;
    }
    const int conductor = p->kind == SOAK_KIND_CONDUCTOR;
    const int porous = soak_material_kind_porous(p->kind);
    add_str(b, o, "name", p->name);
    add_str(b, o, "display_name", p->display_name);
    add_str(b, o, "kind", soak_material_kind_name(p->kind));
    add_rgb(b, o, "albedo", p->albedo);
    add_str(b, o, "albedo_source", p->albedo_source);
    add_num(b, o, "ggx_alpha_dry", p->ggx_alpha_dry);
    add_num(b, o, "ggx_alpha_wet", p->ggx_alpha_wet);
    add_str(b, o, "roughness_source", p->roughness_source);
    if (conductor) {
        add_rgb(b, o, "ior_n", p->ior_n);
        add_rgb(b, o, "ior_k", p->ior_k);
    } else {
        add_num(b, o, "ior", p->ior);
    }
    add_str(b, o, "ior_source", p->ior_source);
    add_num(b, o, "porosity", p->porosity);
    add_num(b, o, "saturation_wetness", porous ? p->porosity : 0.0);
    add_num(b, o, "s_p", p->s_p);
    if (porous) add_str(b, o, "porosity_source", p->porosity_source);
    if (!conductor) {
        add_rgb(b, o, "sigma_t_per_mm", p->sigma_t);
        add_rgb(b, o, "sigma_s_per_mm", p->sigma_s_dry);
        add_rgb(b, o, "sigma_a_per_mm", p->sigma_a_dry);
        add_rgb(b, o, "omega", p->omega_dry);
        add_str(b, o, "medium_source", p->medium_source);
        add_phase(b, o, "phase_dry", &p->phase_dry);
        add_phase(b, o, "phase_wet", &p->phase_wet);
        add_str(b, o, "phase_source", p->phase_source);
    }
    add_num(b, o, "t_fill", p->t_fill);
    add_num(b, o, "film_thickness_mm", p->film_thickness_mm);
    add_str(b, o, "wetting_source", p->wetting_source);
    add_num(b, o, "thickness_mm", p->thickness_mm);
    if (p->kind == SOAK_KIND_THIN_SHEET) add_str(b, o, "sheet_source", p->sheet_source);
    if (table_n >= 2) {
        soak_status st = soak_wetness_table(p, liq, table_n, -1.0, rows);
        if (st != SOAK_OK) return st;
        cJSON *t = cJSON_AddArrayToObject(o, "wetness_table");
        if (!t) return SOAK_ERR_NOMEM;
        for (int i = 0; i < table_n; ++i) add_row(b, t, &rows[i], conductor);
    }
    return b->ok ? SOAK_OK : SOAK_ERR_NOMEM;
}

static soak_status add_liquid(builder *b, cJSON *arr, const soak_liquid *l)
{
    cJSON *o = cJSON_CreateObject();
    if (!o || !cJSON_AddItemToArray(arr, o)) {
        cJSON_Delete(o);
        return SOAK_ERR_NOMEM;
    }
    add_str(b, o, "name", l->name);
    add_str(b, o, "display_name", l->display_name);
    add_num(b, o, "ior", l->ior);
    add_rgb(b, o, "sigma_a_per_mm", l->sigma_a);
    add_rgb(b, o, "sigma_s_per_mm", l->sigma_s);
    add_str(b, o, "source", l->source);
    return b->ok ? SOAK_OK : SOAK_ERR_NOMEM;
}

static soak_status build(cJSON *root, const soak_preset_db *db, const soak_liquid *liq, int table_n)
{
    builder b = {1};
    add_str(&b, root, "format", "soak-materials-export");
    add_num(&b, root, "version", 1);
    /* the file name only: an absolute build-machine path would make the
     * output differ between machines */
    const char *path = soak_presets_path(db), *slash = strrchr(path, '/');
    add_str(&b, root, "materials_file", slash ? slash + 1 : path);
    add_str(&b, root, "table_liquid", liq->name);
    add_num(&b, root, "table_rows", table_n >= 2 ? table_n : 0);
    add_str(&b, root, "table_note",
            "rows at wetness i/(rows-1), steady state (progress 1), preset film thickness; interpolate "
            "linearly in wetness. Each material's saturation_wetness (pores full, film starts) is a kink "
            "of the curves: use enough rows (17 or more). Chain documented in c_core/materials/include/soak/wetness.h.");
    cJSON *mats = cJSON_AddArrayToObject(root, "materials");
    cJSON *liqs = cJSON_AddArrayToObject(root, "liquids");
    if (!b.ok || !mats || !liqs) return SOAK_ERR_NOMEM;
    soak_wet_params *rows = NULL;
    if (table_n >= 2) {
        rows = malloc((size_t)table_n * sizeof *rows);
        if (!rows) return SOAK_ERR_NOMEM;
    }
    soak_status st = SOAK_OK;
    for (int i = 0; st == SOAK_OK && i < soak_presets_count(db); ++i)
        st = add_material(&b, mats, soak_presets_at(db, i), liq, table_n, rows);
    for (int i = 0; st == SOAK_OK && i < soak_presets_liquid_count(db); ++i)
        st = add_liquid(&b, liqs, soak_presets_liquid_at(db, i));
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
    soak_status st = build(root, db, liq, table_n);
    char *text = st == SOAK_OK ? cJSON_Print(root) : NULL;
    cJSON_Delete(root);
    if (st != SOAK_OK) return st;
    if (!text) return SOAK_ERR_NOMEM;
    *json = text;
    return SOAK_OK;
}
