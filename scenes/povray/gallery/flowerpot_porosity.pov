// Gallery: the flowerpot porosity sweep: one terracotta colour, each pot with its pores
// just full (wetness = the preset's saturation, no film yet), with the wetting
// class of presets of increasing porosity (left to right; the leftmost, the
// non-porous class, stays dry): the more porous, the darker and glossier.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.15;
#include "soak.inc"
camera { location <0.9, -11, 4.6> look_at <0.9, 1.3, 0.6> sky z up z right -x * image_width / image_height angle 52 }
light_source { <-0.4, -0.8, 0.8> * 1e4 rgb 1 parallel point_at 0 }
sky_sphere { pigment { gradient z color_map { [0 rgb 0.7] [1 rgb <0.35, 0.45, 0.7>] } } }
plane { z, 0 pigment { rgb 0.5 } finish { ambient 0.15 diffuse 1 } }
#declare Terracotta = pigment { rgb <0.555, 0.212, 0.11> }
// presets sorted by their saturation wetness (the open porosity)
#declare N = Soak_N_Presets;
#declare Order = array[N]
#declare I = 0; #while (I < N) #declare Order[I] = I; #declare I = I + 1; #end
#declare I = 0;
#while (I < N)
  #declare J = I + 1;
  #while (J < N)
    #if (Soak_Preset_Saturation[Order[J]] < Soak_Preset_Saturation[Order[I]])
      #declare Tmp = Order[I]; #declare Order[I] = Order[J]; #declare Order[J] = Tmp;
    #end
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
#declare K = 0;
#declare I = 0;
#while (I < N)
  #declare P = Order[I];
  #if (Soak_Preset_Kind[P] != 2) // dielectrics only
    union {
      difference { cone { 0, 0.55, <0, 0, 1.4>, 0.8 } cone { <0, 0, 0.1>, 0.47, <0, 0, 1.45>, 0.72 } }
      torus { 0.78, 0.06 rotate x * 90 translate z * 1.4 }
      translate <(mod(K, 5) - 2) * 2.1 + 0.6 * div(K, 5), div(K, 5) * 2.6, 0>  // two rows of five, front row first
      Soak_Wet_User_Material(Soak_Preset_Names[P], "water", Soak_Preset_Saturation[P], Terracotta)
    }
    #declare K = K + 1;
  #end
  #declare I = I + 1;
#end
