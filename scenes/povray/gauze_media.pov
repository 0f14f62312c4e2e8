// Cotton gauze lit from behind, rendered as POV-Ray participating media
// (soak.inc's two-term Henyey-Greenstein media; a sheet thin enough for
// POV-Ray's single scattering). Left: dry. Middle: wet with water (water in
// the fibres makes the scattering more forward: brighter from behind, [JLD99]
// sec. 4.1). Right: a coffee spill whose wetness is a `soak bake volume` df3
// wetness volume (Use_Map=1, made by povray/render_scenes.sh: gauze_wet.png
// -> gauze_vol.inc + gauze_vol_wetness.df3), else a round procedural spill.
// povray +Igauze_media.pov +Lpovray [Declare=Use_Map=1]
#version 3.7;
#ifndef(Use_Map) #declare Use_Map = 0; #end
global_settings { assumed_gamma 1.0 max_trace_level 8 }
#declare Soak_Mm_Per_Unit = 1; // scene unit: 1 mm
#include "soak.inc"
#declare Gauze_Mm = 0.004; // equivalent thickness of the open weave: scattering optical depth 0.26
// The spilled panel is a denser weave (optical depth 2) so that the coffee's
// absorption shows; POV-Ray's single scattering misses most of its multiple
// scattering: it shows where the coffee is, not its exact brightness.
#declare Dense_Mm = 0.03;
camera { orthographic location <0, 0, 200> look_at <0, 0, 0> sky y right -x * 340 up y * 127.5 }
light_source { <0.35, 0.25, -1> * 1e5 rgb 3 parallel point_at 0 } // low sun behind the gauze
background { rgb 0 }
#macro Panel(Mat, X)
  box { <0, 0, -Gauze_Mm>, <1, 1, 0> hollow material { Mat } scale <100, 100, 1> translate <X - 50, -50, 0> }
#end
Panel(Soak_Sheet_Material("cotton", "water", 0), -110)
Panel(Soak_Sheet_Material("cotton", "water", 1), 0)
#if (Use_Map)
  #include "gauze_vol.inc"
  #declare Spill = Soak_Df3_Fn(gauze_vol_wetness_file, gauze_vol_dims, gauze_vol_wetness_scale)
#else
  #declare Spill = function { min(max((0.3 - sqrt((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5))) / 0.05 + 0.5, 0), 1) }
#end
// The wetness function lives on the unit box: the box is scaled after the material.
box { <0, 0, 0>, <1, 1, 1> hollow Soak_Sheet_Material_Fn("cotton", "coffee", Spill, 0)
      scale <100, 100, Dense_Mm> translate <60, -50, -Dense_Mm> }
