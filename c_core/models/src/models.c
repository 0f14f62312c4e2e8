/* Adapters from soak_model_params to each model's own API (soak/models.h). */
#include "soak/models.h"
#include "soak/fresnel.h"

#include <math.h>
#include <string.h>

#include "soak/film.h"
#include "soak/ggx.h"
#include "soak/porous.h"
#include "soak/ww.h"

#include "fast_paths.h"

_Static_assert(sizeof(soak_porous_ggx) + sizeof(double) <= sizeof(soak_model_ctx), "model context too small");

typedef double (*eval_fast_fn)(const soak_model_ctx *ctx, soak_vec3 wi, soak_vec3 wo);

/* A set-up that succeeds for a model with eval_fast writes that function's
 * pointer into the last bytes of the context; soak_model_eval runs the
 * unchecked eval_fast only on a context that carries its own model's mark
 * (one comparison instead of re-validating every parameter per call). */
#define CTX_MARK_AT (sizeof(soak_model_ctx) - sizeof(eval_fast_fn))

static soak_status ctx_mark(soak_model_ctx *c, soak_status st, eval_fast_fn fn)
{
    eval_fast_fn none = NULL;
    memcpy(c->bytes + CTX_MARK_AT, st == SOAK_OK ? &fn : &none, sizeof fn);
    return st;
}

static int ctx_marked(const soak_model_ctx *c, eval_fast_fn fn)
{
    eval_fast_fn mark;
    memcpy(&mark, c->bytes + CTX_MARK_AT, sizeof mark);
    return mark == fn;
}

void soak_model_params_default(soak_model_params *p)
{
    p->albedo = 0.5;
    p->ior = 1.5;
    p->k = 0.0;
    p->roughness = 0.3;
    p->n_film = SOAK_WATER_IOR;
    p->absorption = 0.35;
    p->thickness = 1e-3;
    p->porosity = 0.3;
    p->sp = 2.0;
    p->fill = 1.0;
    p->ks = 0.05;
    p->ks_water = 0.02;
}


/* Every set-up starts here: a NaN or Inf in any field is a caller's error
 * even where the chosen model ignores that field (otherwise a NaN k would
 * silently pick the dielectric branch of ww or ggx). k is checked for every
 * model because it selects the base (k > 0: conductor). */
static soak_status params_ok(const soak_model_params *p)
{
    if (!p) return SOAK_ERR_NULL;
    const double v[] = {p->albedo, p->ior,      p->k,        p->roughness, p->n_film, p->absorption,
                        p->thickness, p->porosity, p->sp, p->fill,      p->ks,     p->ks_water};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; ++i)
        if (!soak_is_finite(v[i])) return SOAK_ERR_ARG;
    return soak_in_range(p->k, 0.0, SOAK_GGX_K_MAX) ? SOAK_OK : SOAK_ERR_ARG;
}

/* soak_v3_is_unit for two directions with one branch: |v|^2 - 1 is exact
 * near 1, and a NaN or Inf component fails the comparison. */
static int both_unit(const soak_vec3 *a, const soak_vec3 *b)
{
    double la = a->x * a->x + a->y * a->y + a->z * a->z, lb = b->x * b->x + b->y * b->y + b->z * b->z;
    return (fabs(la - 1.0) <= SOAK_UNIT_TOL) & (fabs(lb - 1.0) <= SOAK_UNIT_TOL);
}

/* --- Lambert ------------------------------------------------------------ */
typedef struct { double albedo; } lambert_ctx;
static soak_status lambert_setup(const soak_model_params *p, soak_model_ctx *c)
{
    soak_status ok = params_ok(p);
    if (ok != SOAK_OK) return ok;
    if (!soak_in_range(p->albedo, 0.0, 1.0)) return SOAK_ERR_ARG;
    ((lambert_ctx *)c->bytes)->albedo = p->albedo;
    return SOAK_OK;
}
static soak_status lambert_eval(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo, double *f)
{
    (void)wi;
    (void)wo;
    *f = ((const lambert_ctx *)c->bytes)->albedo * SOAK_INV_PI;
    return SOAK_OK;
}

/* --- GGX base, dry --------------------------------------------------------- */
typedef struct { double alpha, eta, k; } ggx_ctx;
static soak_status ggx_setup(const soak_model_params *p, soak_model_ctx *c)
{
    soak_status ok = params_ok(p);
    if (ok != SOAK_OK) return ok;
    ggx_ctx *g = (ggx_ctx *)c->bytes;
    g->alpha = p->roughness;
    g->eta = p->ior;
    g->k = p->k;
    double f;
    /* Validate through the model itself at normal incidence. */
    soak_vec3 n = soak_v3(0, 0, 1);
    return p->k > 0.0 ? soak_ggx_brdf_conductor(p->roughness, p->ior, p->k, n, n, &f)
                      : soak_ggx_brdf_dielectric(p->roughness, p->ior, n, n, &f);
}
static soak_status ggx_dielectric_eval(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo, double *f)
{
    const ggx_ctx *g = (const ggx_ctx *)c->bytes;
    return soak_ggx_brdf_dielectric(g->alpha, g->eta, wi, wo, f);
}
static soak_status ggx_conductor_eval(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo, double *f)
{
    const ggx_ctx *g = (const ggx_ctx *)c->bytes;
    return soak_ggx_brdf_conductor(g->alpha, g->eta, g->k, wi, wo, f);
}

/* --- Lekner-Dorf film over Lambert ----------------------------------------- */
typedef struct { soak_film film; soak_film_ctx ctx; double albedo; film_fast fast; } film_ctx;
_Static_assert(sizeof(film_ctx) <= CTX_MARK_AT, "film context overlaps the set-up mark");
static soak_status film_setup(const soak_model_params *p, soak_model_ctx *c)
{
    soak_status ok = params_ok(p);
    if (ok != SOAK_OK) return ok;
    film_ctx *m = (film_ctx *)c->bytes;
    m->film.n = p->n_film;
    m->film.alpha = p->absorption;
    m->film.thickness = p->thickness;
    m->albedo = p->albedo;
    if (!soak_in_range(p->albedo, 0.0, 1.0)) return SOAK_ERR_ARG;
    soak_status st = soak_film_setup(&m->film, &m->ctx);
    if (st == SOAK_OK) m->fast = film_fast_make(&m->ctx, m->albedo);
    return st;
}
static soak_status film_eval(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo, double *f)
{
    const film_ctx *m = (const film_ctx *)c->bytes;
    return soak_film_brdf(&m->film, m->albedo, wi, wo, f);
}
static soak_status film_mirror(const soak_model_ctx *c, double cos_o, double *R)
{
    return soak_film_specular(&((const film_ctx *)c->bytes)->film, cos_o, R);
}
static soak_status film_ctx_eval(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo, double *f)
{
    const film_ctx *m = (const film_ctx *)c->bytes;
    return soak_film_ctx_brdf(&m->ctx, m->albedo, wi, wo, f);
}
static inline double film_ctx_value(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo)
{
    return film_brdf_fast(&((const film_ctx *)c->bytes)->fast, wi, wo);
}
static double film_ctx_eval_fast(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo)
{
    return film_ctx_value(c, wi, wo);
}
static soak_status film_ctx_setup(const soak_model_params *p, soak_model_ctx *c)
{
    return ctx_mark(c, film_setup(p, c), film_ctx_eval_fast);
}

/* --- Weidlich-Wilkie with a water layer, and the Tri-Ace fast path ---------- */
typedef struct { soak_ww ww; soak_ww_triace fast; triace_fast k; } ww_ctx;
_Static_assert(sizeof(ww_ctx) <= CTX_MARK_AT, "ww context overlaps the set-up mark");
static soak_status ww_setup(const soak_model_params *p, soak_model_ctx *c)
{
    soak_status ok = params_ok(p);
    if (ok != SOAK_OK) return ok;
    ww_ctx *m = (ww_ctx *)c->bytes;
    soak_ww_default(&m->ww);
    m->ww.base = p->k > 0.0 ? SOAK_WW_CONDUCTOR : SOAK_WW_DIELECTRIC;
    m->ww.n_water = p->n_film;
    m->ww.absorption = p->absorption;
    m->ww.thickness = p->thickness;
    m->ww.alpha = p->roughness;
    m->ww.n_base = p->ior;
    m->ww.k_base = p->k;
    m->ww.kd = m->ww.base == SOAK_WW_DIELECTRIC ? p->albedo : 0.0;
    return soak_ww_validate(&m->ww);
}
static soak_status ww_triace_setup(const soak_model_params *p, soak_model_ctx *c)
{
    soak_status st = ww_setup(p, c);
    if (st != SOAK_OK) return st;
    ww_ctx *m = (ww_ctx *)c->bytes;
    st = soak_ww_triace_setup(&m->ww, &m->fast); /* n_water in [SOAK_WW_TRIACE_N_MIN, _MAX] */
    if (st == SOAK_OK) m->k = triace_fast_make(&m->fast);
    return st;
}
static soak_status ww_eval(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo, double *f)
{
    return soak_ww_eval(&((const ww_ctx *)c->bytes)->ww, wi, wo, f);
}
static soak_status ww_mirror(const soak_model_ctx *c, double cos_o, double *R)
{
    return soak_ww_specular(&((const ww_ctx *)c->bytes)->ww, cos_o, R);
}
/* The fast path's film top is Schlick's T12 = 1 - R (soak_ww_eval_triace):
 * its mirror lobe takes the same R so that the two add to the same split. */
static soak_status ww_triace_mirror(const soak_model_ctx *c, double cos_o, double *R)
{
    return soak_fresnel_schlick(cos_o, ((const ww_ctx *)c->bytes)->fast.r0_top, R);
}
static soak_status ww_triace_eval(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo, double *f)
{
    return soak_ww_eval_triace(&((const ww_ctx *)c->bytes)->fast, wi, wo, f);
}
/* The raw form takes the directions as given (unit within 1e-5): the
 * refracted directions it builds are renormalised inside. */
static inline double ww_triace_value(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo)
{
    return triace_eval_fast(&((const ww_ctx *)c->bytes)->k, wi, wi.x * wi.x + wi.y * wi.y, wo, wo.x * wo.x + wo.y * wo.y);
}
static double ww_triace_eval_fast(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo)
{
    return ww_triace_value(c, wi, wo);
}
static soak_status ww_triace_setup_marked(const soak_model_params *p, soak_model_ctx *c)
{
    return ctx_mark(c, ww_triace_setup(p, c), ww_triace_eval_fast);
}

/* --- Merillou porous + Hnat wetting (Blinn-Phong), and the GGX variant ----- */
typedef struct { soak_porous_params p; double fill; } porous_ctx;
static soak_status porous_setup(const soak_model_params *p, soak_model_ctx *c)
{
    soak_status ok = params_ok(p);
    if (ok != SOAK_OK) return ok;
    porous_ctx *m = (porous_ctx *)c->bytes;
    memset(&m->p, 0, sizeof m->p);
    m->p.kd = p->albedo;
    m->p.ks = p->ks;
    /* Beckmann RMS slope from GGX alpha (same second moment) and [Lag13]'s
     * Blinn-Phong exponent n = 2/m^2 - 2, clamped at 0. */
    m->p.m = p->roughness;
    double n = 2.0 / (p->roughness * p->roughness) - 2.0;
    m->p.spec_power = n < 0.0 ? 0.0 : (n > SOAK_POROUS_POWER_MAX ? SOAK_POROUS_POWER_MAX : n);
    m->p.porosity = p->porosity;
    m->p.sp = p->sp;
    m->p.ks_water = p->ks_water;
    m->p.water_power = 200.0;
    m->p.norm = SOAK_BLINN_NORM_ENERGY;
    m->fill = p->fill;
    if (!soak_in_range(p->fill, 0.0, 1.0)) return SOAK_ERR_ARG;
    return soak_porous_validate(&m->p);
}
static soak_status porous_eval(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo, double *f)
{
    const porous_ctx *m = (const porous_ctx *)c->bytes;
    return soak_porous_eval(&m->p, m->fill, wi, wo, f);
}
/* The porous samplers take the given direction first; the models are
 * reciprocal, so sampling wi for wo is the same density. */
static soak_status porous_sample(const soak_model_ctx *c, soak_vec3 wo, double u0, double u1, double u2,
                                 soak_vec3 *wi, double *f, double *pdf)
{
    const porous_ctx *m = (const porous_ctx *)c->bytes;
    return soak_porous_sample(&m->p, m->fill, wo, u0, u1, u2, wi, f, pdf);
}
static soak_status porous_pdf(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo, double *pdf)
{
    const porous_ctx *m = (const porous_ctx *)c->bytes;
    return soak_porous_pdf(&m->p, m->fill, wo, wi, pdf);
}

typedef struct { soak_porous_ggx g; double fill; } porous_ggx_ctx;
static soak_status porous_ggx_setup(const soak_model_params *p, soak_model_ctx *c)
{
    soak_status ok = params_ok(p);
    if (ok != SOAK_OK) return ok;
    porous_ggx_ctx *m = (porous_ggx_ctx *)c->bytes;
    soak_porous_ggx_params q = {.albedo = p->albedo,
                                .roughness = p->roughness,
                                .eta = p->ior,
                                .porosity = p->porosity,
                                .sp = p->sp,
                                .water_roughness = 0.02,
                                .eta_water = p->n_film};
    m->fill = p->fill;
    if (!soak_in_range(p->fill, 0.0, 1.0)) return SOAK_ERR_ARG;
    return soak_porous_ggx_setup(&q, &m->g);
}
static soak_status porous_ggx_eval(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo, double *f)
{
    const porous_ggx_ctx *m = (const porous_ggx_ctx *)c->bytes;
    return soak_porous_ggx_eval(&m->g, m->fill, wi, wo, f);
}
static soak_status porous_ggx_sample(const soak_model_ctx *c, soak_vec3 wo, double u0, double u1, double u2,
                                     soak_vec3 *wi, double *f, double *pdf)
{
    const porous_ggx_ctx *m = (const porous_ggx_ctx *)c->bytes;
    return soak_porous_ggx_sample(&m->g, m->fill, wo, u0, u1, u2, wi, f, pdf);
}
static soak_status porous_ggx_pdf(const soak_model_ctx *c, soak_vec3 wi, soak_vec3 wo, double *pdf)
{
    const porous_ggx_ctx *m = (const porous_ggx_ctx *)c->bytes;
    return soak_porous_ggx_pdf(&m->g, m->fill, wo, wi, pdf);
}

static const soak_model models[] = {
    {"lambert", "Lambertian base, albedo/pi", NULL, lambert_setup, lambert_eval, NULL, NULL, NULL, NULL},
    {"ggx-dielectric", "dry GGX microfacet specular of a dielectric (Walter et al. 2007)", NULL, ggx_setup,
     ggx_dielectric_eval, NULL, NULL, NULL, NULL},
    {"ggx-conductor", "dry GGX microfacet conductor with complex IOR (--ior n --k k)", NULL, ggx_setup,
     ggx_conductor_eval, NULL, NULL, NULL, NULL},
    {"film", "Lekner-Dorf water film over Lambert, all interreflections (diffuse part; exact)", NULL, film_setup,
     film_eval, NULL, NULL, film_mirror, NULL},
    {"film-ctx", "the same film with its hemispherical averages precomputed once", "film", film_ctx_setup, film_ctx_eval, NULL, NULL, film_mirror,
     film_ctx_eval_fast},
    {"ww", "Weidlich-Wilkie layered BRDF: smooth water over GGX dielectric (+Lambert) or conductor (non-delta part)",
     NULL, ww_setup, ww_eval, .mirror = ww_mirror},
    {"ww-triace", "Tri-Ace fast path of ww: F_bottom, linear absorption, no refraction", "ww", ww_triace_setup_marked,
     ww_triace_eval, .mirror = ww_triace_mirror, .eval_fast = ww_triace_eval_fast},
    {"porous", "Merillou porous post-process with Hnat wetting on Blinn-Phong (Hnat et al. 2006)", NULL, porous_setup,
     porous_eval, porous_sample, porous_pdf, NULL, NULL},
    {"porous-ggx", "energy-conserving porous wetting on a GGX + Fresnel base", NULL, porous_ggx_setup,
     porous_ggx_eval, porous_ggx_sample, porous_ggx_pdf, NULL, NULL},
};

const soak_model *soak_models(size_t *count)
{
    if (count) *count = sizeof models / sizeof models[0];
    return models;
}

const soak_model *soak_model_find(const char *name)
{
    if (!name) return NULL;
    for (size_t i = 0; i < sizeof models / sizeof models[0]; ++i)
        if (strcmp(models[i].name, name) == 0) return &models[i];
    return NULL;
}

/* The fast paths of this file by name, so that the compiler puts their
 * bodies (fast_paths.h) here: no indirect call, no copy of the directions. */
static inline double eval_fast_inline(eval_fast_fn fn, const soak_model_ctx *ctx, const soak_vec3 *wi, const soak_vec3 *wo)
{
    if (fn == ww_triace_eval_fast) {
        const triace_fast *k = &((const ww_ctx *)ctx->bytes)->k;
        return triace_eval_fast(k, *wi, wi->x * wi->x + wi->y * wi->y, *wo, wo->x * wo->x + wo->y * wo->y);
    }
    if (fn == film_ctx_eval_fast) return film_brdf_fast(&((const film_ctx *)ctx->bytes)->fast, *wi, *wo);
    return fn(ctx, *wi, *wo);
}

soak_status soak_model_eval(const soak_model *m, const soak_model_ctx *ctx, soak_vec3 wi, soak_vec3 wo, double *f)
{
    if (!m || !ctx || !f) return SOAK_ERR_NULL;
    const soak_vec3 *a = &wi, *b = &wo;
    if (!both_unit(a, b)) return SOAK_ERR_ARG;
    if (!(a->z > 0.0 && b->z > 0.0)) {
        *f = 0.0;
        return SOAK_OK;
    }
    double v;
    if (m->eval_fast) {
        if (!ctx_marked(ctx, m->eval_fast)) return SOAK_ERR_ARG;
        v = eval_fast_inline(m->eval_fast, ctx, a, b);
    } else {
        soak_status st = m->eval(ctx, wi, wo, &v);
        if (st != SOAK_OK) return st;
    }
    if (!(v >= 0.0 && v <= 1e300)) return SOAK_ERR_NUMERIC;
    *f = v;
    return SOAK_OK;
}
