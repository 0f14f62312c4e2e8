/* BSDF set-up and dispatch over the adaptors (soak/bsdf.h). */
#include <string.h>

#include "bsdf_internal.h"
#include "soak/ggx.h"

void soak_bsdf_desc_default(soak_bsdf_desc *d, soak_bsdf_kind kind)
{
    memset(d, 0, sizeof *d);
    d->kind = kind;
    d->albedo = soak_rgb3(0.5, 0.5, 0.5);
    d->eta = soak_rgb3(1.5, 1.5, 1.5);
    d->alpha = 0.1;
    d->ior = 1.5;
    d->coat_weight = 1.0;
    d->film_ior = 1.0;
    for (int ch = 0; ch < 3; ++ch) soak_model_params_default(&d->params[ch]);
}

static soak_status film_check(const soak_bsdf_desc *d)
{
    if (!soak_in_range(d->film_ior, 1, 3) || !soak_in_range(d->film_thickness, 0, 1e3)) return SOAK_ERR_ARG;
    for (int ch = 0; ch < 3; ++ch)
        if (!soak_in_range(soak_rgb_at(d->film_absorption, ch), 0, 1e9)) return SOAK_ERR_ARG;
    if (d->film_ior == 1.0) return SOAK_OK;
    return d->kind == SOAK_BSDF_LAMBERT || d->kind == SOAK_BSDF_GGX_CONDUCTOR || d->kind == SOAK_BSDF_GGX_DIELECTRIC ||
                   d->kind == SOAK_BSDF_COATED
               ? SOAK_OK
               : SOAK_ERR_ARG; /* glass and the models carry their own interfaces */
}

static soak_status base_setup(soak_bsdf *b)
{
    switch (b->d.kind) {
    case SOAK_BSDF_LAMBERT: return bsdf_lambert_setup(b);
    case SOAK_BSDF_GGX_CONDUCTOR:
    case SOAK_BSDF_GGX_DIELECTRIC: return bsdf_ggx_setup(b);
    case SOAK_BSDF_GLASS: return bsdf_glass_setup(b);
    case SOAK_BSDF_MODEL: return bsdf_model_setup(b);
    case SOAK_BSDF_COATED: return bsdf_coated_setup(b);
    }
    return SOAK_ERR_ARG;
}

/* A film over the base: closed form over Lambert when it applies, else the
 * traced layer. The base then sits in the liquid: its index is relative to it. */
static void layer_setup(soak_bsdf *b)
{
    double n2 = b->d.film_ior;
    b->flags |= SOAK_BSDF_DELTA;
    if (b->d.kind == SOAK_BSDF_LAMBERT && !b->d.film_traced && bsdf_film_setup(b) == SOAK_OK) {
        b->closed_film = 1;
        return;
    }
    b->d.eta = soak_rgb_scale(b->d.eta, 1.0 / n2);
    b->d.k = soak_rgb_scale(b->d.k, 1.0 / n2);
    if (b->d.kind == SOAK_BSDF_COATED) bsdf_coated_tables(b); /* the interface is now material/liquid */
    b->flags |= SOAK_BSDF_WALK;
}

soak_status soak_bsdf_setup(const soak_bsdf_desc *d, soak_bsdf *b)
{
    if (!d || !b) return SOAK_ERR_NULL;
    memset(b, 0, sizeof *b);
    b->d = *d;
    soak_status st = film_check(d);
    if (st == SOAK_OK) st = base_setup(b);
    if (st != SOAK_OK) return st;
    if (d->film_ior > 1.0) layer_setup(b);
    return SOAK_OK;
}

int soak_bsdf_get_flags(const soak_bsdf *b) { return b ? b->flags : 0; }

void bsdf_base_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    if (b->d.kind == SOAK_BSDF_LAMBERT) bsdf_lambert_eval(b, wi, wo, f, pdf);
    else if (b->d.kind == SOAK_BSDF_COATED) bsdf_coated_eval(b, wi, wo, f, pdf);
    else bsdf_ggx_eval(b, wi, wo, f, pdf);
}

int bsdf_base_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s)
{
    if (b->d.kind == SOAK_BSDF_LAMBERT) return bsdf_lambert_sample(b, wo, u, s);
    if (b->d.kind == SOAK_BSDF_COATED) return bsdf_coated_sample(b, wo, u, s);
    return bsdf_ggx_sample(b, wo, u, s);
}

static int finite_rgb(soak_rgb c) { return soak_is_finite(c.r) && soak_is_finite(c.g) && soak_is_finite(c.b); }

soak_status soak_bsdf_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    if (!b) return SOAK_ERR_NULL;
    if (!soak_v3_is_unit(wi) || !soak_v3_is_unit(wo)) return SOAK_ERR_ARG;
    if (b->flags & SOAK_BSDF_WALK) return SOAK_ERR_UNSUPPORTED;
    soak_rgb fv = soak_rgb3(0, 0, 0);
    double pv = 0;
    soak_status st = SOAK_OK;
    if (b->closed_film) bsdf_film_eval(b, wi, wo, &fv, &pv);
    else if (b->d.kind == SOAK_BSDF_MODEL) st = bsdf_model_eval(b, wi, wo, &fv, &pv);
    else if (b->d.kind != SOAK_BSDF_GLASS) bsdf_base_eval(b, wi, wo, &fv, &pv);
    if (st != SOAK_OK) return st;
    if (!finite_rgb(fv) || !soak_is_finite(pv)) return SOAK_ERR_NUMERIC;
    if (f) *f = fv;
    if (pdf) *pdf = pv;
    return SOAK_OK;
}

soak_status soak_bsdf_pdf(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, double *pdf)
{
    return soak_bsdf_eval(b, wi, wo, NULL, pdf);
}

soak_status soak_bsdf_sample_dir(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok)
{
    if (!b || !u || !s || !ok) return SOAK_ERR_NULL;
    if (!soak_v3_is_unit(wo)) return SOAK_ERR_ARG;
    for (int i = 0; i < 3; ++i)
        if (!soak_in_range(u[i], 0, 1)) return SOAK_ERR_ARG;
    if (b->flags & SOAK_BSDF_WALK) return SOAK_ERR_UNSUPPORTED;
    memset(s, 0, sizeof *s);
    s->eta = 1.0;
    *ok = 0;
    soak_status st = SOAK_OK;
    if (b->d.kind == SOAK_BSDF_GLASS) *ok = bsdf_glass_sample(b, wo, u, s);
    else if (!(wo.z > 0)) *ok = 0;
    else if (b->closed_film) *ok = bsdf_film_sample(b, wo, u, s);
    else if (b->d.kind == SOAK_BSDF_MODEL) st = bsdf_model_sample(b, wo, u, s, ok);
    else *ok = bsdf_base_sample(b, wo, u, s);
    if (st != SOAK_OK) return st;
    if (*ok && (!finite_rgb(s->weight) || !soak_is_finite(s->pdf))) return SOAK_ERR_NUMERIC;
    return SOAK_OK;
}
