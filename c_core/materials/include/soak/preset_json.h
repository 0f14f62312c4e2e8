/* A preset's identity and optics as JSON, in the order and with the keys both
 * JSON files that list presets use (`soak export --target json`, `soak
 * materials --json`), so that the two cannot drift apart. */
#ifndef SOAK_PRESET_JSON_H
#define SOAK_PRESET_JSON_H

#include "soak/json_writer.h"
#include "soak/preset.h"

/* Adds to o: name, display_name, kind, the dry albedo under albedo_key,
 * ggx_alpha_dry, ggx_alpha_wet, the complex index (ior_n, ior_k) of a
 * conductor or the real ior of anything else, porosity and
 * saturation_wetness (the porosity for porous kinds, else 0). with_sources:
 * each group's source string after its values (albedo_source,
 * roughness_source, ior_source). Failures clear j->ok. */
void soak_json_preset_optics(soak_json *j, cJSON *o, const soak_preset *p, const char *albedo_key,
                             int with_sources);

#endif
