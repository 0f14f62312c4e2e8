// Gallery: a concrete ground wetting from left to right (film coverage grows with the
// wetness) into a puddle at the right; two polished copper balls, dry on the dry
// ground (left) and under a water film in the puddle (right). A hazy evening sky with
// clouds over a dark tree line, and a sunlit brick facade behind the viewer, give the
// copper and the water something to mirror.
// Declare=Dry=1: the same scene dry (wetness 0 everywhere).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.35;
#include "soak.inc"
camera { location <0.5, -0.95, 0.72> look_at <0.5, 0.42, 0.02> sky z up z right -x * image_width / image_height angle 52 }
light_source { <-0.8, 0.45, 0.5> * 1e4 rgb <1.5, 1.25, 0.95> parallel point_at 0 }
// the sky: hazy blue above, warm towards the horizon, clouds, a dark tree line on the horizon
#declare Cloud = function { pattern { bozo turbulence 0.6 octaves 6 omega 0.55 lambda 2.2 scale <0.3, 0.3, 0.06> } }
#declare Trees = function { pattern { bozo turbulence 0.3 octaves 5 scale <0.04, 0.04, 1> } }
#declare Sky_Blue = pigment { gradient z color_map { [0 rgb <1.35, 1.1, 0.8>] [0.12 rgb <1.0, 0.95, 0.85>] [0.4 rgb <0.75, 0.76, 0.82>] [1 rgb <0.55, 0.6, 0.75>] } }
#declare Sky = pigment { function { Cloud(x, y, z) }
  pigment_map { [0 Sky_Blue] [0.48 Sky_Blue] [0.62 rgb <1.45, 1.3, 1.1>] [1 rgb <1.2, 1.1, 1.0>] } }
sky_sphere { pigment { function { select(z - 0.02 - 0.05 * Trees(x, y, 0), 0, 0.99) }
  pigment_map { [0 rgb <0.05, 0.08, 0.05>] [0.5 rgb <0.05, 0.08, 0.05>] [0.5 Sky] [1 Sky] } } }
#ifndef(Dry) #declare Dry = 0; #end
#declare Wet = function { (1 - Dry) * min(max(x, 0), 1) }
box { <0, 0, -0.1>, <1, 1, 0>
  Soak_Puddle_Material("concrete", "water", Wet, 0.7, normal { granite 0.2 scale 0.05 }) }
sphere { <0.25, 0.6, 0.12>, 0.12 Soak_Wet_Material("copper", "water", 0) }
sphere { <0.84, 0.6, 0.12>, 0.12 Soak_Wet_Material("copper", "water", 1 - Dry) }
// the gallery's surroundings: a dry paving around the tile
plane { z, -0.1 Soak_Wet_Material("asphalt", "water", 0) }
// behind the viewer: a sunlit brick facade with windows (mirrored in the balls)
#declare Bricks = pigment { brick rgb 0.55, rgb <0.36, 0.14, 0.08> brick_size <0.25, 0.1, 0.085> mortar 0.012 rotate 90 * x }
union {
  difference {
    box { <-4, -3.6, -0.1>, <5, -3.4, 2.6> }
    #for (I, 0, 5) box { <-2.7 + I * 1.4, -3.7, 0.8>, <-2.0 + I * 1.4, -3.3, 1.9> } #end
  }
  texture { pigment { Bricks } finish { ambient 0.2 diffuse 0.8 } }
}
#for (I, 0, 5) box { <-2.7 + I * 1.4, -3.55, 0.8>, <-2.0 + I * 1.4, -3.5, 1.9> pigment { rgb 0.03 } finish { ambient 0 diffuse 0.2 reflection 0.1 } } #end
