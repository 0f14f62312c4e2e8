/* The scene's materials and per-object wetness, parsed (scene_material.c):
 * step 1 of the reader (scene.c parse -> scene_preset.c resolve presets ->
 * scene_levels.c build levels). Internal to the render layer. */
#ifndef SOAK_SCENE_MATERIAL_H
#define SOAK_SCENE_MATERIAL_H

#include "scene_json.h"
#include "soak/scene.h"

/* materials.<name> at path into m: every type of scenes/README.md. */
soak_status scene_parse_material(scene_ctx *c, const cJSON *j, const char *path, soak_material *m);
/* An object's "wetness": a number, constant, map or plane. */
soak_status scene_parse_wetness(scene_ctx *c, const cJSON *j, const char *path, soak_wetness *w);
void scene_material_free(soak_material *m);

#endif
