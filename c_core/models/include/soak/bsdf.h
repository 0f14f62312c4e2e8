/* One BSDF interface over every reflectance model, for the path tracer and
 * for tests and tools that compare models: set-up once (parameters
 * sanitised there), then eval / sample / pdf per shading point, RGB-valued.
 * Modelled on Cycles' closure files (setup, eval, sample) and pbrt-v4's
 * BxDFs (f, Sample_f, PDF, Flags; CoatedDiffuse / CoatedConductor for the
 * film as a layer over a base).
 *
 * Conventions: unit directions in the local shading frame, normal +z; wo
 * points to the viewer, wi to the light. f is in 1/sr without the cosine;
 * pdf is the solid-angle density of sample() producing wi for this wo
 * (delta lobes excluded: eval and pdf describe the non-delta part). RGB
 * models that the library defines per channel (soak/models.h) are set up
 * once per channel.
 *
 * Kinds (adaptor files bsdf_<kind>.c):
 *   LAMBERT         albedo / pi                                  diffuse
 *   GGX_CONDUCTOR   Walter et al. 2007 with complex index (soak/ggx.h) glossy
 *   GGX_DIELECTRIC  the same, reflection only, real index       glossy
 *   GLASS           smooth dielectric, reflection + refraction  delta, two-sided
 *   MODEL           an entry of soak_models() (ww, ww-triace, porous,
 *                   porous-ggx, ...): eval per channel; sampled by the
 *                   model's own sampler (of the green channel) when it has
 *                   one, else a one-sample mixture of a cosine lobe and GGX
 *                   visible normals at the model's roughness; a model's
 *                   mirror lobe (ww's film top) is the delta lobe.
 *   COATED          a rough dielectric interface (GGX of width alpha, index
 *                   eta, weight coat_weight = ks) over a Lambertian base of
 *                   albedo A, the interfaces' light summed in closed form
 *                   (bsdf_coated.c):
 *                     f = ks f_ggx(wi, wo)
 *                       + A (1 - ks E(wi)) (1 - ks E(wo)) / (pi (1 - A ks E_avg))
 *                   E(mu): the GGX lobe's directional albedo, E_avg = 2 int E mu dmu.
 *                   It is what a first-surface interface gives (the grains'
 *                   facets of a granular material: light that is not reflected
 *                   by the facets enters the body unrefracted, and light leaving
 *                   the body meets the same facets from below and is sent back
 *                   with the same probability ks E); soak measure --config coated
 *                   traces that stack photon by photon. Energy: the directional
 *                   albedo is ks E(wo) + (1 - ks E(wo)) A (1 - ks E_avg) / (1 - A ks E_avg)
 *                   <= 1 for A <= 1 (= 1 at A = 1); symmetric in wi, wo.
 * A film (film_ior > 1) makes a LAMBERT / GGX base a layered BSDF: smooth
 * liquid of index n2 and Beer-Lambert absorption over the base, with every
 * interreflection between base and film underside ([JLD99] sec. 2.1 / 3.1,
 * Lekner & Dorf 1988):
 *   - closed form over LAMBERT (soak/film.h): a delta mirror lobe of
 *     reflectance F12(cos_o) plus the diffuse Lekner-Dorf BSDF; eval / sample
 *     / pdf as for any BSDF;
 *   - traced over any other base, or when desc.film_traced (flag
 *     SOAK_BSDF_WALK): the same contract, estimated by random walks through
 *     the layer in the spirit of pbrt-v4's LayeredBxDF (Pharr, Jakob &
 *     Humphreys, PBR 4th ed., sec. 14.3): eval's f is an unbiased estimate
 *     (bsdf_walk.c: one walk, every bounce's light at the base summed, the
 *     underside's Fresnel taken as a weight), pdf an unbiased estimate of
 *     sample()'s exit density from an independent walk, and sample() the
 *     walk that the renderer used to follow itself (weight: its throughput,
 *     whose mean given wi is f cos / pdf). Each estimate's random stream is
 *     a hash of its directions, so eval is a function: the same pair gives
 *     the same value, a light's and a sample's MIS weights see the same pdf
 *     and still sum to one. soak_bsdf_eval_mean averages independent
 *     estimates (and gives their standard error).
 *
 * Set-up clamps (documented, the only ones): GGX alpha below
 * SOAK_GGX_ALPHA_MIN is raised to it (a narrower lobe is a mirror that
 * double precision cannot resolve); everything else outside its range, NaN
 * or Inf is rejected with SOAK_ERR_ARG. eval/sample/pdf never return
 * NaN/Inf with SOAK_OK. */
#ifndef SOAK_BSDF_H
#define SOAK_BSDF_H

#include <stdint.h>

#include "soak/film.h"
#include "soak/models.h"
#include "soak/status.h"
#include "soak/vec.h"

typedef enum soak_bsdf_flags {
    SOAK_BSDF_DIFFUSE = 1,
    SOAK_BSDF_GLOSSY = 2,
    SOAK_BSDF_DELTA = 4,    /* has a delta lobe (mirror or refraction) */
    SOAK_BSDF_TRANSMIT = 8, /* can send light through the surface (glass) */
    SOAK_BSDF_WALK = 16     /* traced layer: eval and pdf are estimates (soak_bsdf_eval_mean) */
} soak_bsdf_flags;

typedef enum soak_bsdf_kind {
    SOAK_BSDF_LAMBERT = 0,
    SOAK_BSDF_GGX_CONDUCTOR,
    SOAK_BSDF_GGX_DIELECTRIC,
    SOAK_BSDF_GLASS,
    SOAK_BSDF_MODEL,
    SOAK_BSDF_COATED
} soak_bsdf_kind;

/* Nodes of the COATED interface's albedo table E(mu), mu = i / (N - 1). */
#define SOAK_BSDF_COAT_NODES 48

/* What set-up reads; fields a kind does not use are ignored. */
typedef struct soak_bsdf_desc {
    soak_bsdf_kind kind;
    soak_rgb albedo;   /* LAMBERT, [0, 1] */
    soak_rgb eta, k;   /* GGX: index relative to air; k = 0 for GGX_DIELECTRIC */
    double alpha;      /* GGX width, (0, 1]; below SOAK_GGX_ALPHA_MIN raised to it */
    double coat_weight; /* COATED: ks, the interface's specular weight, [0, 1] */
    double ior;        /* GLASS, [1, 3] */
    const soak_model *model;      /* MODEL */
    soak_model_params params[3];  /* MODEL, per channel */
    double film_ior;   /* [1, 3]; 1 = no film */
    soak_rgb film_absorption; /* per length unit, [0, 1e9] */
    double film_thickness;    /* length unit (any: only their product counts), [0, 1e3] */
    int film_traced;   /* 1: walk through the film even over Lambert */
} soak_bsdf_desc;

/* A desc of the given kind with neutral values (no film, alpha 0.1, ior 1.5,
 * coat_weight 1). */
void soak_bsdf_desc_default(soak_bsdf_desc *d, soak_bsdf_kind kind);

typedef struct soak_bsdf {
    soak_bsdf_desc d;   /* sanitised copy; GGX eta, k are relative to the film */
    int flags;
    const struct soak_bsdf_ops *ops;  /* the kind's entry points (or its film's) */
    const struct soak_bsdf_ops *base; /* the kind's own, under a film */
    soak_film_ctx film[3];
    soak_model_ctx model[3];
    double coat_E[3][SOAK_BSDF_COAT_NODES]; /* COATED: E(mu) per channel */
    double coat_E_avg[3];                    /* 2 int E(mu) mu dmu of the interpolant */
} soak_bsdf;

typedef struct soak_bsdf_sample {
    soak_vec3 wi;
    soak_rgb weight; /* f cos / pdf (delta: the lobe's reflectance / its probability) */
    double pdf;      /* solid angle; 0 for a delta lobe */
    int delta;       /* 1: wi is a delta direction (no MIS) */
    double eta;      /* GLASS refraction: n_t / n_i crossed; 1 otherwise */
} soak_bsdf_sample;

soak_status soak_bsdf_setup(const soak_bsdf_desc *d, soak_bsdf *b);
int soak_bsdf_get_flags(const soak_bsdf *b);

/* Non-delta part: f (1/sr, per channel) and the pdf of sampling wi for wo.
 * Either output may be NULL. Pairs with wi.z <= 0 or wo.z <= 0 give 0 (for
 * GLASS always 0). SOAK_BSDF_WALK: both are estimates (see above). Outputs
 * are written only on SOAK_OK (as every function here). */
soak_status soak_bsdf_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf);
/* The pdf alone (no f evaluated): what eval gives as *pdf. */
soak_status soak_bsdf_pdf(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, double *pdf);
/* Mean of n independent estimates of f (streams chosen by seed), its
 * standard error and the mean of the pdf estimates (se, pdf may be NULL); a
 * closed-form BSDF: its f and pdf, se 0, for any n in [1, 1e9]. */
soak_status soak_bsdf_eval_mean(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, long n, uint64_t seed, soak_rgb *f,
                                 soak_rgb *se, double *pdf);
/* Samples wi for wo with u[0..2] in [0, 1). Returns SOAK_OK with *ok = 0
 * when no direction results (below the horizon): the path ends. GLASS
 * accepts wo on either side (wo.z < 0: from inside). */
soak_status soak_bsdf_sample_dir(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok);

/* ---- Cost ----
 * Mean CPU time of one eval (RGB, value and pdf) over a fixed set of 64
 * direction pairs, repeated n_rounds times; for reports, never for tests. */
soak_status soak_bsdf_eval_cost_ns(const soak_bsdf *b, int n_rounds, double *ns);
/* The loop that soak_bsdf_eval_cost_ns times, untimed: n evaluations over the
 * same 64 direction pairs, their sum in checksum (for instruction counts
 * under valgrind, which must see the work done). */
soak_status soak_bsdf_eval_loop(const soak_bsdf *b, long n, double *checksum);

#endif
