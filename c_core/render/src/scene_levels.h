/* A preset's states at the wetness of each point (scene_levels.c).
 *
 * The front ends evaluate a preset's chain at the point's liquid amount
 * L = wetness * (wet map) (blender_addon/soak/wet_group.py; povray/soak.inc
 * Soak_Wet_Texture_Fn with the map as the wetness function; osl/ Wetness
 * input). The reference does the same: at scene load the chain is evaluated
 * at levels t_i of the object's wetness (L = t_i * wetness: a uniform grid,
 * the saturation point where the pores are full and the film starts, and
 * every constant object wetness used with the material), each level a
 * complete material (film, base, interface) built by the same code as the
 * material itself. Between levels the BSDF is interpolated linearly in t. */
#ifndef SOAK_SCENE_LEVELS_H
#define SOAK_SCENE_LEVELS_H

#include "scene_json.h"
#include "scene_preset.h"
#include "soak/scene.h"

/* Uniform levels of a mapped or planar wetness (plus the knots above). */
#define SOAK_LEVELS_GRID 33

/* After the objects: the levels of every kept material that an object
 * uses with a wetness other than the constant 1. */
soak_status scene_levels_build(scene_ctx *c, soak_scene *s);
void scene_levels_free(soak_material *m);
/* The level i at or below object wetness x (i < n - 1 when n >= 2) and x's
 * fraction of the way to level i + 1, in [0, 1]. Needs L->n >= 1. */
int scene_levels_find(const soak_material_levels *L, double x, double *frac);

#endif
