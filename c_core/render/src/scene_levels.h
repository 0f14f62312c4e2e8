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
#include "soak/preset.h"
#include "soak/scene.h"

/* Uniform levels of a mapped or planar wetness (plus the knots above). */
#define SOAK_LEVELS_GRID 33

/* What parse_preset read, to build the material again at another wetness. */
typedef struct scene_preset_recipe {
    char name[64], liquid[64];
    double wetness, m_per_unit;
    int has_base;
    soak_rgb base;
    int no_interface; /* "interface": 0 */
    int film_over;    /* "film_over" given: its coverage and thickness below */
    double over_coverage, over_thickness;
} scene_preset_recipe;

typedef struct soak_material_levels soak_material_levels;
struct soak_material_levels {
    scene_preset_recipe recipe;
    int n;              /* 0: the material's one state (no object needs others) */
    double *t;          /* n object wetnesses, increasing, t[n - 1] = 1 */
    soak_material *view; /* n materials: the preset at liquid amount t[i] * wetness */
};

/* Keeps rec with m (m->levels, no levels yet). */
soak_status scene_levels_keep(const scene_preset_recipe *rec, soak_material *m);
/* After the objects: the levels of every kept material that an object
 * uses with a wetness other than the constant 1. */
soak_status scene_levels_build(scene_ctx *c, soak_scene *s);
void scene_levels_free(soak_material *m);
/* The level i at or below object wetness x (i < n - 1 when n >= 2) and x's
 * fraction of the way to level i + 1, in [0, 1]. Needs L->n >= 1. */
int scene_levels_find(const soak_material_levels *L, double x, double *frac);

/* The preset rec at liquid amount `wetness` (scene_preset.c: the code
 * that parse_preset runs), written over m's film, base and interface. */
soak_status scene_preset_view(const soak_preset *p, const soak_liquid *liq, const scene_preset_recipe *rec,
                              double wetness, soak_material *m);

#endif
