/* A scene's preset materials (scene_preset.c): step 2 of the reader
 * (scene_material.c parses, this resolves a preset through the wetness
 * chain, scene_levels.c builds its states at other wetnesses from the
 * recipe kept here). Internal to the render layer. */
#ifndef SOAK_SCENE_PRESET_H
#define SOAK_SCENE_PRESET_H

#include "scene_json.h"
#include "soak/preset.h"
#include "soak/scene.h"

/* What parse_preset read, to build the material again at another wetness. */
typedef struct scene_preset_recipe {
    char name[64], liquid[64];
    double wetness, m_per_unit;
    int has_base;
    soak_rgb base;
    int no_interface; /* "interface": 0 */
    int film_over;    /* "film_over" given: its coverage and thickness below */
    double over_coverage, over_thickness;
    double saturation; /* the chain's liquid amount where the pores are full (wetness.h step 2) */
} scene_preset_recipe;

/* A preset material's states at the object wetnesses it is seen at
 * (scene_levels.h); the recipe is kept by scene_parse_preset. */
typedef struct soak_material_levels soak_material_levels;
struct soak_material_levels {
    scene_preset_recipe recipe;
    int n;               /* 0: the material's one state (no object needs others) */
    double *t;           /* n object wetnesses, increasing, t[n - 1] = 1 */
    soak_material *view; /* n materials: the preset at liquid amount t[i] * wetness */
};

/* The scene's presets, loaded on first use into c->db (once per scene);
 * path names the material asking, for the message. */
soak_status scene_presets_db(scene_ctx *c, const char *path, const soak_preset_db **db);

/* {"type": "preset", ...} at path into m (scenes/README.md). */
soak_status scene_parse_preset(scene_ctx *c, const cJSON *j, const char *path, soak_material *m);

/* The preset rec at liquid amount `wetness` (the code scene_parse_preset
 * runs), written over m's film, base and interface. */
soak_status scene_preset_view(const soak_preset *p, const soak_liquid *liq, const scene_preset_recipe *rec,
                              double wetness, soak_material *m);

#endif
