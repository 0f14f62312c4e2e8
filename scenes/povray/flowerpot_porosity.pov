// The flowerpot porosity sweep of [Hnat06] Fig. 5: one terracotta colour on the
// clay class with its open porosity alpha_poro = 0, 0.1 ... 0.5 (left to right;
// presets clay_p00 ... clay_p50 of `soak export --variant`, which
// povray/render_scenes.sh exports into a soak_materials.inc beside the scene),
// each with its pores just full (wetness = the saturation = the porosity, no
// film yet): the more porous, the darker and glossier. Seen from the side with an
// orthographic camera, so each pot's body is at a known column
// (tests/povray/scenes_check.py measures them).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.15;
#include "soak.inc"
camera { orthographic location <0, -20, 0.75> look_at <0, 0, 0.75> sky z up z * 4.5 right -x * 12 }
light_source { <-0.4, -0.8, 0.8> * 1e4 rgb 1 parallel point_at 0 }
sky_sphere { pigment { gradient z color_map { [0 rgb 0.7] [1 rgb <0.35, 0.45, 0.7>] } } }
plane { z, 0 pigment { rgb 0.5 } finish { ambient 0.15 diffuse 1 } }
#declare Terracotta = pigment { rgb <0.555, 0.212, 0.11> }
#declare Names = array[6] { "clay_p00", "clay_p10", "clay_p20", "clay_p30", "clay_p40", "clay_p50" }
#declare I = 0;
#while (I < 6)
  union {
    difference { cone { 0, 0.55, <0, 0, 1.4>, 0.8 } cone { <0, 0, 0.1>, 0.47, <0, 0, 1.45>, 0.72 } }
    torus { 0.78, 0.06 rotate x * 90 translate z * 1.4 }
    translate <(I - 2.5) * 1.9, 0, 0>
    Soak_Wet_User_Material(Names[I], "water", Soak_Preset_Saturation[Soak_Preset_Index(Names[I])], Terracotta)
  }
  #declare I = I + 1;
#end
