/* A scene material's views for the renderer (scene_model.c), built once
 * at load by the material parsers (scene_material.c, scene_preset.c).
 * model_params describe a material in the models' terms (per channel): the
 * dry albedo, base index, roughness, the liquid film and the pore fill.
 * wet_albedo is the albedo of models that do not model pores themselves
 * (the preset chain's darkened subsurface albedo; the albedo otherwise).
 * Internal to the render layer. */
#ifndef SOAK_SCENE_MODEL_H
#define SOAK_SCENE_MODEL_H

#include "scene_json.h"
#include "soak/preset.h"
#include "soak/scene.h"
#include "soak/wetness.h"

/* The largest extinction of a medium over its channels (and its grid). */
void scene_medium_majorant(soak_scene_medium *m);

/* The model view of a Lambertian or GGX base, and of the material's film. */
void scene_model_view_lambert(soak_material *m);
void scene_model_view_ggx(soak_material *m);
void scene_model_view_film(soak_material *m);
/* The model view of a preset's chain state: dry albedo and pores for the
 * porous models, the chain's subsurface albedo for the others. */
void scene_preset_model_view(const soak_preset *p, const soak_wet_params *w, double m_per_unit, soak_material *m);

/* m rendered through model (SOAK_ERR_UNSUPPORTED: m has no model view). */
soak_status scene_material_use_model(soak_material *m, const soak_model *model);
/* The same for the model called name ("model" at path), with the message. */
soak_status scene_use_model(scene_ctx *c, const char *path, const char *name, soak_material *m);

#endif
