/* A path meeting a surface (render_surface.c). */
#ifndef SOAK_RENDER_SURFACE_H
#define SOAK_RENDER_SURFACE_H

#include "rt_ctx.h"

/* Handles the surface interaction at hit: gathers next-event estimates into
 * path->L, updates beta and sets the next ray (or alive = 0). */
void rt_surface(rt_thread *t, const soak_hit *hit, rt_path *path);

#endif
