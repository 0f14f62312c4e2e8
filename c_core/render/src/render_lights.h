/* Lights and the environment map (render_lights.c). */
#ifndef SOAK_RENDER_LIGHTS_H
#define SOAK_RENDER_LIGHTS_H

#include "rt_ctx.h"

soak_status rt_env_build(rt_env *env, const soak_environment *e);
void rt_env_free(rt_env *env);
soak_rgb rt_env_eval(const rt_ctx *c, soak_vec3 dir);
double rt_env_pdf(const rt_ctx *c, soak_vec3 dir);

typedef struct rt_light_sample {
    soak_vec3 wi; /* unit, toward the light */
    double dist;  /* distance to the light point (INFINITY for directional/env) */
    soak_rgb L;   /* radiance (area/env) or delta value (irradiance E, I/r^2) */
    double pdf;   /* solid angle pdf; 0 for delta lights */
} rt_light_sample;

/* Light index in [0, n_lights) or n_lights for the environment. Returns 0 if
 * the light cannot illuminate p (inside a sphere light, zero value). */
int rt_light_sample_at(rt_thread *t, int light, soak_vec3 p, rt_light_sample *s);
int rt_light_count(const rt_ctx *c); /* lights + the environment if it is a map */
/* Solid-angle pdf of sampling direction wi toward sphere light l from p. */
double rt_sphere_light_pdf(const soak_light *l, soak_vec3 p);
/* 1 when the segment from p (offset already applied) along wi up to dist is free. */
int rt_visible(rt_thread *t, soak_vec3 p, soak_vec3 wi, double dist);

#endif
