/* The preset file's schema (documented in soak/preset.h) read into the
 * database: every group of every material and liquid checked, through the
 * JSON reader all of soak's files share (soak/json_read.h); every error
 * names file, JSON path and reason. */
#define _POSIX_C_SOURCE 200809L
#include <cjson/cJSON.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "soak/fresnel.h"
#include "soak/hg.h"
#include "soak/json_read.h"
#include "soak/preset.h"
#include "soak/units.h"

#include "preset_db.h"

#define MAX_ENTRIES 1024
#define PATH_MAX_LEN 160
/* A conductor's albedo must equal F0(n, k) to this tolerance per channel. */
#define CONDUCTOR_F0_TOL 2e-3

typedef struct ctx {
    const char *file;
    char *err;
    size_t errlen;
    soak_preset_db *db;
} ctx;

static const char *kind_names[] = {"porous_dielectric", "nonporous_dielectric", "conductor", "thin_sheet"};

const char *soak_material_kind_name(soak_material_kind kind)
{
    return (int)kind >= 0 && (int)kind < 4 ? kind_names[kind] : "unknown";
}

int soak_material_kind_porous(soak_material_kind kind)
{
    return kind == SOAK_KIND_POROUS_DIELECTRIC || kind == SOAK_KIND_THIN_SHEET;
}

soak_status soak_preset_db_keep(soak_preset_db *db, const char *s, const char **out)
{
    if (db->n_strings == db->cap_strings) {
        int cap = db->cap_strings ? 2 * db->cap_strings : 64;
        char **grown = realloc(db->strings, (size_t)cap * sizeof *grown);
        if (!grown) return SOAK_ERR_NOMEM;
        db->strings = grown;
        db->cap_strings = cap;
    }
    char *copy = strdup(s);
    if (!copy) return SOAK_ERR_NOMEM;
    db->strings[db->n_strings++] = copy;
    *out = copy;
    return SOAK_OK;
}

static soak_json_in in_of(const ctx *c) { return (soak_json_in){c->file, c->err, c->errlen}; }

__attribute__((format(printf, 4, 5))) static soak_status fail(ctx *c, soak_status st, const char *path, const char *fmt,
                                                              ...)
{
    va_list ap;
    va_start(ap, fmt);
    soak_verror_at(c->err, c->errlen, st, c->file, path, fmt, ap);
    va_end(ap);
    return st;
}

/* JSON paths longer than PATH_MAX_LEN are cut short; the schema's are far shorter. */
__attribute__((format(printf, 2, 3))) static void path_printf(char *out, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(out, PATH_MAX_LEN, fmt, ap);
    va_end(ap);
}

static void join(char *out, const char *base, const char *key) { soak_json_path(out, PATH_MAX_LEN, base, key); }

/* obj must be an object whose keys are all in `allowed` (every one
 * present), without duplicates. Keys in `known` but not `allowed` are
 * reported as not used by `why`. */
static soak_status check_object(ctx *c, const cJSON *obj, const char *path, const char *const *allowed,
                                const char *const *known, const char *why)
{
    soak_json_in in = in_of(c);
    return soak_json_keys(&in, obj, path, allowed, known, why, 1);
}

static soak_status get_number(ctx *c, const cJSON *obj, const char *path, const char *key, double lo, double hi,
                              double *out)
{
    soak_json_in in = in_of(c);
    return soak_json_get_number(&in, obj, key, path, lo, hi, 0, 1, 0.0, out);
}

static soak_status get_rgb(ctx *c, const cJSON *obj, const char *path, const char *key, double lo, double hi,
                           soak_rgb *out)
{
    soak_json_in in = in_of(c);
    return soak_json_get_rgb(&in, obj, key, path, lo, hi, 0, 1, soak_rgb3(0.0, 0.0, 0.0), out);
}

/* A string kept in the database (it outlives the JSON tree). */
static soak_status get_string(ctx *c, const cJSON *obj, const char *path, const char *key, const char **out)
{
    soak_json_in in = in_of(c);
    const char *s = NULL;
    soak_status st = soak_json_get_string(&in, obj, key, path, 1, &s);
    if (st != SOAK_OK) return st;
    char sub[PATH_MAX_LEN];
    join(sub, path, key);
    if (strlen(s) >= SOAK_PRESET_TEXT_MAX)
        return fail(c, SOAK_ERR_ARG, sub, "longer than %d characters", SOAK_PRESET_TEXT_MAX - 1);
    st = soak_preset_db_keep(c->db, s, out);
    return st == SOAK_OK ? st : fail(c, st, sub, "out of memory");
}

static soak_status get_name(ctx *c, const cJSON *obj, const char *path, const char **out)
{
    soak_status st = get_string(c, obj, path, "name", out);
    if (st != SOAK_OK) return st;
    char sub[PATH_MAX_LEN];
    join(sub, path, "name");
    size_t n = strlen(*out);
    if (n >= SOAK_PRESET_NAME_MAX)
        return fail(c, SOAK_ERR_ARG, sub, "'%s' is longer than %d characters", *out, SOAK_PRESET_NAME_MAX - 1);
    for (const char *p = *out; *p; ++p)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= '0' && *p <= '9') || *p == '_' || *p == '-'))
            return fail(c, SOAK_ERR_ARG, sub, "'%s' may only use a-z, 0-9, '_' and '-'", *out);
    return SOAK_OK;
}

static soak_status get_phase(ctx *c, const cJSON *obj, const char *path, const char *key, soak_hg2 *out)
{
    static const char *const keys[] = {"g1", "g2", "w", NULL};
    char sub[PATH_MAX_LEN];
    join(sub, path, key);
    const cJSON *it = cJSON_GetObjectItemCaseSensitive(obj, key);
    soak_status st = check_object(c, it, sub, keys, NULL, NULL);
    if (st == SOAK_OK) st = get_number(c, it, sub, "g1", -SOAK_HG_G_MAX, SOAK_HG_G_MAX, &out->g1);
    if (st == SOAK_OK) st = get_number(c, it, sub, "g2", -SOAK_HG_G_MAX, SOAK_HG_G_MAX, &out->g2);
    if (st == SOAK_OK) st = get_number(c, it, sub, "w", 0.0, 1.0, &out->w);
    return st;
}

/* Opens group `key` of a material and checks its keys for this kind. */
static soak_status open_group(ctx *c, const cJSON *m, const char *path, const char *key, const char *const *allowed,
                              const char *const *known, const char *why, const cJSON **group, char *gpath)
{
    join(gpath, path, key);
    *group = cJSON_GetObjectItemCaseSensitive(m, key);
    return check_object(c, *group, gpath, allowed, known, why);
}

/* The optional "measured" group (see soak/preset.h). */
static soak_status parse_measured(ctx *c, const cJSON *m, const char *path, soak_preset *p)
{
    static const char *const keys[] = {"wet_dry_ratio", "spread",         "dry_albedo", "wetness",
                                       "quantity",      "sun_zenith_deg", "source",     NULL};
    const cJSON *g = NULL;
    char gp[PATH_MAX_LEN];
    const char *quantity = NULL;
    soak_status st = open_group(c, m, path, "measured", keys, NULL, "measured", &g, gp);
    if (st == SOAK_OK) st = get_number(c, g, gp, "wet_dry_ratio", 0.0, 10.0, &p->measured_ratio);
    if (st == SOAK_OK) st = get_number(c, g, gp, "spread", 0.0, 1.0, &p->measured_spread);
    if (st == SOAK_OK) st = get_number(c, g, gp, "dry_albedo", 1e-6, 1.0, &p->measured_dry_albedo);
    if (st == SOAK_OK) st = get_number(c, g, gp, "wetness", 0.0, 1.0, &p->measured_wetness);
    if (st == SOAK_OK) st = get_string(c, g, gp, "quantity", &quantity);
    /* Every measurement states its light (docs/calibration.md). */
    if (st == SOAK_OK) st = get_number(c, g, gp, "sun_zenith_deg", 0.0, 90.0, &p->measured_sun_zenith_deg);
    if (st == SOAK_OK) st = get_string(c, g, gp, "source", &p->measured_source);
    if (st != SOAK_OK) return st;
    if (strcmp(quantity, "albedo_total") != 0 && strcmp(quantity, "albedo") != 0) {
        char sub[PATH_MAX_LEN];
        join(sub, gp, "quantity");
        return fail(c, SOAK_ERR_ARG, sub, "'%s' is not one of albedo_total, albedo", quantity);
    }
    p->measured_total = strcmp(quantity, "albedo_total") == 0;
    p->has_measured = 1;
    return SOAK_OK;
}

/* One material object being read: its kind decides which groups it has. */
typedef struct mat_reader {
    ctx *c;
    const cJSON *m;
    const char *path;
    char why[64]; /* "kind <name>", for keys a kind does not use */
    int porous, conductor, sheet;
} mat_reader;

/* Opens group `key` of the material; `known`: the keys of every kind. */
static soak_status open_material_group(const mat_reader *r, const char *key, const char *const *allowed,
                                       const char *const *known, const cJSON **group, char *gpath)
{
    return open_group(r->c, r->m, r->path, key, allowed, known, r->why, group, gpath);
}

/* "kind", read first: it decides which groups are required. */
static soak_status parse_kind(ctx *c, const cJSON *m, const char *path, soak_preset *p)
{
    const cJSON *kind = cJSON_GetObjectItemCaseSensitive(m, "kind");
    char kpath[PATH_MAX_LEN];
    join(kpath, path, "kind");
    if (!kind) return fail(c, SOAK_ERR_PARSE, kpath, "missing (required)");
    if (!cJSON_IsString(kind)) return fail(c, SOAK_ERR_PARSE, kpath, "must be a non-empty string");
    int k = -1;
    for (int i = 0; i < 4; ++i)
        if (strcmp(kind->valuestring, soak_material_kind_name((soak_material_kind)i)) == 0) k = i;
    if (k < 0)
        return fail(c, SOAK_ERR_ARG, kpath,
                    "'%s' is not one of porous_dielectric, nonporous_dielectric, conductor, thin_sheet",
                    kind->valuestring);
    p->kind = (soak_material_kind)k;
    return SOAK_OK;
}

/* The material's keys: the groups of its kind, "measured" when present. */
static soak_status check_material_keys(const mat_reader *r, int measured)
{
    static const char *const all_keys[] = {"name",  "display_name", "kind",   "albedo", "roughness",
                                           "ior",   "porosity",     "medium", "phase",  "wetting",
                                           "sheet", "measured",     NULL};
    static const char *const head_keys[] = {"name", "display_name", "kind", NULL};
    const char *keys[17];
    int nk = 0;
    for (int i = 0; head_keys[i]; ++i) keys[nk++] = head_keys[i];
    keys[nk++] = "albedo";
    keys[nk++] = "roughness";
    keys[nk++] = "ior";
    keys[nk++] = "wetting";
    if (r->porous) keys[nk++] = "porosity";
    if (!r->conductor) keys[nk++] = "medium";
    if (!r->conductor) keys[nk++] = "phase";
    if (r->sheet) keys[nk++] = "sheet";
    if (measured) keys[nk++] = "measured"; /* optional for every kind */
    keys[nk] = NULL;
    return check_object(r->c, r->m, r->path, keys, all_keys, r->why);
}

static soak_status parse_albedo_group(const mat_reader *r, soak_preset *p)
{
    static const char *const albedo_keys[] = {"rgb", "source", NULL};
    const cJSON *g = NULL;
    char gp[PATH_MAX_LEN];
    soak_status st = open_material_group(r, "albedo", albedo_keys, NULL, &g, gp);
    if (st == SOAK_OK) st = get_rgb(r->c, g, gp, "rgb", 0.0, 1.0, &p->albedo);
    if (st == SOAK_OK) st = get_string(r->c, g, gp, "source", &p->albedo_source);
    return st;
}

/* Dry roughness; porous kinds also a wet one, never rougher (filled pores
 * only smooth a surface). */
static soak_status parse_roughness_group(const mat_reader *r, soak_preset *p)
{
    static const char *const rough_all[] = {"ggx_alpha_dry", "ggx_alpha_wet", "source", NULL};
    static const char *const rough_dry[] = {"ggx_alpha_dry", "source", NULL};
    const cJSON *g = NULL;
    char gp[PATH_MAX_LEN];
    soak_status st = open_material_group(r, "roughness", r->porous ? rough_all : rough_dry, rough_all, &g, gp);
    if (st == SOAK_OK) st = get_number(r->c, g, gp, "ggx_alpha_dry", 1e-4, 1.0, &p->ggx_alpha_dry);
    p->ggx_alpha_wet = p->ggx_alpha_dry;
    if (st == SOAK_OK && r->porous) {
        st = get_number(r->c, g, gp, "ggx_alpha_wet", 1e-4, 1.0, &p->ggx_alpha_wet);
        if (st == SOAK_OK && p->ggx_alpha_wet > p->ggx_alpha_dry) {
            char sub[PATH_MAX_LEN];
            join(sub, gp, "ggx_alpha_wet");
            return fail(r->c, SOAK_ERR_ARG, sub, "%g exceeds ggx_alpha_dry %g (filled pores only smooth a surface)",
                        p->ggx_alpha_wet, p->ggx_alpha_dry);
        }
    }
    if (st == SOAK_OK) st = get_string(r->c, g, gp, "source", &p->roughness_source);
    return st;
}

/* A conductor's albedo must be the normal-incidence reflectance of its n, k. */
static soak_status check_conductor_albedo(const mat_reader *r, const soak_preset *p)
{
    for (int i = 0; i < 3; ++i) {
        double f0 = 0.0;
        soak_fresnel_r0(soak_rgb_at(p->ior_n, i), soak_rgb_at(p->ior_k, i), &f0);
        if (!soak_in_range(soak_rgb_at(p->albedo, i) - f0, -CONDUCTOR_F0_TOL, CONDUCTOR_F0_TOL)) {
            char sub[PATH_MAX_LEN];
            path_printf(sub, "%s.albedo.rgb[%d]", r->path, i);
            return fail(r->c, SOAK_ERR_ARG, sub,
                        "%.6g differs from the normal-incidence reflectance %.6f of ior.n, ior.k by more than %g",
                        soak_rgb_at(p->albedo, i), f0, CONDUCTOR_F0_TOL);
        }
    }
    return SOAK_OK;
}

/* Conductors: RGB n and k; dielectrics: one n. */
static soak_status parse_ior_group(const mat_reader *r, soak_preset *p)
{
    static const char *const ior_all[] = {"n", "k", "source", NULL};
    static const char *const ior_diel[] = {"n", "source", NULL};
    const cJSON *g = NULL;
    char gp[PATH_MAX_LEN];
    soak_status st = open_material_group(r, "ior", r->conductor ? ior_all : ior_diel, ior_all, &g, gp);
    if (st == SOAK_OK && r->conductor) {
        st = get_rgb(r->c, g, gp, "n", 0.01, 100.0, &p->ior_n);
        if (st == SOAK_OK) st = get_rgb(r->c, g, gp, "k", 0.0, 100.0, &p->ior_k);
        if (st == SOAK_OK) st = check_conductor_albedo(r, p);
    } else if (st == SOAK_OK) {
        st = get_number(r->c, g, gp, "n", 1.0, 3.0, &p->ior);
    }
    if (st == SOAK_OK) st = get_string(r->c, g, gp, "source", &p->ior_source);
    return st;
}

static soak_status parse_porosity_group(const mat_reader *r, soak_preset *p)
{
    static const char *const poro_keys[] = {"alpha", "s_p", "source", NULL};
    const cJSON *g = NULL;
    char gp[PATH_MAX_LEN];
    soak_status st = open_material_group(r, "porosity", poro_keys, NULL, &g, gp);
    if (st == SOAK_OK) st = get_number(r->c, g, gp, "alpha", 1e-3, 0.95, &p->porosity);
    if (st == SOAK_OK) st = get_number(r->c, g, gp, "s_p", 0.01, 100.0, &p->s_p);
    if (st == SOAK_OK) st = get_string(r->c, g, gp, "source", &p->porosity_source);
    return st;
}

/* Dielectrics' medium: extinction, then the phase function (dry; porous
 * kinds also wet). */
static soak_status parse_medium_groups(const mat_reader *r, soak_preset *p)
{
    static const char *const medium_keys[] = {"sigma_t_per_mm", "source", NULL};
    static const char *const phase_all[] = {"dry", "wet", "source", NULL};
    static const char *const phase_dry[] = {"dry", "source", NULL};
    const cJSON *g = NULL;
    char gp[PATH_MAX_LEN];
    soak_status st = open_material_group(r, "medium", medium_keys, NULL, &g, gp);
    soak_rgb sigma_t_per_mm = {0.0, 0.0, 0.0};
    if (st == SOAK_OK) st = get_rgb(r->c, g, gp, "sigma_t_per_mm", 1e-6, 1e5, &sigma_t_per_mm);
    p->sigma_t_per_m = soak_rgb_per_m_from_per_mm(sigma_t_per_mm);
    if (st == SOAK_OK) st = get_string(r->c, g, gp, "source", &p->medium_source);
    if (st != SOAK_OK) return st;
    st = open_material_group(r, "phase", r->porous ? phase_all : phase_dry, phase_all, &g, gp);
    if (st == SOAK_OK) st = get_phase(r->c, g, gp, "dry", &p->phase_dry);
    p->phase_wet = p->phase_dry;
    if (st == SOAK_OK && r->porous) st = get_phase(r->c, g, gp, "wet", &p->phase_wet);
    if (st == SOAK_OK) st = get_string(r->c, g, gp, "source", &p->phase_source);
    return st;
}

static soak_status parse_wetting_group(const mat_reader *r, soak_preset *p)
{
    static const char *const wet_all[] = {"t_fill", "film_thickness_mm", "source", NULL};
    static const char *const wet_film[] = {"film_thickness_mm", "source", NULL};
    static const char *const wet_all_ca[] = {
        "t_fill", "film_thickness_mm", "source", "contact_angle_deg", "contact_angle_source", NULL};
    static const char *const wet_film_ca[] = {"film_thickness_mm", "source", "contact_angle_deg",
                                              "contact_angle_source", NULL};
    const cJSON *w = cJSON_GetObjectItemCaseSensitive(r->m, "wetting");
    const int ca = cJSON_IsObject(w) && (cJSON_GetObjectItemCaseSensitive(w, "contact_angle_deg") ||
                                         cJSON_GetObjectItemCaseSensitive(w, "contact_angle_source"));
    const cJSON *g = NULL;
    char gp[PATH_MAX_LEN];
    soak_status st = open_material_group(
        r, "wetting", r->porous ? (ca ? wet_all_ca : wet_all) : (ca ? wet_film_ca : wet_film), wet_all_ca, &g, gp);
    if (st == SOAK_OK && r->porous) st = get_number(r->c, g, gp, "t_fill", 0.0, 1e6, &p->t_fill);
    double film_mm = 0.0;
    if (st == SOAK_OK) st = get_number(r->c, g, gp, "film_thickness_mm", 0.0, 1000.0, &film_mm);
    p->film_thickness_m = soak_m_from_mm(film_mm);
    if (st == SOAK_OK) st = get_string(r->c, g, gp, "source", &p->wetting_source);
    /* Optional pair (soak/preset.h): water's contact angle and its source, both or neither. */
    p->contact_angle_deg = -1.0;
    p->contact_angle_source = NULL;
    if (st == SOAK_OK && ca) st = get_number(r->c, g, gp, "contact_angle_deg", 0.0, 180.0, &p->contact_angle_deg);
    if (st == SOAK_OK && ca) st = get_string(r->c, g, gp, "contact_angle_source", &p->contact_angle_source);
    return st;
}

/* A sheet's thickness: given, or the grammage over the bulk density (ISO 534's
 * apparent density: 80 g/m^2 at 800 kg/m^3 is 0.1 mm), one or the other. */
static soak_status parse_sheet_group(const mat_reader *r, soak_preset *p)
{
    static const char *const all_keys[] = {"thickness_mm", "grammage_g_m2", "density_kg_m3", "source", NULL};
    static const char *const given_keys[] = {"thickness_mm", "source", NULL};
    static const char *const mass_keys[] = {"grammage_g_m2", "density_kg_m3", "source", NULL};
    const cJSON *sheet = cJSON_GetObjectItemCaseSensitive(r->m, "sheet");
    const int by_mass = cJSON_IsObject(sheet) && cJSON_GetObjectItemCaseSensitive(sheet, "grammage_g_m2") != NULL;
    const cJSON *g = NULL;
    char gp[PATH_MAX_LEN];
    soak_status st = open_material_group(r, "sheet", by_mass ? mass_keys : given_keys, all_keys, &g, gp);
    double sheet_mm = 0.0, g_m2 = 0.0, kg_m3 = 0.0;
    if (st == SOAK_OK && !by_mass) {
        st = get_number(r->c, g, gp, "thickness_mm", 1e-3, 1000.0, &sheet_mm);
        p->thickness_m = soak_m_from_mm(sheet_mm);
    } else if (st == SOAK_OK) {
        st = get_number(r->c, g, gp, "grammage_g_m2", 1.0, 1e5, &g_m2);
        if (st == SOAK_OK) st = get_number(r->c, g, gp, "density_kg_m3", 10.0, 1e4, &kg_m3);
        p->thickness_m = 1e-3 * g_m2 / kg_m3; /* g/m^2 -> kg/m^2, over kg/m^3 */
    }
    if (st == SOAK_OK) st = get_string(r->c, g, gp, "source", &p->sheet_source);
    return st;
}

static soak_status parse_material(ctx *c, const cJSON *m, const char *path, soak_preset *p)
{
    if (!cJSON_IsObject(m)) return fail(c, SOAK_ERR_PARSE, path, "must be a JSON object");
    soak_status st = parse_kind(c, m, path, p);
    if (st != SOAK_OK) return st;
    mat_reader r = {c,
                    m,
                    path,
                    "",
                    soak_material_kind_porous(p->kind),
                    p->kind == SOAK_KIND_CONDUCTOR,
                    p->kind == SOAK_KIND_THIN_SHEET};
    snprintf(r.why, sizeof r.why, "kind %s", soak_material_kind_name(p->kind));
    const int measured = cJSON_GetObjectItemCaseSensitive(m, "measured") != NULL;
    st = check_material_keys(&r, measured);
    if (st == SOAK_OK) st = get_name(c, m, path, &p->name);
    if (st == SOAK_OK) st = get_string(c, m, path, "display_name", &p->display_name);
    if (st == SOAK_OK) st = parse_albedo_group(&r, p);
    if (st == SOAK_OK) st = parse_roughness_group(&r, p);
    if (st == SOAK_OK) st = parse_ior_group(&r, p);
    if (st == SOAK_OK && r.porous) st = parse_porosity_group(&r, p);
    if (st == SOAK_OK && !r.conductor) st = parse_medium_groups(&r, p);
    if (st != SOAK_OK) return st;
    if (soak_preset_derive(p) != SOAK_OK) return fail(c, SOAK_ERR_NUMERIC, path, "albedo inversion failed");
    st = parse_wetting_group(&r, p);
    if (st == SOAK_OK && r.sheet) st = parse_sheet_group(&r, p);
    if (st == SOAK_OK && measured) st = parse_measured(c, m, path, p);
    return st;
}

static soak_status parse_liquid(ctx *c, const cJSON *l, const char *path, soak_liquid *q)
{
    static const char *const keys[] = {"name",           "display_name", "ior", "sigma_a_per_mm",
                                       "sigma_s_per_mm", "source",       NULL};
    soak_status st = check_object(c, l, path, keys, NULL, NULL);
    if (st == SOAK_OK) st = get_name(c, l, path, &q->name);
    if (st == SOAK_OK) st = get_string(c, l, path, "display_name", &q->display_name);
    if (st == SOAK_OK) st = get_number(c, l, path, "ior", 1.0, 3.0, &q->ior);
    soak_rgb sigma_a_per_mm = {0.0, 0.0, 0.0}, sigma_s_per_mm = {0.0, 0.0, 0.0};
    if (st == SOAK_OK) st = get_rgb(c, l, path, "sigma_a_per_mm", 0.0, 1000.0, &sigma_a_per_mm);
    if (st == SOAK_OK) st = get_rgb(c, l, path, "sigma_s_per_mm", 0.0, 1000.0, &sigma_s_per_mm);
    q->sigma_a_per_m = soak_rgb_per_m_from_per_mm(sigma_a_per_mm);
    q->sigma_s_per_m = soak_rgb_per_m_from_per_mm(sigma_s_per_mm);
    if (st == SOAK_OK) st = get_string(c, l, path, "source", &q->source);
    return st;
}

soak_status soak_preset_parse_root(const soak_json_in *in, const cJSON *root, soak_preset_db *db)
{
    ctx cc = {in->file, in->err, in->errlen, db};
    ctx *c = &cc;
    static const char *const keys[] = {"format", "version", "description", "materials", "liquids", NULL};
    soak_status st = check_object(c, root, "", keys, NULL, NULL);
    if (st != SOAK_OK) return st;
    const cJSON *fmt = cJSON_GetObjectItemCaseSensitive(root, "format");
    if (!cJSON_IsString(fmt) || strcmp(fmt->valuestring, "soak-materials") != 0)
        return fail(c, SOAK_ERR_PARSE, "format", "must be the string \"soak-materials\"");
    double version = 0.0;
    st = get_number(c, root, "", "version", 1.0, 1.0, &version);
    if (st != SOAK_OK) return st;
    const char *desc = NULL;
    st = get_string(c, root, "", "description", &desc);
    if (st != SOAK_OK) return st;

    const cJSON *mats = cJSON_GetObjectItemCaseSensitive(root, "materials");
    const cJSON *liqs = cJSON_GetObjectItemCaseSensitive(root, "liquids");
    int nm = cJSON_GetArraySize(mats), nl = cJSON_GetArraySize(liqs);
    if (!cJSON_IsArray(mats) || nm < 1 || nm > MAX_ENTRIES)
        return fail(c, SOAK_ERR_PARSE, "materials", "must be an array of 1 to %d materials", MAX_ENTRIES);
    if (!cJSON_IsArray(liqs) || nl < 1 || nl > MAX_ENTRIES)
        return fail(c, SOAK_ERR_PARSE, "liquids", "must be an array of 1 to %d liquids", MAX_ENTRIES);
    c->db->materials = calloc((size_t)nm, sizeof *c->db->materials);
    c->db->liquids = calloc((size_t)nl, sizeof *c->db->liquids);
    if (!c->db->materials || !c->db->liquids) return fail(c, SOAK_ERR_NOMEM, "", "out of memory");

    int i = 0;
    for (const cJSON *it = mats->child; it; it = it->next, ++i) {
        char path[PATH_MAX_LEN];
        path_printf(path, "materials[%d]", i);
        st = parse_material(c, it, path, &c->db->materials[i]);
        if (st != SOAK_OK) return st;
        for (int j = 0; j < i; ++j)
            if (strcmp(c->db->materials[j].name, c->db->materials[i].name) == 0)
                return fail(c, SOAK_ERR_ARG, path, "name '%s' repeats materials[%d]", c->db->materials[i].name, j);
        c->db->n_materials = i + 1;
    }
    i = 0;
    for (const cJSON *it = liqs->child; it; it = it->next, ++i) {
        char path[PATH_MAX_LEN];
        path_printf(path, "liquids[%d]", i);
        st = parse_liquid(c, it, path, &c->db->liquids[i]);
        if (st != SOAK_OK) return st;
        for (int j = 0; j < i; ++j)
            if (strcmp(c->db->liquids[j].name, c->db->liquids[i].name) == 0)
                return fail(c, SOAK_ERR_ARG, path, "name '%s' repeats liquids[%d]", c->db->liquids[i].name, j);
        c->db->n_liquids = i + 1;
    }
    return SOAK_OK;
}
