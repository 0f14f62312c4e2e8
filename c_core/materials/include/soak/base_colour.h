/* The wetness function for any base colour: artists wet their own textured
 * materials, so a preset is also a class of materials (porosity, phase
 * change, extinction, film, liquid) whose dry colour the user chooses.
 * `soak albedo --base-colour` evaluates it; `soak export` tabulates it for
 * the front ends (soak_export_base_nodes, soak/export.h). */
#ifndef SOAK_BASE_COLOUR_H
#define SOAK_BASE_COLOUR_H

#include "soak/preset.h"
#include "soak/status.h"
#include "soak/wetness.h"

/* soak_wetness_eval for the preset's class with its dry albedo replaced by
 * dry (each channel in [0,1]). Dielectrics: the dry medium is re-derived
 * from the new albedo (soak_preset_derive). Conductors: dry is read as the
 * normal-incidence reflectance in air and mapped to n, k per channel by
 * Gulbrandsen 2014 (JCGT 3(4), "Artist friendly metallic Fresnel") with the
 * preset's own edge tint, then covered by the film as usual. */
soak_status soak_wet_params_for_base(const soak_preset *preset, const soak_liquid *liquid, const soak_wet_input *in,
                                     soak_rgb dry, soak_wet_params *out);

#endif
