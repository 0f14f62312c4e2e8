/* A preset's identity and optics, and a liquid, as JSON, in the order and
 * with the keys both JSON files that list presets use (`soak export
 * --target json`, `soak materials --json`), so that the two cannot drift
 * apart. */
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
void soak_json_preset_optics(soak_json *j, cJSON *o, const soak_preset *p, const char *albedo_key, int with_sources);

/* Units of a liquid's coefficients in a JSON file (the key says which). */
typedef enum soak_json_length { SOAK_JSON_PER_M, SOAK_JSON_PER_MM } soak_json_length;

/* Appends a liquid to list: name, display_name, ior, sigma_a_per_<unit>,
 * sigma_s_per_<unit>, with_film: the film's normal-incidence and
 * hemispherical reflectance (film_normal_reflectance,
 * film_hemispherical_reflectance: Fresnel at the liquid's index, a
 * zero-thickness film over a black base), then source. SOAK_ERR_NOMEM, or
 * the film's status. */
soak_status soak_json_liquid(soak_json *j, cJSON *list, const soak_liquid *l, soak_json_length unit, int with_film);

#endif
