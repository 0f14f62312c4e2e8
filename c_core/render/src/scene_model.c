/* A scene material's views for the renderer, built once at load: its
 * parameters in the models' terms (soak_models()), the switch to render it
 * through a model, and a medium's majorant (scene_model.h). */
#define _POSIX_C_SOURCE 200809L
#include "scene_model.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "soak/units.h"

void scene_medium_majorant(soak_scene_medium *m)
{
    double mj =
        soak_rgb_max(soak_rgb3(m->sigma_s.r + m->sigma_a.r, m->sigma_s.g + m->sigma_a.g, m->sigma_s.b + m->sigma_a.b));
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

void scene_model_view_film(soak_material *m)
{
    for (int ch = 0; ch < 3; ++ch) {
        soak_model_params *q = &m->model_params[ch];
        q->n_film = m->film_ior;
        q->absorption = soak_rgb_at(m->film_absorption, ch);
        q->thickness = m->film_thickness;
        q->fill = 1.0;
    }
}

void scene_model_view_lambert(soak_material *m)
{
    model_view_base(m);
    for (int ch = 0; ch < 3; ++ch) m->model_params[ch].albedo = soak_rgb_at(m->albedo, ch);
    m->wet_albedo = m->albedo;
}

void scene_model_view_ggx(soak_material *m)
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
soak_status scene_material_use_model(soak_material *m, const soak_model *model)
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

soak_status scene_use_model(scene_ctx *c, const char *path, const char *name, soak_material *m)
{
    const soak_model *model = soak_model_find(name);
    if (!model) return sj_fail(c, SOAK_ERR_NOT_FOUND, path, "no model named '%s' (see `soak eval --list`)", name);
    soak_status st = scene_material_use_model(m, model);
    if (st != SOAK_OK)
        return sj_fail(c, st, path, "the model '%s' rejects this material's parameters (%s)", name,
                       soak_status_str(st));
    return SOAK_OK;
}

soak_status soak_scene_set_model(soak_scene *scene, const char *material, const char *model, char *err, size_t errlen)
{
    if (!scene || !material || !model) return SOAK_ERR_NULL;
    const soak_model *md = soak_model_find(model);
    soak_material *m = NULL;
    for (int i = 0; i < scene->n_materials; ++i)
        if (scene->materials[i].type != SOAK_MAT_EMITTER && strcmp(scene->materials[i].name, material) == 0)
            m = &scene->materials[i];
    soak_status st = !m || !md ? SOAK_ERR_NOT_FOUND : scene_material_use_model(m, md);
    if (st != SOAK_OK && err && errlen)
        snprintf(err, errlen, "%s: material '%s' through model '%s': %s", scene->path, material, model,
                 !m ? "no such material"
                    : (!md ? "no such model"
                           : (st == SOAK_ERR_UNSUPPORTED ? "no model describes it (dielectric, emitter or medium base)"
                                                         : soak_status_str(st))));
    if (st != SOAK_OK && err && errlen) soak_message_printable(err);
    return st;
}
