/* The air | film | material layer stack of a wet surface (render_stack.c). */
#ifndef SOAK_RENDER_STACK_H
#define SOAK_RENDER_STACK_H

#include "rt_ctx.h"

/* The air | film | material layer stack of a wet surface. */
typedef struct rt_stack {
    double n2, n3, k; /* film (1 and no absorbing thickness = none), material, Fresnel exponent */
    soak_rgb alpha;   /* film absorption, 1/length */
    double h;         /* film thickness */
} rt_stack;

/* The stack a path meets entering wet medium material m at wetness wet:
 * one draw picks the film (probability wet x coverage, with its thickness),
 * of those a share film_pore_share of pore water (the same interface, no
 * thickness), or dry (no film). */
rt_stack rt_wet_stack(rt_thread *t, const soak_material *m, double wet);

/* Fresnel of the interfaces a path meets (unpolarised, exact): eta = n_t/n_i. */
double rt_fresnel(double cos_i, double eta, double *cos_t);
/* Crosses the stack with Snell invariant p = n sin(theta), starting in the
 * material going up (start_low) or in air going down. Returns 1 when it ends
 * in the material, 0 in air. Multiplies *beta by the film absorption only. */
int rt_cross_stack(rt_thread *t, const rt_stack *s, double p, int start_low, soak_rgb *beta);
/* Direction with tangential unit tdir and invariant p in a medium of index n. */
soak_vec3 rt_snell_dir(soak_vec3 tdir, soak_vec3 n_out, double p, double n, int up);

#endif
