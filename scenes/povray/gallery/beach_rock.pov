// Gallery: the beach rock in four states ([JLD99] sec. 4.2, Fig. 6 a-d, left to
// right): dry; wet at its foot below the last wave's line; pores full; all wet with a
// film. On sand wet up to the water line, in a low evening sun.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.18;
#include "soak.inc"
camera { location <0, -9.5, 2.6> look_at <0, 0, 0.5> sky z up z right -x * image_width / image_height angle 50 }
light_source { <-0.7, -0.35, 0.35> * 1e4 rgb <1.25, 1.1, 0.9> parallel point_at 0 }
#include "hdri_sky.inc"
Soak_HDRI_Sky("forest_x0.45.hdr", -60)     // as scenes/gallery/beach_rock.json
// sand: wet towards the sea (far side, y > 1.5) with a soft edge
#declare Sea = function { 0.45 * min(max((y - 1.2) / 0.6, 0), 1) }   // up to pores full and a thin film
plane { z, 0 Soak_Wet_Material_Bumped("sand", "water", Sea, normal { bumps 0.05 scale 0.2 }) }
#declare Sat = Soak_Preset_Saturation[Soak_Preset_Index("limestone")];
#declare Wave = function { min(max((0.55 - z) / 0.08 + 0.5, 0), 1) }
#declare States = array[4]
#declare States[0] = function { 0 }
#declare States[1] = function { Wave(x, y, z) }
#declare States[2] = function { Sat }
#declare States[3] = function { 1 }
#declare I = 0;
#while (I < 4)
  #declare F = function { States[I](x, y, z) }
  sphere { 0, 1 scale <1, 0.9, 0.7> rotate z * (25 * I - 30) translate <(I - 1.5) * 2.4, 0, 0.6>
    Soak_Wet_Material_Bumped("limestone", "water", F, normal { granite 0.3 scale 0.5 }) }
  #undef F
  #declare I = I + 1;
#end
