/* Puddles that level (soak/bake_rain.h step 3): the water a depression of
 * the surface collects fills it to a horizontal surface no higher than its
 * spill level, and what exceeds that spills over the sill. Private to the
 * bake layer and exposed to white-box tests. */
#ifndef SOAK_BAKE_RAIN_LEVEL_H
#define SOAK_BAKE_RAIN_LEVEL_H

#include "soak/status.h"

#include "bake_rain_flow.h"

/* Levels depth (metres, w * h) in every depression of g's surface: the
 * spill levels come from a priority flood of g->level over the covered
 * texels (outlets: texels with an open edge or a drip); each depression's
 * water (depth * area summed) becomes a horizontal surface, and a volume
 * over the depression's capacity goes to the sill texel it spills over.
 * Volume is conserved up to rounding. */
soak_status soak_rain_level(const soak_rain_flow_grid *g, double *depth);

/* The same in two parts: the flood and the depressions, once per surface
 * (g's arrays are borrowed, not copied), and the filling, every step. */
typedef struct soak_rain_level_plan soak_rain_level_plan;
soak_status soak_rain_level_create(const soak_rain_flow_grid *g, soak_rain_level_plan **out);
soak_status soak_rain_level_run(const soak_rain_level_plan *lp, double *depth);
void soak_rain_level_destroy(soak_rain_level_plan *lp);

#endif
