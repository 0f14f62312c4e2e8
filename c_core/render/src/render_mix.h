/* A surface's dry / wet / pore BSDFs as one mixture (render_mix.c). */
#ifndef SOAK_RENDER_MIX_H
#define SOAK_RENDER_MIX_H

#include "rt_ctx.h"

typedef struct rt_bsdf_mix {
    int n; /* components (1: a single BSDF) */
    const soak_bsdf *b[3];
    double w[3]; /* shares, summing to 1 */
    int chosen;  /* the component drawn for the continuation */
} rt_bsdf_mix;
/* 1 when every component is closed-form and reflecting (see render_mix.c). */
int rt_mix_can(const rt_bsdf_mix *m);
int rt_mix_flags(const rt_bsdf_mix *m);
soak_status rt_mix_eval(const rt_bsdf_mix *m, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf);
int rt_mix_reweight(const rt_bsdf_mix *m, soak_vec3 wo, soak_bsdf_sample *s);

#endif
