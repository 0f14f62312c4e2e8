/* Scene materials to BSDFs (soak/bsdf.h), once per render. */
#include <stdio.h>

#include "render_bsdfs.h"

/* The material's base with its own rough interface of weight coat (a
 * preset's lambert base: COATED; coat 0: the bare body). */
static void base_desc(const soak_material *m, double coat, soak_bsdf_desc *d)
{
    if (m->type == SOAK_MAT_WET && m->base == SOAK_BASE_LAMBERT && coat > 0) {
        soak_bsdf_desc_default(d, SOAK_BSDF_COATED);
        d->albedo = m->albedo;
        d->eta = soak_rgb3(m->ior, m->ior, m->ior);
        d->alpha = m->alpha;
        d->coat_weight = coat;
    } else if (m->type == SOAK_MAT_LAMBERT || (m->type == SOAK_MAT_WET && m->base == SOAK_BASE_LAMBERT)) {
        soak_bsdf_desc_default(d, SOAK_BSDF_LAMBERT);
        d->albedo = m->albedo;
    } else if (m->type == SOAK_MAT_DIELECTRIC) {
        soak_bsdf_desc_default(d, SOAK_BSDF_GLASS);
        d->ior = m->ior;
    } else if (m->type == SOAK_MAT_CONDUCTOR || (m->type == SOAK_MAT_WET && m->base == SOAK_BASE_GGX)) {
        soak_bsdf_desc_default(d, SOAK_BSDF_GGX_CONDUCTOR);
        d->eta = m->eta;
        d->k = m->k;
        d->alpha = m->alpha;
    } else {
        soak_bsdf_desc_default(d, SOAK_BSDF_LAMBERT); /* emitters, media: never shaded here */
        d->albedo = soak_rgb3(0, 0, 0);
    }
}

static void model_desc(const soak_material *m, int wet, soak_bsdf_desc *d)
{
    soak_bsdf_desc_default(d, SOAK_BSDF_MODEL);
    d->model = soak_material_model(m, wet);
    soak_material_model_params(m, wet, d->params);
}

static void film_of(const soak_material *m, int trace_films, double thickness, soak_bsdf_desc *d)
{
    d->film_ior = m->film_ior;
    d->film_absorption = m->film_absorption;
    d->film_thickness = thickness;
    d->film_traced = trace_films;
}

/* A wet surface's three draws (render_surface.c surface_mix): dry, with
 * the coat weight that holds every grain outside the film (dry_coat_weight,
 * soak/wet_specular.h point 4); the film with its thickness over the coated
 * base (the grains under the liquid, index n / n_liquid); the pore water, a
 * flat liquid surface at zero thickness over the body alone (a pore has no
 * grain facets), a draw of its own whenever it differs from the film's. */
static soak_status material_setup(const soak_material *m, int trace_films, rt_material_bsdf *out)
{
    soak_bsdf_desc d;
    out->has_wet = out->has_pore = 0;
    if (m->type == SOAK_MAT_MODEL) {
        model_desc(m, 0, &d);
        soak_status st = soak_bsdf_setup(&d, &out->dry);
        model_desc(m, 1, &d);
        if (st == SOAK_OK) st = soak_bsdf_setup(&d, &out->wet);
        out->has_wet = 1;
        return st;
    }
    int wet = m->type == SOAK_MAT_WET && m->base != SOAK_BASE_MEDIUM;
    base_desc(m, wet ? m->dry_coat_weight : m->coat_weight, &d);
    soak_status st = soak_bsdf_setup(&d, &out->dry);
    if (st != SOAK_OK || !wet) return st;
    base_desc(m, m->coat_weight, &d);
    film_of(m, trace_films, m->film_thickness, &d);
    out->has_wet = 1;
    st = soak_bsdf_setup(&d, &out->wet);
    if (st != SOAK_OK || !(m->film_pore_share > 0 && (m->film_thickness > 0 || m->coat_weight > 0))) return st;
    base_desc(m, 0.0, &d);
    film_of(m, trace_films, 0.0, &d);
    out->has_pore = 1;
    return soak_bsdf_setup(&d, &out->pore);
}

soak_status rt_bsdfs_setup(const soak_scene *s, int trace_films, rt_material_bsdf *bsdfs, char *err, size_t errlen)
{
    for (int i = 0; i < s->n_materials; ++i) {
        soak_status st = material_setup(&s->materials[i], trace_films, &bsdfs[i]);
        if (st != SOAK_OK) {
            if (err && errlen) snprintf(err, errlen, "material '%s': BSDF set-up failed (%s)", s->materials[i].name, soak_status_str(st));
            return st;
        }
    }
    return SOAK_OK;
}

soak_status rt_material_bsdf_setup(const soak_material *m, int trace_films, rt_material_bsdf *out)
{
    return material_setup(m, trace_films, out);
}
