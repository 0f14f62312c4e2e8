/* Scene materials and per-object wetness (format: scenes/README.md). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_json.h"
#include "scene_levels.h"
#include "scene_preset.h"
#include "soak/fresnel.h"
#include "soak/ggx.h"
#include "soak/json_number.h"
#include "soak/porous.h"
#include "soak/preset.h"
#include "soak/units.h"
#include "soak/wetness.h"

void scene_medium_majorant(soak_scene_medium *m)
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
    if (st == SOAK_OK) scene_medium_majorant(m);
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
void scene_preset_model_view(const soak_preset *p, const soak_wet_params *w, double m_per_unit, soak_material *m)
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

soak_status scene_use_model(scene_ctx *c, const char *path, const char *name, soak_material *m)
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
    return scene_use_model(c, tp, model->name, m);
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
    scene_medium_majorant(&m->dry_medium);
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
    if (strcmp(type, "preset") == 0) return scene_parse_preset(c, j, path, m);
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
