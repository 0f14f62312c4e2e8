/* One table of every BRDF model and fast path, behind a uniform parameter
 * set, so `soak eval`, the benchmark and the all-model tests treat them
 * alike. Each entry wraps the model's own header; no physics lives here.
 * A fast path names its exact peer (`exact`), against which the benchmark
 * reports the error. */
#ifndef SOAK_MODELS_H
#define SOAK_MODELS_H

#include <stddef.h>

#include "soak/status.h"
#include "soak/vec.h"

typedef struct soak_model_params {
    double albedo;     /* diffuse albedo of the base, [0,1] (default 0.5) */
    double ior;        /* base index relative to air (default 1.5; metals: n) */
    double k;          /* base extinction for conductors (default 0) */
    double roughness;  /* GGX alpha of the base, [1e-4,1] (default 0.3) */
    double n_film;     /* liquid index, [1,3] (default SOAK_WATER_IOR = 1.333; 1 = no film) */
    double absorption; /* liquid absorption coefficient per length unit (default 0.35: water, 1/m) */
    double thickness;  /* film thickness in that length unit (default 1e-3: 1 mm in m) */
    double porosity;   /* [0,1] (default 0.3) */
    double sp;         /* pore depth/diameter (default 2) */
    double fill;       /* pore fill fraction, [0,1] (default 1) */
    double ks;         /* Blinn-Phong specular coefficient for the porous model (default 0.05) */
    double ks_water;   /* water specular coefficient, [0, 0.5] (default 0.02; SOAK_POROUS_KS_WATER_MAX) */
} soak_model_params;

void soak_model_params_default(soak_model_params *p);

/* Opaque per-model set-up data (tables, precomputed constants). */
typedef struct soak_model_ctx {
    _Alignas(16) unsigned char bytes[4096];
} soak_model_ctx;

typedef struct soak_model {
    const char *name;
    const char *summary;
    const char *exact; /* exact peer of a fast path, NULL for exact models */
    soak_status (*setup)(const soak_model_params *p, soak_model_ctx *ctx);
    /* The model's own evaluation (its header's contract: both directions
     * strictly above the horizon). Call soak_model_eval instead. */
    soak_status (*eval)(const soak_model_ctx *ctx, soak_vec3 wi, soak_vec3 wo, double *f);
    /* Optional (NULL when the model has none; soak/bsdf.h then samples a
     * cosine + GGX mixture). The model's own importance sampling: given wo
     * and u0, u1, u2 in [0, 1], a direction wi with f = eval(wi, wo) and its
     * solid-angle density; pdf = 0 means no sample. pdf() gives the same
     * density for a given pair. */
    soak_status (*sample)(const soak_model_ctx *ctx, soak_vec3 wo, double u0, double u1, double u2, soak_vec3 *wi,
                          double *f, double *pdf);
    soak_status (*pdf)(const soak_model_ctx *ctx, soak_vec3 wi, soak_vec3 wo, double *pdf);
    /* Optional: reflectance of the model's delta (mirror) lobe at cos_o,
     * which eval leaves out (ww's film top). NULL: no delta lobe. */
    soak_status (*mirror)(const soak_model_ctx *ctx, double cos_o, double *R);
    /* Optional: eval's value without eval's checks, for a context whose
     * set-up returned SOAK_OK and unit directions strictly above the
     * horizon; soak_model_eval checks the directions once and calls this.
     * Call soak_model_eval instead. */
    double (*eval_fast)(const soak_model_ctx *ctx, soak_vec3 wi, soak_vec3 wo);
} soak_model;

const soak_model *soak_models(size_t *count);
const soak_model *soak_model_find(const char *name);

/* BRDF (1/sr) without the cosine, the same contract for every model: ctx
 * from a successful set-up of the same model (else SOAK_ERR_ARG), wi, wo
 * unit within 1e-5 (else SOAK_ERR_ARG, which also catches NaN/Inf); a
 * direction at or below the horizon (z <= 0) gives f = 0; a NaN, Inf or
 * negative value is SOAK_ERR_NUMERIC, never returned. The parameters are
 * validated once, at set-up: this checks the directions and the result. */
soak_status soak_model_eval(const soak_model *m, const soak_model_ctx *ctx, soak_vec3 wi, soak_vec3 wo, double *f);

#endif
