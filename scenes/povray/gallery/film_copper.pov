// Gallery: a concrete ground wetting from left to right (film coverage grows with the
// wetness) into a puddle at the right; copper panels under a water film (left) and dry (right).
// Declare=Dry=1: the same scene dry (wetness 0 everywhere; the benchmark's dry scene).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.2;
#include "soak.inc"
camera { location <0.5, -0.95, 0.85> look_at <0.5, 0.42, 0.02> sky z up z right -x * image_width / image_height angle 52 }
light_source { <-0.3, 0.8, 0.6> * 1e4 rgb 1 parallel point_at 0 }
sky_sphere { pigment { gradient z color_map { [0 rgb 0.8] [1 rgb <0.3, 0.45, 0.8>] } } }
#ifndef(Dry) #declare Dry = 0; #end
#declare Wet = function { (1 - Dry) * min(max(x, 0), 1) }
box { <0, 0, -0.1>, <1, 1, 0>
  Soak_Puddle_Material("concrete", "water", Wet, 0.8, normal { granite 0.2 scale 0.05 }) }
box { <0.05, 0.55, 0>, <0.45, 0.6, 0.4> Soak_Wet_Material("copper", "water", 1 - Dry) }
box { <0.55, 0.55, 0>, <0.95, 0.6, 0.4> Soak_Wet_Material("copper", "water", 0) }
// the gallery's surroundings: a dry paving around the tile, for the film and the copper to reflect
plane { z, -0.1 Soak_Wet_Material("concrete", "water", 0) }
