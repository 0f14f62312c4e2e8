/* A preset material of a scene: the wetness chain's state of a named preset
 * (soak/wetness.h) made a soak_material (format: scenes/README.md;
 * scene_preset.h). */
#define _POSIX_C_SOURCE 200809L
#include "scene_preset.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_json.h"
#include "scene_model.h"
#include "soak/base_colour.h"
#include "soak/json_number.h"
#include "soak/preset.h"
#include "soak/units.h"
#include "soak/wet_specular.h"
#include "soak/wetness.h"

/* What a preset material asks for. */
typedef struct preset_request {
    const char *name, *liquid, *model; /* liquid, model: NULL when absent */
    double wetness;
    int has_base; /* "base_colour" given: the preset's class wets this dry colour */
    soak_rgb base;
    double m_per_unit; /* the scene's length unit, from the material's "unit_mm" */
} preset_request;

/* What the wetness chain made of the preset, kept past the preset file's lifetime. */
typedef struct preset_chain {
    soak_wet_params w;
    soak_wet_params w_dry; /* the same preset at wetness 0 (thin sheets: the dry medium) */
    soak_material_kind kind;
    double ior;
    soak_rgb n, k;
} preset_chain;

soak_status scene_presets_db(scene_ctx *c, const char *path, const soak_preset_db **db)
{
    if (!c->db) {
        char msg[1024];
        soak_status st = soak_presets_load(NULL, &c->db, msg, sizeof msg);
        if (st != SOAK_OK) return sj_fail(c, st, path, "cannot load the presets: %s", msg);
    }
    *db = c->db;
    return SOAK_OK;
}

/* Evaluates the chain (steady state) for the request with the scene's
 * presets; sets m's model view. The dry state only for a thin sheet (its
 * dry medium). */
static soak_status eval_preset(scene_ctx *c, const char *path, const preset_request *r, soak_material *m,
                               preset_chain *out)
{
    char np[320];
    sj_path(np, sizeof np, path, "name");
    const soak_preset_db *db = NULL;
    soak_status st = scene_presets_db(c, np, &db);
    if (st != SOAK_OK) return st;
    const char *liquid = r->liquid ? r->liquid : "water";
    const soak_preset *p = soak_presets_find(db, r->name);
    const soak_liquid *liq = soak_presets_find_liquid(db, liquid);
    if (!p) {
        st = sj_fail(c, SOAK_ERR_NOT_FOUND, np, "no preset named '%s' (see `soak materials`)", r->name);
    } else if (!liq) {
        sj_path(np, sizeof np, path, "liquid");
        st = sj_fail(c, SOAK_ERR_NOT_FOUND, np, "no liquid named '%s'", liquid);
    } else {
        soak_wet_input in = soak_wet_input_steady(p, r->wetness);
        soak_wet_input dry = soak_wet_input_steady(p, 0.0);
        soak_preset own = *p;
        if (r->has_base) own.albedo = r->base; /* the model view's dry albedo */
        st = r->has_base ? soak_wet_params_for_base(p, liq, &in, r->base, &out->w)
                         : soak_wetness_eval(p, liq, &in, &out->w);
        if (st == SOAK_OK && p->kind == SOAK_KIND_THIN_SHEET)
            st = r->has_base ? soak_wet_params_for_base(p, liq, &dry, r->base, &out->w_dry)
                             : soak_wetness_eval(p, liq, &dry, &out->w_dry);
        out->kind = p->kind;
        out->ior = p->ior;
        out->n = p->ior_n;
        out->k = p->ior_k;
        if (st == SOAK_OK) scene_preset_model_view(&own, &out->w, r->m_per_unit, m);
        else st = sj_fail(c, st, path, "wetness evaluation failed (%s)", soak_status_str(st));
    }
    return st;
}

/* The chain's liquid-air interface (wetness.h step 5): the film over the
 * coverage c and the pore water's surface (zero thickness) over porosity *
 * fill of the rest (soak_wet_interface_area, the one owner of that area).
 * A wet draw is the film with its thickness, or with probability
 * film_pore_share = 1 - c / area the pore water at zero thickness over the
 * body alone (render_bsdfs.c; the grains stay in the dry draw, preset_base's
 * dry_coat_weight): a coloured liquid absorbs over the film's path only where
 * a film lies (brick + coffee at w = 0.5 was 22.5 % dark with one thick film
 * over both). */
static void preset_film(const soak_wet_params *w, double m_per_unit, soak_material *m)
{
    m->film_ior = w->film_ior;
    m->film_k = 1;
    m->film_coverage = soak_wet_interface_area(w);
    m->film_pore_share = m->film_coverage > 0 ? 1.0 - fmin(w->film_coverage / m->film_coverage, 1.0) : 0.0;
    m->film_thickness = w->film_coverage > 0 ? soak_units_from_m(w->film_thickness_m, m_per_unit) : 0.0;
    m->film_absorption = soak_rgb_per_unit_from_per_m(w->film_absorption_per_m, m_per_unit);
}

/* A thin sheet's traced medium from the chain's coefficients (SI) in scene units. */
static void sheet_medium(const soak_wet_params *w, double m_per_unit, soak_scene_medium *med)
{
    med->sigma_s = soak_rgb_per_unit_from_per_m(w->sigma_s_per_m, m_per_unit);
    med->sigma_a = soak_rgb_per_unit_from_per_m(w->sigma_a_per_m, m_per_unit);
    med->phase = w->phase;
    med->volume = NULL;
    scene_medium_majorant(med);
}

static void preset_base(const preset_chain *pc, double m_per_unit, soak_material *m)
{
    const soak_wet_params *w = &pc->w;
    if (pc->kind == SOAK_KIND_CONDUCTOR) {
        m->base = SOAK_BASE_GGX;
        m->eta = pc->n;
        m->k = pc->k;
        m->alpha = w->ggx_alpha;
    } else if (pc->kind != SOAK_KIND_THIN_SHEET) {
        /* Opaque dielectrics: the chain's base is a Lambertian surface of the
         * subsurface albedo (van de Hulst, index matched) under the liquid
         * interface; tracing the same medium under a smooth n = 1.5 boundary
         * would be a different model (1.5-2.7x darker dry, see
         * scenes/README.md). */
        m->base = SOAK_BASE_LAMBERT;
        m->albedo = w->albedo_subsurface;
        /* The material's own rough interface over that base (wetness.h step
         * 6: GGX alpha of the chain, Merillou/Hnat weight 1 - porosity). */
        m->ior = pc->ior;
        m->alpha = w->ggx_alpha;
        m->coat_weight = w->specular_weight;
        /* in the dry draw: every grain outside the film (wet_specular.h point 4) */
        m->dry_coat_weight = soak_wet_grain_coat_weight(w);
    } else {
        /* Thin sheets keep their traced medium (translucency) under a smooth
         * boundary of the fibres' index: an index-matched boundary would match
         * the chain's front-lit albedo, but the tracer's in-medium light
         * sampling finds no delta light through a boundary of index 1 (back-lit
         * sheets render black), so the sheet stays the slab it was; its
         * front-lit albedo is darker than the chain's (scenes/README.md). */
        m->base = SOAK_BASE_MEDIUM;
        m->medium.ior = pc->ior;
        sheet_medium(w, m_per_unit, &m->medium);
        /* Where the object's wetness (a map, a plane) says dry, a path enters
         * the sheet's dry medium: the walk picks the wet one with probability
         * the object's wetness (render_medium.c), so a wet spot of a map
         * transmits as the preset at the material's wetness and the rest as
         * the dry preset; the film follows the same wetness. */
        m->dry_medium = m->medium;
        sheet_medium(&pc->w_dry, m_per_unit, &m->dry_medium);
        m->has_dry = 1;
    }
}

/* A preset's "film_over": the liquid's film (coverage, thickness in scene
 * units) laid over the chain's state at the material's wetness instead of
 * the chain's own film: water over a rock whose inside is drier ([JLD99]
 * sec. 4.2, Fig. 6c). The film keeps the liquid's index and absorption;
 * without pore water (a film over the surface, not water in its pores). */
static soak_status parse_film_over(scene_ctx *c, const cJSON *j, const char *path, soak_material *m)
{
    const cJSON *f = cJSON_GetObjectItemCaseSensitive(j, "film_over");
    if (!f) return SOAK_OK;
    static const char *const keys[] = {"coverage", "thickness", NULL};
    char fp[320];
    sj_path(fp, sizeof fp, path, "film_over");
    double coverage = 1, thickness = 0;
    soak_status st = sj_keys(c, f, fp, keys);
    if (st == SOAK_OK) st = sj_num(c, f, "coverage", fp, 0, 1, 0, 1, &coverage);
    if (st == SOAK_OK) st = sj_num_gt(c, f, "thickness", fp, 0, 1e3, 1, 0, &thickness);
    if (st != SOAK_OK) return st;
    if (m->base == SOAK_BASE_GGX)
        return sj_fail(c, SOAK_ERR_ARG, fp, "not for a metal preset (its film is the chain's)");
    m->film_coverage = coverage;
    m->film_pore_share = 0.0;
    m->film_thickness = thickness;
    m->dry_coat_weight = m->coat_weight; /* no pore water: every grain outside the film is in the dry draw */
    return SOAK_OK;
}

/* What parse_preset read, kept for the material's states at the wetness of
 * each point (scene_levels.c builds them); after parse_film_over. */
static soak_status keep_recipe(const preset_request *r, const preset_chain *pc, int no_interface, const cJSON *j,
                               soak_material *m)
{
    scene_preset_recipe rec;
    memset(&rec, 0, sizeof rec);
    snprintf(rec.name, sizeof rec.name, "%s", r->name);
    snprintf(rec.liquid, sizeof rec.liquid, "%s", r->liquid ? r->liquid : "water");
    rec.wetness = r->wetness;
    rec.m_per_unit = r->m_per_unit;
    rec.has_base = r->has_base;
    rec.base = r->base;
    rec.no_interface = no_interface;
    rec.film_over = cJSON_GetObjectItemCaseSensitive(j, "film_over") != NULL;
    rec.over_coverage = m->film_coverage;
    rec.over_thickness = m->film_thickness;
    rec.saturation = pc->w.saturation;
    m->levels = calloc(1, sizeof *m->levels);
    if (!m->levels) return SOAK_ERR_NOMEM;
    m->levels->recipe = rec;
    return SOAK_OK;
}

soak_status scene_preset_view(const soak_preset *p, const soak_liquid *liq, const scene_preset_recipe *rec,
                              double wetness, soak_material *m)
{
    preset_chain pc;
    memset(&pc, 0, sizeof pc);
    soak_wet_input in = soak_wet_input_steady(p, wetness);
    soak_status st =
        rec->has_base ? soak_wet_params_for_base(p, liq, &in, rec->base, &pc.w) : soak_wetness_eval(p, liq, &in, &pc.w);
    if (st != SOAK_OK) return st;
    if (p->kind == SOAK_KIND_THIN_SHEET) return SOAK_ERR_UNSUPPORTED; /* its dry medium follows the wetness */
    pc.kind = p->kind;
    pc.ior = p->ior;
    pc.n = p->ior_n;
    pc.k = p->ior_k;
    m->type = SOAK_MAT_WET;
    preset_film(&pc.w, rec->m_per_unit, m);
    preset_base(&pc, rec->m_per_unit, m);
    if (rec->no_interface) m->coat_weight = m->dry_coat_weight = 0.0;
    if (rec->film_over) {
        m->film_coverage = rec->over_coverage;
        m->film_pore_share = 0.0;
        m->film_thickness = rec->over_thickness;
        m->dry_coat_weight = m->coat_weight; /* as parse_film_over: no pore water */
    }
    return SOAK_OK;
}

/* Preset + wetness through soak/wetness.h (steady state). The chain is in
 * SI (m, 1/m); "unit_mm" is the scene length unit in mm (the scene file's
 * documented key), converted here once to metres per unit. */
soak_status scene_parse_preset(scene_ctx *c, const cJSON *j, const char *path, soak_material *m)
{
    static const char *const keys[] = {"type",  "name",        "wetness",   "liquid",    "unit_mm",
                                       "model", "base_colour", "interface", "film_over", NULL};
    preset_request r;
    double interface = 1;
    soak_status st = sj_keys(c, j, path, keys);
    r.has_base = cJSON_GetObjectItemCaseSensitive(j, "base_colour") != NULL;
    if (st == SOAK_OK) st = sj_rgb(c, j, "base_colour", path, 0, 1, 0, soak_rgb3(0, 0, 0), &r.base);
    if (st == SOAK_OK) st = sj_str(c, j, "name", path, 1, &r.name);
    if (st == SOAK_OK) st = sj_num(c, j, "wetness", path, 0, 1, 0, 0, &r.wetness);
    if (st == SOAK_OK) st = sj_str(c, j, "liquid", path, 0, &r.liquid);
    double unit_mm = 0.0;
    if (st == SOAK_OK) st = sj_num_gt(c, j, "unit_mm", path, 0, 1e9, 0, 1000, &unit_mm);
    r.m_per_unit = soak_m_from_mm(unit_mm);
    if (st == SOAK_OK) st = sj_str(c, j, "model", path, 0, &r.model);
    if (st == SOAK_OK) st = sj_num(c, j, "interface", path, 0, 1, 0, 1, &interface);
    if (st != SOAK_OK) return st;
    preset_chain pc;
    st = eval_preset(c, path, &r, m, &pc);
    if (st != SOAK_OK) return st;
    if (r.has_base && pc.kind == SOAK_KIND_CONDUCTOR) {
        char bp[320];
        sj_path(bp, sizeof bp, path, "base_colour");
        return sj_fail(c, SOAK_ERR_ARG, bp,
                       "'%s' is a metal: its colour is its complex index (n, k), "
                       "base_colour wets a dielectric's or a thin sheet's own colour",
                       r.name);
    }
    m->type = SOAK_MAT_WET;
    preset_film(&pc.w, r.m_per_unit, m);
    preset_base(&pc, r.m_per_unit, m);
    /* "interface": 0 leaves the material's own specular interface out: what a
     * front end draws with its highlights off (tests/povray/flat_ground.py) */
    if (interface < 0.5) m->coat_weight = m->dry_coat_weight = 0.0;
    st = parse_film_over(c, j, path, m);
    if (st == SOAK_OK && !r.model && pc.kind != SOAK_KIND_THIN_SHEET) st = keep_recipe(&r, &pc, interface < 0.5, j, m);
    if (st != SOAK_OK || !r.model) return st;
    char mp[320];
    sj_path(mp, sizeof mp, path, "model");
    if (cJSON_GetObjectItemCaseSensitive(j, "film_over"))
        return sj_fail(c, SOAK_ERR_ARG, mp, "a model view renders the chain's own film: leave out \"film_over\"");
    return scene_use_model(c, mp, r.model, m);
}
