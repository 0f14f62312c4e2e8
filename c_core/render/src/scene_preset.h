/* A scene's preset materials (scene_preset.c) and what they share with the
 * other materials of scene_material.c. Internal to the render layer. */
#ifndef SOAK_SCENE_PRESET_H
#define SOAK_SCENE_PRESET_H

#include "scene_json.h"
#include "soak/preset.h"
#include "soak/scene.h"
#include "soak/wetness.h"

/* {"type": "preset", ...} at path into m (scenes/README.md). */
soak_status scene_parse_preset(scene_ctx *c, const cJSON *j, const char *path, soak_material *m);

/* The model view of a preset's chain state: dry albedo and pores for the
 * porous models, the chain's subsurface albedo for the others. */
void scene_preset_model_view(const soak_preset *p, const soak_wet_params *w, double m_per_unit, soak_material *m);

/* m rendered through the model called name ("model" at path). */
soak_status scene_use_model(scene_ctx *c, const char *path, const char *name, soak_material *m);

/* The largest extinction of a medium over its channels (and its grid). */
void scene_medium_majorant(soak_scene_medium *m);

#endif
