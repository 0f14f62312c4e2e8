// The beach rock in four wetness states ([JLD99] sec. 4.2): dry, mixed (wet
// below a wave line), pores full (the rock covered: darker, no film yet) and
// all wet (a water film: darker and glossy).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.15;
#include "soak.inc"
camera { location <0, -9, 3> look_at <0, 0, 0.6> sky z up z right -x * 2 angle 48 }
light_source { <-0.5, -0.6, 0.7> * 1e4 rgb 1 parallel point_at 0 }
sky_sphere { pigment { gradient z color_map { [0 rgb <0.6, 0.7, 0.8>] [1 rgb <0.25, 0.4, 0.7>] } } }
plane { z, 0 pigment { rgb <0.44, 0.39, 0.25> } finish { ambient 0.15 diffuse 1 } }
#declare Sat = Soak_Preset_Saturation[Soak_Preset_Index("limestone")];
#declare Wave = function { min(max((0.7 - z) / 0.1 + 0.5, 0), 1) }
#declare States = array[4]
#declare States[0] = function { 0 }
#declare States[1] = function { Wave(x, y, z) }
#declare States[2] = function { Sat }
#declare States[3] = function { 1 }
#declare I = 0;
#while (I < 4)
  #declare F = function { States[I](x, y, z) }
  sphere { 0, 1 scale <1, 1, 0.75> translate <(I - 1.5) * 2.3, 0, 0.75>
    Soak_Wet_Material_Bumped("limestone", "water", F, normal { granite 0.25 scale 0.4 }) }
  #undef F
  #declare I = I + 1;
#end
