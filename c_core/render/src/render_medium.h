/* Random walks in wet media (render_medium.c). */
#ifndef SOAK_RENDER_MEDIUM_H
#define SOAK_RENDER_MEDIUM_H

#include "rt_ctx.h"
#include "render_stack.h"

/* Wet material with a scattering base: enters at hit (from air, direction
 * path->dir), walks, exits or dies. */
void rt_wet_medium(rt_thread *t, const soak_hit *hit, const soak_object *obj, const soak_material *m, rt_path *path);

/* The scene medium as the random walk of soak/medium.h sees it: homogeneous
 * per-channel, or the grid (trilinear, cell-centred) under its majorant. */
soak_medium_rgb rt_medium_rgb(const soak_scene_medium *m);
/* Walk options of the renderer: roulette on max beta below 1/2, cap RT_MEDIUM_MAX_EVENTS. */
soak_walk_options rt_walk_options(soak_rgb beta);
/* Walk boundary: the scene's surfaces, the wet film stack of a medium object
 * crossed upward on arrival (reflection back in, or exit). */
typedef struct rt_med_surface {
    soak_hit hit;    /* last surface found by the distance callback */
    int lost;        /* the ray missed every surface: open geometry */
    soak_vec3 n_ref; /* outward normal of the last surface crossed */
} rt_med_surface;
typedef struct rt_med_boundary {
    rt_thread *t;
    rt_med_surface *surf;
    const soak_object *obj;
    const soak_material *m;
    const rt_stack *stack;
} rt_med_boundary;
soak_boundary rt_med_boundary_make(const rt_med_boundary *b);

#endif
