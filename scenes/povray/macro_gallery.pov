// The macros that no other seed scene shows, one tile each, seen from above
// under a sun and a sky (left to right, top row first):
//   1 Soak_Wet_User_Texture_Fn: a user's checker pigment (your own texture)
//     wetted by a round spill: the core's wetness function darkens each
//     colour per channel;
//   2 Soak_Wet_Material_Bumped + Soak_Spill_Normal: red wine spilled on oak,
//     the raised rim a drying spill leaves ([JLD99]'s cognac);
//   3 Soak_Schedule_Fn: sand wetting from the left, frozen at Time = 0.5 (t0
//     grows across the tile, t_fill = Soak_T_Fill("sand")): the wet front;
//   4 Soak_Wet_Colour: the wet colour of a dry colour at parse time, as a
//     flat pigment (dry, half wet, wet stripes);
//   5 Soak_Wet_User_Subsurface_Material: a user's green pigment with the
//     marble preset's translucency (POV-Ray's BSSRDF), wet;
//   6 Soak_Sheet_Object: a thin cotton sheet as participating media standing
//     over the tiles, lit through by the sun behind it.
// Scene unit 1 mm. povray +Imacro_gallery.pov +Lpovray
#version 3.7;
#declare Soak_Mm_Per_Unit = 1;
#declare Soak_Ambient = 0.15;
#declare Soak_Subsurface_Samples = <60, 10>;
#include "soak.inc"
global_settings { assumed_gamma 1.0 ambient_light 1 Soak_Subsurface_Settings() max_trace_level 8 }
camera { location <145, -110, 330> look_at <145, 75, 0> sky z up z right -x * 1.6 angle 50 }
light_source { <-0.4, 0.9, 0.7> * 1e6 rgb 2 parallel point_at 0 }   // the sun, behind left
sky_sphere { pigment { gradient z color_map { [0 rgb 0.35] [1 rgb <0.12, 0.18, 0.35>] } } }
#macro Tile(Mat, Col, Row)   // a 90 x 90 x 10 mm tile at grid position (Col, Row)
  box { <0, 0, -10>, <1, 1, 0> material { Mat } scale <90, 90, 1> translate <Col * 100, Row * 100, 0> }
#end
// the wetness functions live on the unit square of each tile (scaled after the material)
#declare Spill = function { min(max((0.32 - sqrt((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5))) / 0.04 + 0.5, 0), 1) }
// 1: a user's checker texture wetted by the spill
Tile(material { Soak_Wet_User_Texture_Fn("brick", "water", Spill,
       pigment { checker rgb <0.62, 0.36, 0.22> rgb <0.75, 0.72, 0.62> scale 0.25 })
     Soak_Wet_Interior("water") }, 0, 1)
// 2: red wine on oak, the spill's rim as a bump
Tile(Soak_Wet_Material_Bumped("oak", "red_wine", Spill, Soak_Spill_Normal(Spill, 0.8)), 1, 1)
// 3: sand wetting from the left, at half time
#declare T0 = function { x }
Tile(Soak_Wet_Material_Fn("sand", "water", Soak_Schedule_Fn(function { 1 }, T0, Soak_T_Fill("sand"), 0.5)), 2, 1)
// 4: Soak_Wet_Colour of one dry colour at wetness 0, 0.5, 1
#declare Dry = <0.70, 0.55, 0.35>;
#declare K = 0;
#while (K < 3)
  box { <K * 30, 0, -10>, <K * 30 + 30, 90, 0>
        pigment { rgb Soak_Wet_Colour("sand", "water", K / 2, Dry) } finish { diffuse 1 ambient Soak_Ambient } }
  #declare K = K + 1;
#end
// 5: a user's pigment with the marble's subsurface scattering, wet
object { box { <0, 0, -10>, <90, 90, 0> }
         Soak_Wet_User_Subsurface_Material("marble", "water", 1, pigment { rgb <0.45, 0.7, 0.5> })
         translate <100, 0, 0> }
// 6: a thin cotton sheet (media) standing on the last tile, lit through from behind
object { Soak_Sheet_Object("cotton", "water", 1, 0.004) scale <90, 60, 1> rotate x * 90 translate <200, 45, 0> }
box { <200, 0, -10>, <290, 90, 0> Soak_Wet_Material("concrete", "water", 0) }
