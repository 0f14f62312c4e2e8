// Placing a wet map (Soak_Map_Fn, Soak_Map_Placed_Fn), three concrete tiles of
// 2 x 2 units seen from above under a low sun, one 16-bit wet map (place_wet.png
// in the current folder, baked by povray/render_scenes.sh with `soak bake
// turbulence`), left to right:
//   1 Soak_Map_Fn: the map over its unit square x, y in [0, 1] (the tile's
//     lower-left quarter), dry outside it;
//   2 Soak_Map_Placed_Fn with transform { translate -0.5 scale 1.5 rotate 30*z
//     translate 1 }: centred on the tile, 1.5 units wide, turned by 30 degrees,
//     dry outside;
//   3 Soak_Map_Placed_Fn(..., transform { scale 0.5 }, 0, 1): tiled every 0.5 units.
// A fourth object, a ball, takes the map by its own UV coordinates
// (Soak_Wet_Material_UV_Fn): POV-Ray's sphere UV wraps u around z.
// povray +Imap_placement.pov +Lpovray (run where place_wet.png lies)
#version 3.7;
#declare Soak_Ambient = 0.2;
#include "soak.inc"
global_settings { assumed_gamma 1.0 ambient_light 1 max_trace_level 8 }
camera { location <3.4, -4.0, 7.5> look_at <3.4, 1.5, 0> sky z up z right -x * 2.4 angle 58 }
light_source { <-0.6, -0.3, 0.6> * 1e6 rgb 1.6 parallel point_at 0 }
sky_sphere { pigment { gradient z color_map { [0 rgb 0.35] [1 rgb <0.12, 0.18, 0.35>] } } }
#declare Map = Soak_Map_Fn("place_wet.png")
#declare Placed = Soak_Map_Placed_Fn("place_wet.png", transform { translate <-0.5, -0.5, 0> scale 1.5 rotate 30*z translate <1, 1, 0> }, 0, 0)
#declare Tiled = Soak_Map_Placed_Fn("place_wet.png", transform { scale 0.5 }, 0, 1)
#macro Tile(Wet, Col)
  box { <0, 0, -0.2>, <2, 2, 0> Soak_Wet_Material_Fn("concrete", "water", Wet) translate <Col * 2.4, 0, 0> }
#end
Tile(Map, 0)
Tile(Placed, 1)
Tile(Tiled, 2)
// the map's unit square on tile 1, outlined
#declare Edge = 0.015;
union {
  cylinder { <0, 0, 0>, <1, 0, 0>, Edge } cylinder { <1, 0, 0>, <1, 1, 0>, Edge }
  cylinder { <1, 1, 0>, <0, 1, 0>, Edge } cylinder { <0, 1, 0>, <0, 0, 0>, Edge }
  pigment { rgb <0.9, 0.5, 0.1> } finish { ambient 0.3 diffuse 0.7 } no_shadow
}
sphere { <6.6, 3.2, 0.45>, 0.45 Soak_Wet_Material_UV_Fn("concrete", "water", Map) }
box { <-0.5, -0.5, -0.4>, <7.5, 4.2, -0.2> pigment { rgb 0.3 } finish { ambient 0.2 diffuse 0.8 } }
