/* A preset's BSDFs at its levels of liquid (render_levels.c). */
#ifndef SOAK_RENDER_LEVELS_H
#define SOAK_RENDER_LEVELS_H

#include "rt_ctx.h"

/* Sets up out[i] (n_materials entries) for every material with levels. */
soak_status rt_levels_setup(const soak_scene *s, int trace_films, rt_levels *out, char *err, size_t errlen);
void rt_levels_free(rt_levels *levels, int n_materials);
/* The material state a hit of obj is shaded with: *m and *mb (the
 * material's own on entry) become a drawn level's when the material has
 * levels. Returns the probability of the liquid's interface (film or pore
 * water) at the hit. */
double rt_level_at(rt_thread *t, const soak_object *obj, const soak_hit *hit, const soak_material **m,
                   const rt_material_bsdf **mb);

#endif
