/* Scene materials and per-object wetness (format: scenes/README.md). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_json.h"
#include "scene_levels.h"
#include "soak/base_colour.h"
#include "soak/fresnel.h"
#include "soak/json_number.h"
#include "soak/ggx.h"
#include "soak/porous.h"
#include "soak/preset.h"
#include "soak/units.h"
#include "soak/wet_specular.h"
#include "soak/wetness.h"

static void medium_majorant(soak_scene_medium *m)
{
    double mj = soak_rgb_max(soak_rgb3(m->sigma_s.r + m->sigma_a.r, m->sigma_s.g + m->sigma_a.g, m->sigma_s.b + m->sigma_a.b));
    if (m->volume) {
        size_t n = soak_volume_count(m->volume);
        for (int ch = 0; ch < 3; ++ch) {
            const float *s = soak_volume_plane(m->volume, SOAK_VOL_SIGMA_S_R + ch);
            const float *a = soak_volume_plane(m->volume, SOAK_VOL_SIGMA_A_R + ch);
            for (size_t i = 0; i < n; ++i) mj = fmax(mj, (double)s[i] + (double)a[i]);
        }
    }
    m->majorant = mj;
}

static soak_status check_volume(scene_ctx *c, const soak_volume *v, const char *path)
{
    size_t n = soak_volume_count(v);
    for (int ch = 0; ch <= SOAK_VOL_W; ++ch) {
        const float *p = soak_volume_plane(v, ch);
        double lo = ch <= SOAK_VOL_SIGMA_A_B ? 0 : (ch == SOAK_VOL_W ? 0 : -SOAK_HG_G_MAX);
        double hi = ch <= SOAK_VOL_SIGMA_A_B ? SOAK_VOL_SIGMA_MAX : (ch == SOAK_VOL_W ? 1 : SOAK_HG_G_MAX);
        for (size_t i = 0; i < n; ++i)
            if (!soak_in_range(p[i], lo, hi))
                return sj_fail(c, SOAK_ERR_ARG, path, "channel %s has value %g outside [%g, %g]",
                               soak_volume_channel_name(ch), (double)p[i], lo, hi);
    }
    return SOAK_OK;
}

static soak_status parse_medium(scene_ctx *c, const cJSON *j, const char *path, soak_scene_medium *m, int allow_type)
{
    static const char *const keys[] = {"type", "sigma_s", "sigma_a", "g1", "g2", "w", "ior", "volume", NULL};
    static const char *const keys_dry[] = {"sigma_s", "sigma_a", "g1", "g2", "w", NULL};
    soak_status st = sj_keys(c, j, path, allow_type ? keys : keys_dry);
    if (st == SOAK_OK) st = sj_rgb(c, j, "sigma_s", path, 0, 1e9, 1, soak_rgb3(0, 0, 0), &m->sigma_s);
    if (st == SOAK_OK) st = sj_rgb(c, j, "sigma_a", path, 0, 1e9, 0, soak_rgb3(0, 0, 0), &m->sigma_a);
    if (st == SOAK_OK) st = sj_num(c, j, "g1", path, -SOAK_HG_G_MAX, SOAK_HG_G_MAX, 0, 0, &m->phase.g1);
    if (st == SOAK_OK) st = sj_num(c, j, "g2", path, -SOAK_HG_G_MAX, SOAK_HG_G_MAX, 0, m->phase.g1, &m->phase.g2);
    if (st == SOAK_OK) st = sj_num(c, j, "w", path, 0, 1, 0, 1, &m->phase.w);
    if (st != SOAK_OK || !allow_type) return st;
    st = sj_num(c, j, "ior", path, 1, 3, 0, 1.5, &m->ior);
    const cJSON *vol = cJSON_GetObjectItemCaseSensitive(j, "volume");
    if (st == SOAK_OK && vol) {
        static const char *const vkeys[] = {"file", "origin", NULL};
        char vp[400], fp[420], full[2048], msg[2048];
        const char *file;
        sj_path(vp, sizeof vp, path, "volume");
        sj_path(fp, sizeof fp, vp, "file");
        st = sj_keys(c, vol, vp, vkeys);
        if (st == SOAK_OK) st = sj_str(c, vol, "file", vp, 1, &file);
        if (st == SOAK_OK) st = sj_vec3(c, vol, "origin", vp, 0, soak_v3(0, 0, 0), &m->volume_origin);
        if (st == SOAK_OK) st = sj_file(c, file, fp, full, sizeof full);
        if (st != SOAK_OK) return st;
        m->volume = calloc(1, sizeof *m->volume);
        if (!m->volume) return SOAK_ERR_NOMEM;
        st = soak_volume_read_grid(full, m->volume, msg, sizeof msg);
        if (st != SOAK_OK) {
            free(m->volume);
            m->volume = NULL;
            return sj_fail(c, st, fp, "%s", msg);
        }
        st = check_volume(c, m->volume, fp);
        if (st != SOAK_OK) return st;
    }
    if (st == SOAK_OK) medium_majorant(m);
    return st;
}

/* ---- Materials rendered through a model of soak_models() ----
 * model_params describe a material in the models' terms (per channel): the
 * dry albedo, base index, roughness, the liquid film and the pore fill.
 * wet_albedo is the albedo of models that do not model pores themselves
 * (the preset chain's darkened subsurface albedo; the albedo otherwise). */
static void model_view_base(soak_material *m)
{
    for (int ch = 0; ch < 3; ++ch) {
        soak_model_params *q = &m->model_params[ch];
        soak_model_params_default(q);
        q->albedo = 0.0;
        q->n_film = 1.0;
        q->absorption = 0.0;
        q->thickness = 0.0;
        q->fill = 0.0;
    }
    m->has_model_params = 1;
}

static void model_view_film(soak_material *m)
{
    for (int ch = 0; ch < 3; ++ch) {
        soak_model_params *q = &m->model_params[ch];
        q->n_film = m->film_ior;
        q->absorption = soak_rgb_at(m->film_absorption, ch);
        q->thickness = m->film_thickness;
        q->fill = 1.0;
    }
}

static void model_view_lambert(soak_material *m)
{
    model_view_base(m);
    for (int ch = 0; ch < 3; ++ch) m->model_params[ch].albedo = soak_rgb_at(m->albedo, ch);
    m->wet_albedo = m->albedo;
}

static void model_view_ggx(soak_material *m)
{
    model_view_base(m);
    for (int ch = 0; ch < 3; ++ch) {
        m->model_params[ch].ior = soak_rgb_at(m->eta, ch);
        m->model_params[ch].k = soak_rgb_at(m->k, ch);
        m->model_params[ch].roughness = m->alpha;
    }
    m->wet_albedo = soak_rgb3(0, 0, 0);
}

/* Preset at the chain's steady state: dry albedo and pores for the porous
 * models, the chain's subsurface albedo for the others. */
static void preset_model_view(const soak_preset *p, const soak_wet_params *w, double m_per_unit, soak_material *m)
{
    model_view_base(m);
    for (int ch = 0; ch < 3; ++ch) {
        soak_model_params *q = &m->model_params[ch];
        int conductor = p->kind == SOAK_KIND_CONDUCTOR;
        q->albedo = conductor ? 0.0 : soak_rgb_at(p->albedo, ch);
        q->ior = conductor ? soak_rgb_at(p->ior_n, ch) : p->ior;
        q->k = conductor ? soak_rgb_at(p->ior_k, ch) : 0.0;
        q->roughness = w->ggx_alpha;
        q->n_film = w->film_ior;
        q->absorption = soak_per_unit_from_per_m(soak_rgb_at(w->film_absorption_per_m, ch), m_per_unit);
        q->thickness = w->film_coverage > 0 ? soak_units_from_m(w->film_thickness_m, m_per_unit) : 0.0;
        q->porosity = p->porosity;
        q->sp = p->s_p;
        q->fill = w->fill;
    }
    m->wet_albedo = p->kind == SOAK_KIND_CONDUCTOR ? soak_rgb3(0, 0, 0) : w->albedo_subsurface;
}

/* Switches m to be rendered through `model`, from its model view (both
 * states must pass the model's set-up); the object wetness then picks the
 * model's wet state with probability wetness * film_coverage (coverage 1
 * unless the film covers part of a preset's surface; the porous models'
 * pores fill everywhere). */
static soak_status material_use_model(soak_material *m, const soak_model *model)
{
    if (!m->has_model_params) return SOAK_ERR_UNSUPPORTED;
    const soak_model *was = m->model;
    m->model = model;
    soak_model_params q[3];
    soak_model_ctx ctx;
    soak_status st = SOAK_OK;
    for (int wet = 0; wet <= 1 && st == SOAK_OK; ++wet) {
        const soak_model *md = soak_material_model(m, wet);
        soak_material_model_params(m, wet, q);
        for (int ch = 0; ch < 3 && st == SOAK_OK; ++ch) st = md ? md->setup(&q[ch], &ctx) : SOAK_ERR_NOT_FOUND;
    }
    if (st != SOAK_OK) {
        m->model = was;
        return st;
    }
    if (strncmp(model->name, "porous", 6) == 0 || m->type != SOAK_MAT_WET) m->film_coverage = 1.0;
    m->type = SOAK_MAT_MODEL;
    return SOAK_OK;
}

const soak_model *soak_material_model(const soak_material *m, int wet)
{
    if (!m->model || wet || !m->model->exact) return m->model;
    return soak_model_find(m->model->exact);
}

void soak_material_model_params(const soak_material *m, int wet, soak_model_params out[3])
{
    int pores = m->model && strncmp(m->model->name, "porous", 6) == 0;
    for (int ch = 0; ch < 3; ++ch) {
        out[ch] = m->model_params[ch];
        if (!pores) out[ch].albedo = soak_rgb_at(m->wet_albedo, ch);
        if (wet) continue;
        out[ch].n_film = 1.0;
        out[ch].thickness = 0.0;
        out[ch].fill = 0.0;
    }
}

static soak_status use_model(scene_ctx *c, const char *path, const char *name, soak_material *m)
{
    const soak_model *model = soak_model_find(name);
    if (!model) return sj_fail(c, SOAK_ERR_NOT_FOUND, path, "no model named '%s' (see `soak eval --list`)", name);
    soak_status st = material_use_model(m, model);
    if (st != SOAK_OK) return sj_fail(c, st, path, "the model '%s' rejects this material's parameters (%s)", name, soak_status_str(st));
    return SOAK_OK;
}

/* A model material: {"type": "<model>", albedo, ior, k, roughness, film
 * {ior, thickness, absorption}, porosity, sp, fill, ks, ks_water}. */
static soak_status parse_model(scene_ctx *c, const cJSON *j, const char *path, const soak_model *model, soak_material *m)
{
    static const char *const keys[] = {"type", "albedo", "ior", "k", "roughness", "film", "porosity", "sp", "fill", "ks", "ks_water", NULL};
    static const char *const fkeys[] = {"ior", "thickness", "absorption", NULL};
    soak_model_params d;
    soak_model_params_default(&d);
    soak_rgb albedo, ior, k, absorption = soak_rgb3(0, 0, 0);
    double rough, n_film = SOAK_WATER_IOR, thick = 0, por, sp, fill, ks, ksw;
    soak_status st = sj_keys(c, j, path, keys);
    if (st == SOAK_OK) st = sj_rgb(c, j, "albedo", path, 0, 1, 0, soak_rgb3(d.albedo, d.albedo, d.albedo), &albedo);
    if (st == SOAK_OK) st = sj_rgb(c, j, "ior", path, SOAK_ETA_MIN, SOAK_ETA_MAX, 0, soak_rgb3(d.ior, d.ior, d.ior), &ior);
    if (st == SOAK_OK) st = sj_rgb(c, j, "k", path, 0, SOAK_GGX_K_MAX, 0, soak_rgb3(0, 0, 0), &k);
    if (st == SOAK_OK) st = sj_num(c, j, "roughness", path, SOAK_GGX_ALPHA_MIN, SOAK_GGX_ALPHA_MAX, 0, d.roughness, &rough);
    if (st == SOAK_OK) st = sj_num(c, j, "porosity", path, 0, 1, 0, d.porosity, &por);
    if (st == SOAK_OK) st = sj_num(c, j, "sp", path, 0, 1e3, 0, d.sp, &sp);
    if (st == SOAK_OK) st = sj_num(c, j, "fill", path, 0, 1, 0, 1, &fill);
    if (st == SOAK_OK) st = sj_num(c, j, "ks", path, 0, 1, 0, d.ks, &ks);
    if (st == SOAK_OK) st = sj_num(c, j, "ks_water", path, 0, SOAK_POROUS_KS_WATER_MAX, 0, d.ks_water, &ksw);
    const cJSON *film = cJSON_GetObjectItemCaseSensitive(j, "film");
    if (st == SOAK_OK && film) {
        char fp[320];
        sj_path(fp, sizeof fp, path, "film");
        st = sj_keys(c, film, fp, fkeys);
        if (st == SOAK_OK) st = sj_num(c, film, "ior", fp, 1, 3, 0, SOAK_WATER_IOR, &n_film);
        if (st == SOAK_OK) st = sj_num(c, film, "thickness", fp, 0, 1e3, 0, 0, &thick);
        if (st == SOAK_OK) st = sj_rgb(c, film, "absorption", fp, 0, 1e9, 0, soak_rgb3(0, 0, 0), &absorption);
    }
    if (st != SOAK_OK) return st;
    m->albedo = albedo;
    m->film_ior = n_film;
    m->film_thickness = thick;
    m->film_absorption = absorption;
    m->film_coverage = 1.0;
    model_view_lambert(m);
    model_view_film(m);
    for (int ch = 0; ch < 3; ++ch) {
        soak_model_params *q = &m->model_params[ch];
        q->ior = soak_rgb_at(ior, ch);
        q->k = soak_rgb_at(k, ch);
        q->roughness = rough;
        q->porosity = por;
        q->sp = sp;
        q->fill = fill;
        q->ks = ks;
        q->ks_water = ksw;
    }
    char tp[320];
    sj_path(tp, sizeof tp, path, "type");
    return use_model(c, tp, model->name, m);
}

static soak_status parse_ggx(scene_ctx *c, const cJSON *j, const char *path, soak_material *m)
{
    soak_status st = sj_rgb(c, j, "eta", path, SOAK_ETA_MIN, SOAK_ETA_MAX, 1, soak_rgb3(1, 1, 1), &m->eta);
    if (st == SOAK_OK) st = sj_rgb(c, j, "k", path, 0, SOAK_GGX_K_MAX, 1, soak_rgb3(0, 0, 0), &m->k);
    if (st == SOAK_OK) st = sj_num(c, j, "roughness", path, SOAK_GGX_ALPHA_MIN, SOAK_GGX_ALPHA_MAX, 0, 0.1, &m->alpha);
    return st;
}

/* A wet material's "film": the liquid layer (absent: water, k = 1, full coverage). */
static soak_status parse_film(scene_ctx *c, const cJSON *film, const char *fp, soak_material *m)
{
    static const char *const fkeys[] = {"ior", "k", "thickness", "absorption", "coverage", "pore_share", NULL};
    m->film_ior = SOAK_WATER_IOR;
    m->film_k = 1;
    m->film_coverage = 1;
    if (!film) return SOAK_OK;
    soak_status st = sj_keys(c, film, fp, fkeys);
    if (st == SOAK_OK) st = sj_num(c, film, "ior", fp, 1, 3, 0, SOAK_WATER_IOR, &m->film_ior);
    if (st == SOAK_OK) st = sj_num(c, film, "k", fp, 0.01, 100, 0, 1, &m->film_k);
    if (st == SOAK_OK) st = sj_num(c, film, "thickness", fp, 0, 1e3, 0, 0, &m->film_thickness);
    if (st == SOAK_OK) st = sj_rgb(c, film, "absorption", fp, 0, 1e9, 0, soak_rgb3(0, 0, 0), &m->film_absorption);
    if (st == SOAK_OK) st = sj_num(c, film, "coverage", fp, 0, 1, 0, 1, &m->film_coverage);
    if (st == SOAK_OK) st = sj_num(c, film, "pore_share", fp, 0, 1, 0, 0, &m->film_pore_share);
    return st;
}

/* A wet material's "base" (required): lambert, ggx or medium. */
static soak_status parse_wet_base(scene_ctx *c, const cJSON *base, const char *bp, soak_material *m)
{
    if (!base) return sj_fail(c, SOAK_ERR_PARSE, bp, "missing (required)");
    const char *bt;
    soak_status st = sj_str(c, base, "type", bp, 1, &bt);
    if (st != SOAK_OK) return st;
    if (strcmp(bt, "lambert") == 0) {
        static const char *const k[] = {"type", "albedo", NULL};
        m->base = SOAK_BASE_LAMBERT;
        st = sj_keys(c, base, bp, k);
        if (st == SOAK_OK) st = sj_rgb(c, base, "albedo", bp, 0, 1, 1, soak_rgb3(0, 0, 0), &m->albedo);
        return st;
    }
    if (strcmp(bt, "ggx") == 0) {
        static const char *const k[] = {"type", "eta", "k", "roughness", NULL};
        m->base = SOAK_BASE_GGX;
        st = sj_keys(c, base, bp, k);
        if (st == SOAK_OK) st = parse_ggx(c, base, bp, m);
        return st;
    }
    if (strcmp(bt, "medium") == 0) {
        m->base = SOAK_BASE_MEDIUM;
        return parse_medium(c, base, bp, &m->medium, 1);
    }
    char tp[340];
    sj_path(tp, sizeof tp, bp, "type");
    return sj_fail(c, SOAK_ERR_PARSE, tp, "unknown base type '%s' (accepted: lambert, ggx, medium)", bt);
}

/* A wet material's "dry" medium (optional): the base medium's values where
 * the object is dry, without its volume. */
static soak_status parse_dry(scene_ctx *c, const cJSON *dry, const char *dp, soak_material *m)
{
    if (!dry) return SOAK_OK;
    if (m->base != SOAK_BASE_MEDIUM) return sj_fail(c, SOAK_ERR_ARG, dp, "dry medium parameters need base.type \"medium\"");
    m->dry_medium = m->medium;
    m->dry_medium.volume = NULL;
    soak_status st = parse_medium(c, dry, dp, &m->dry_medium, 0);
    if (st != SOAK_OK) return st;
    medium_majorant(&m->dry_medium);
    m->has_dry = 1;
    return SOAK_OK;
}

static soak_status parse_wet(scene_ctx *c, const cJSON *j, const char *path, soak_material *m)
{
    static const char *const keys[] = {"type", "film", "base", "dry", NULL};
    char fp[320], bp[320], dp[320];
    sj_path(fp, sizeof fp, path, "film");
    sj_path(bp, sizeof bp, path, "base");
    sj_path(dp, sizeof dp, path, "dry");
    soak_status st = sj_keys(c, j, path, keys);
    if (st != SOAK_OK) return st;
    m->type = SOAK_MAT_WET;
    st = parse_film(c, cJSON_GetObjectItemCaseSensitive(j, "film"), fp, m);
    if (st == SOAK_OK) st = parse_wet_base(c, cJSON_GetObjectItemCaseSensitive(j, "base"), bp, m);
    if (st == SOAK_OK) st = parse_dry(c, cJSON_GetObjectItemCaseSensitive(j, "dry"), dp, m);
    if (st != SOAK_OK) return st;
    if (m->base == SOAK_BASE_LAMBERT) model_view_lambert(m);
    if (m->base == SOAK_BASE_GGX) model_view_ggx(m);
    if (m->base != SOAK_BASE_MEDIUM) model_view_film(m);
    return SOAK_OK;
}

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

/* Loads the presets and evaluates the chain (steady state) for the
 * request; sets m's model view. */
static soak_status eval_preset(scene_ctx *c, const char *path, const preset_request *r, soak_material *m,
                               preset_chain *out)
{
    char np[320], msg[1024];
    sj_path(np, sizeof np, path, "name");
    soak_preset_db *db = NULL;
    soak_status st = soak_presets_load(NULL, &db, msg, sizeof msg);
    if (st != SOAK_OK) return sj_fail(c, st, np, "cannot load the presets: %s", msg);
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
        if (st == SOAK_OK)
            st = r->has_base ? soak_wet_params_for_base(p, liq, &dry, r->base, &out->w_dry)
                             : soak_wetness_eval(p, liq, &dry, &out->w_dry);
        out->kind = p->kind;
        out->ior = p->ior;
        out->n = p->ior_n;
        out->k = p->ior_k;
        if (st == SOAK_OK)
            preset_model_view(&own, &out->w, r->m_per_unit, m);
        else
            st = sj_fail(c, st, path, "wetness evaluation failed (%s)", soak_status_str(st));
    }
    soak_presets_free(db);
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
    medium_majorant(med);
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
    if (m->base == SOAK_BASE_GGX) return sj_fail(c, SOAK_ERR_ARG, fp, "not for a metal preset (its film is the chain's)");
    m->film_coverage = coverage;
    m->film_pore_share = 0.0;
    m->film_thickness = thickness;
    m->dry_coat_weight = m->coat_weight; /* no pore water: every grain outside the film is in the dry draw */
    return SOAK_OK;
}

/* What parse_preset read, kept for the material's states at the wetness of
 * each point (scene_levels.c); after parse_film_over. */
static soak_status keep_recipe(const preset_request *r, int no_interface, const cJSON *j, soak_material *m)
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
    return scene_levels_keep(&rec, m);
}

soak_status scene_preset_view(const soak_preset *p, const soak_liquid *liq, const scene_preset_recipe *rec,
                              double wetness, soak_material *m)
{
    preset_chain pc;
    memset(&pc, 0, sizeof pc);
    soak_wet_input in = soak_wet_input_steady(p, wetness);
    soak_status st = rec->has_base ? soak_wet_params_for_base(p, liq, &in, rec->base, &pc.w)
                                   : soak_wetness_eval(p, liq, &in, &pc.w);
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
static soak_status parse_preset(scene_ctx *c, const cJSON *j, const char *path, soak_material *m)
{
    static const char *const keys[] = {"type", "name", "wetness", "liquid", "unit_mm", "model", "base_colour",
                                       "interface", "film_over", NULL};
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
        return sj_fail(c, SOAK_ERR_ARG, bp, "'%s' is a metal: its colour is its complex index (n, k), "
                       "base_colour wets a dielectric's or a thin sheet's own colour", r.name);
    }
    m->type = SOAK_MAT_WET;
    preset_film(&pc.w, r.m_per_unit, m);
    preset_base(&pc, r.m_per_unit, m);
    /* "interface": 0 leaves the material's own specular interface out: what a
     * front end draws with its highlights off (tests/povray/flat_ground.py) */
    if (interface < 0.5) m->coat_weight = m->dry_coat_weight = 0.0;
    st = parse_film_over(c, j, path, m);
    if (st == SOAK_OK && !r.model && pc.kind != SOAK_KIND_THIN_SHEET) st = keep_recipe(&r, interface < 0.5, j, m);
    if (st != SOAK_OK || !r.model) return st;
    char mp[320];
    sj_path(mp, sizeof mp, path, "model");
    if (cJSON_GetObjectItemCaseSensitive(j, "film_over"))
        return sj_fail(c, SOAK_ERR_ARG, mp, "a model view renders the chain's own film: leave out \"film_over\"");
    return use_model(c, mp, r.model, m);
}

soak_status scene_parse_material(scene_ctx *c, const cJSON *j, const char *path, soak_material *m)
{
    const char *type;
    soak_status st = sj_str(c, j, "type", path, 1, &type);
    if (st != SOAK_OK) return st;
    if (strcmp(type, "lambert") == 0) {
        static const char *const keys[] = {"type", "albedo", NULL};
        m->type = SOAK_MAT_LAMBERT;
        st = sj_keys(c, j, path, keys);
        if (st == SOAK_OK) st = sj_rgb(c, j, "albedo", path, 0, 1, 1, soak_rgb3(0, 0, 0), &m->albedo);
        if (st == SOAK_OK) model_view_lambert(m);
        return st;
    }
    if (strcmp(type, "dielectric") == 0) {
        static const char *const keys[] = {"type", "ior", "absorption", NULL};
        m->type = SOAK_MAT_DIELECTRIC;
        st = sj_keys(c, j, path, keys);
        if (st == SOAK_OK) st = sj_num(c, j, "ior", path, 1, 3, 0, 1.5, &m->ior);
        if (st == SOAK_OK) st = sj_rgb(c, j, "absorption", path, 0, 1e9, 0, soak_rgb3(0, 0, 0), &m->absorption);
        return st;
    }
    if (strcmp(type, "conductor") == 0) {
        static const char *const keys[] = {"type", "eta", "k", "roughness", NULL};
        m->type = SOAK_MAT_CONDUCTOR;
        st = sj_keys(c, j, path, keys);
        if (st == SOAK_OK) st = parse_ggx(c, j, path, m);
        if (st == SOAK_OK) model_view_ggx(m);
        return st;
    }
    if (strcmp(type, "wet") == 0) return parse_wet(c, j, path, m);
    if (strcmp(type, "preset") == 0) return parse_preset(c, j, path, m);
    const soak_model *model = soak_model_find(type);
    if (model) return parse_model(c, j, path, model, m);
    char tp[320];
    sj_path(tp, sizeof tp, path, "type");
    return sj_fail(c, SOAK_ERR_PARSE, tp, "unknown material type '%s' (accepted: lambert, dielectric, conductor, wet, preset, or a model of `soak eval --list`: ww, ww-triace, porous, porous-ggx, ...)",
                   type);
}

soak_status scene_parse_wetness(scene_ctx *c, const cJSON *j, const char *path, soak_wetness *w)
{
    if (cJSON_IsNumber(j)) {
        w->type = SOAK_WETNESS_CONSTANT;
        char why[128];
        soak_status st = soak_json_number(j, 0.0, 1.0, 0, &w->value, why, sizeof why);
        return st == SOAK_OK ? SOAK_OK : sj_fail(c, st, path, "%s", why);
    }
    const char *type;
    soak_status st = sj_str(c, j, "type", path, 1, &type);
    if (st != SOAK_OK) return st;
    if (strcmp(type, "map") == 0) {
        static const char *const keys[] = {"type", "file", NULL};
        const char *file;
        char fp[400], full[2048], msg[2048];
        sj_path(fp, sizeof fp, path, "file");
        st = sj_keys(c, j, path, keys);
        if (st == SOAK_OK) st = sj_str(c, j, "file", path, 1, &file);
        if (st == SOAK_OK) st = sj_file(c, file, fp, full, sizeof full);
        if (st != SOAK_OK) return st;
        st = soak_image_read(full, &w->map, msg, sizeof msg);
        if (st != SOAK_OK) return sj_fail(c, st, fp, "%s", msg);
        w->type = SOAK_WETNESS_MAP;
        size_t n = (size_t)w->map.width * w->map.height * w->map.channels;
        for (size_t i = 0; i < n; ++i)
            if (!(w->map.pixels[i] >= -1e30f && w->map.pixels[i] <= 1e30f))
                return sj_fail(c, SOAK_ERR_ARG, fp, "%s: non-finite pixel", full);
        return SOAK_OK;
    }
    if (strcmp(type, "plane") == 0) {
        static const char *const keys[] = {"type", "normal", "offset", "blend", NULL};
        w->type = SOAK_WETNESS_PLANE;
        st = sj_keys(c, j, path, keys);
        if (st == SOAK_OK) st = sj_vec3(c, j, "normal", path, 1, soak_v3(0, 0, 1), &w->normal);
        if (st == SOAK_OK) st = sj_num(c, j, "offset", path, -1e12, 1e12, 0, 0, &w->offset);
        if (st == SOAK_OK) st = sj_num(c, j, "blend", path, 0, 1e12, 0, 0, &w->blend);
        if (st != SOAK_OK) return st;
        if (!(soak_v3_len(w->normal) > 0)) {
            char np[400];
            sj_path(np, sizeof np, path, "normal");
            return sj_fail(c, SOAK_ERR_ARG, np, "must not be the zero vector");
        }
        w->normal = soak_v3_norm(w->normal);
        return SOAK_OK;
    }
    if (strcmp(type, "constant") == 0) {
        static const char *const keys[] = {"type", "value", NULL};
        w->type = SOAK_WETNESS_CONSTANT;
        st = sj_keys(c, j, path, keys);
        if (st == SOAK_OK) st = sj_num(c, j, "value", path, 0, 1, 1, 1, &w->value);
        return st;
    }
    char tp[400];
    sj_path(tp, sizeof tp, path, "type");
    return sj_fail(c, SOAK_ERR_PARSE, tp, "unknown wetness type '%s' (accepted: constant, map, plane, or a number)", type);
}

void scene_material_free(soak_material *m)
{
    scene_levels_free(m);
    if (m->medium.volume) {
        soak_volume_free(m->medium.volume);
        free(m->medium.volume);
        m->medium.volume = NULL;
    }
}

double soak_scene_wetness(const soak_object *obj, soak_vec3 p, double u, double v)
{
    const soak_wetness *w = &obj->wetness;
    double x = 1.0;
    switch (w->type) {
    case SOAK_WETNESS_CONSTANT: x = w->value; break;
    case SOAK_WETNESS_MAP: {
        const soak_image *im = &w->map;
        double fu = u - floor(u), fv = v - floor(v);
        int px = (int)(fu * im->width), py = (int)((1.0 - fv) * im->height);
        px = px < 0 ? 0 : (px >= im->width ? im->width - 1 : px);
        py = py < 0 ? 0 : (py >= im->height ? im->height - 1 : py);
        const float *pix = im->pixels + ((size_t)py * im->width + px) * im->channels;
        int nc = im->channels >= 3 ? 3 : 1;
        double s = 0;
        for (int i = 0; i < nc; ++i) s += pix[i];
        x = s / nc;
        break;
    }
    case SOAK_WETNESS_PLANE: {
        double d = soak_v3_dot(w->normal, p) - w->offset;
        x = w->blend > 0 ? 0.5 - d / w->blend : (d < 0 ? 1.0 : 0.0);
        break;
    }
    }
    return x < 0 ? 0 : (x > 1 ? 1 : x);
}

soak_status soak_scene_set_model(soak_scene *scene, const char *material, const char *model, char *err, size_t errlen)
{
    if (!scene || !material || !model) return SOAK_ERR_NULL;
    const soak_model *md = soak_model_find(model);
    soak_material *m = NULL;
    for (int i = 0; i < scene->n_materials; ++i)
        if (scene->materials[i].type != SOAK_MAT_EMITTER && strcmp(scene->materials[i].name, material) == 0) m = &scene->materials[i];
    soak_status st = !m || !md ? SOAK_ERR_NOT_FOUND : material_use_model(m, md);
    if (st != SOAK_OK && err && errlen)
        snprintf(err, errlen, "%s: material '%s' through model '%s': %s", scene->path, material, model,
                 !m ? "no such material"
                    : (!md ? "no such model"
                           : (st == SOAK_ERR_UNSUPPORTED ? "no model describes it (dielectric, emitter or medium base)"
                                                         : soak_status_str(st))));
    if (st != SOAK_OK && err && errlen) soak_message_printable(err);
    return st;
}
