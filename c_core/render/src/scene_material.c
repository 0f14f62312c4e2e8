/* Scene materials and per-object wetness, parsed (format: scenes/README.md;
 * scene_material.h). */
#define _POSIX_C_SOURCE 200809L
#include "scene_material.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_json.h"
#include "scene_levels.h"
#include "scene_model.h"
#include "scene_preset.h"
#include "soak/fresnel.h"
#include "soak/ggx.h"
#include "soak/json_number.h"
#include "soak/porous.h"
#include "soak/preset.h"
#include "soak/units.h"
#include "soak/wetness.h"

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

/* A model material: {"type": "<model>", albedo, ior, k, roughness, film
 * {ior, thickness, absorption}, porosity, sp, fill, ks, ks_water}. */
static soak_status parse_model(scene_ctx *c, const cJSON *j, const char *path, const soak_model *model,
                               soak_material *m)
{
    static const char *const keys[] = {"type",     "albedo", "ior",  "k",  "roughness", "film",
                                       "porosity", "sp",     "fill", "ks", "ks_water",  NULL};
    static const char *const fkeys[] = {"ior", "thickness", "absorption", NULL};
    soak_model_params d;
    soak_model_params_default(&d);
    soak_rgb albedo, ior, k, absorption = soak_rgb3(0, 0, 0);
    double rough, n_film = SOAK_WATER_IOR, thick = 0, por, sp, fill, ks, ksw;
    soak_status st = sj_keys(c, j, path, keys);
    if (st == SOAK_OK) st = sj_rgb(c, j, "albedo", path, 0, 1, 0, soak_rgb3(d.albedo, d.albedo, d.albedo), &albedo);
    if (st == SOAK_OK)
        st = sj_rgb(c, j, "ior", path, SOAK_ETA_MIN, SOAK_ETA_MAX, 0, soak_rgb3(d.ior, d.ior, d.ior), &ior);
    if (st == SOAK_OK) st = sj_rgb(c, j, "k", path, 0, SOAK_GGX_K_MAX, 0, soak_rgb3(0, 0, 0), &k);
    if (st == SOAK_OK)
        st = sj_num(c, j, "roughness", path, SOAK_GGX_ALPHA_MIN, SOAK_GGX_ALPHA_MAX, 0, d.roughness, &rough);
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
    scene_model_view_lambert(m);
    scene_model_view_film(m);
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
    if (m->base != SOAK_BASE_MEDIUM)
        return sj_fail(c, SOAK_ERR_ARG, dp, "dry medium parameters need base.type \"medium\"");
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
    if (m->base == SOAK_BASE_LAMBERT) scene_model_view_lambert(m);
    if (m->base == SOAK_BASE_GGX) scene_model_view_ggx(m);
    if (m->base != SOAK_BASE_MEDIUM) scene_model_view_film(m);
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
        if (st == SOAK_OK) scene_model_view_lambert(m);
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
        if (st == SOAK_OK) scene_model_view_ggx(m);
        return st;
    }
    if (strcmp(type, "wet") == 0) return parse_wet(c, j, path, m);
    if (strcmp(type, "preset") == 0) return scene_parse_preset(c, j, path, m);
    const soak_model *model = soak_model_find(type);
    if (model) return parse_model(c, j, path, model, m);
    char tp[320];
    sj_path(tp, sizeof tp, path, "type");
    return sj_fail(c, SOAK_ERR_PARSE, tp,
                   "unknown material type '%s' (accepted: lambert, dielectric, conductor, wet, preset, or a model of "
                   "`soak eval --list`: ww, ww-triace, porous, porous-ggx, ...)",
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
    return sj_fail(c, SOAK_ERR_PARSE, tp, "unknown wetness type '%s' (accepted: constant, map, plane, or a number)",
                   type);
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
