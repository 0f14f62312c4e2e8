// Bricks drying (an animation over clock 0..1). A wet map (brick_wet.png, a
// 16-bit PNG from `soak bake`, with Declare=Use_Map=1; default: all wet) holds
// the liquid; each brick dries from its border inwards: t0 grows with the
// distance to the mortar, and the pore schedule runs backwards over the brick
// preset's t_fill.
// povray +Ibricks_drying.pov +Lpovray +KFI1 +KFF8 Declare=Use_Map=1
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.1;
#include "soak.inc"
camera { orthographic location <0.5, 0.5, 3> look_at <0.5, 0.5, 0> up y right -x sky y }
light_source { <0.4, 0.5, 1> * 1e4 rgb 1 parallel point_at 0 }
sky_sphere { pigment { rgb 0.5 } }
#ifndef(Use_Map) #declare Use_Map = 0; #end
#if (Use_Map) #declare Wet = Soak_Map_Fn("brick_wet.png") #else #declare Wet = function { 1 } #end
// brick cells 0.25 x 0.125, every other row offset by half a brick
#declare Bx = function(x, y) { (x + 0.125 * mod(floor(y / 0.125), 2)) / 0.25 }
#declare Edge = function { min(min(Bx(x, y) - floor(Bx(x, y)), 1 - (Bx(x, y) - floor(Bx(x, y)))) * 0.25,
                               min(y / 0.125 - floor(y / 0.125), 1 - (y / 0.125 - floor(y / 0.125))) * 0.125) }
#declare T0 = function { Edge(x, y, z) * 12 }
#declare Dry = Soak_Drying_Fn(Wet, T0, Soak_T_Fill("brick"), clock)
box { <0, 0, -0.1>, <1, 1, 0> Soak_Wet_Material_Fn("brick", "water", Dry) }
// mortar
box { <0, 0, -0.2>, <1, 1, -0.01> pigment { rgb 0.35 } finish { ambient 0.1 diffuse 1 } }
