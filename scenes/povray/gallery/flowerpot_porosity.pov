// Gallery: the flowerpot porosity sweep of [Hnat06] Fig. 5: one terracotta
// colour on the clay class with its open porosity alpha_poro = 0, 0.1 ... 0.5
// (left to right; presets clay_p00 ... clay_p50, which `soak export --variant`
// adds: render through povray/render_gallery.sh, or export them yourself with
// the lines of scenes/gallery/variants.txt into a soak_materials.inc beside
// this scene). Front row: the pores just full (wetness = the saturation, which
// is the porosity; no film yet); back row: dry. The sun from the left and a
// lamp near the camera, whose highlight the pore water shows.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.15;
#include "soak.inc"
camera { location <0, -14.5, 7.5> look_at <0, 1.0, 0.7> sky z up z right -x * image_width / image_height angle 40 }
light_source { <-0.5, -0.35, 1.0> * 1e4 rgb 0.8 parallel point_at 0 }
light_source { <-3, -10, 9> rgb 0.9 }   // the lamp near the camera
#include "hdri_sky.inc"
Soak_HDRI_Sky("courtyard_x0.45.hdr", 18)   // as scenes/gallery/flowerpot_porosity.json
plane { z, 0 pigment { rgb 0.5 } finish { ambient 0.15 diffuse 1 } }
plane { y, 6 pigment { rgb 0.6 } finish { ambient 0.15 diffuse 1 } }
#declare Terracotta = pigment { rgb <0.555, 0.212, 0.11> }
#declare Names = array[6] { "clay_p00", "clay_p10", "clay_p20", "clay_p30", "clay_p40", "clay_p50" }
#declare I = 0;
#while (I < 6)
  #declare P = Soak_Preset_Index(Names[I]);
  #declare Row = 0;
  #while (Row < 2) // 0: front, pores full; 1: back, dry
    union {
      difference { cone { 0, 0.55, <0, 0, 1.4>, 0.8 } cone { <0, 0, 0.1>, 0.47, <0, 0, 1.45>, 0.72 } }
      torus { 0.78, 0.06 rotate x * 90 translate z * 1.4 }
      translate <(I - 2.5) * 1.9, Row * 3.0, 0>
      Soak_Wet_User_Material(Names[I], "water", (1 - Row) * Soak_Preset_Saturation[P], Terracotta)
    }
    #declare Row = Row + 1;
  #end
  #declare I = I + 1;
#end
