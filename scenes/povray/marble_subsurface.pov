// Marble with POV-Ray's subsurface scattering (Soak_Wet_Subsurface_Material):
// a dry block (left) and a wet one (right: the water film darkens it; the
// diffusion length is the core's, the same wet and dry), lit from behind: a
// thin marble fin on each block glows with the light that crosses its 3 mm,
// and the fin's shadow on the block's top has a soft edge (light diffuses a
// few mm past it).
// Scene units are mm (Soak_Mm_Per_Unit = 1). Needs +Q9 (POV-Ray's default).
// povray +Imarble_subsurface.pov +Lpovray
#version 3.7;
#declare Soak_Mm_Per_Unit = 1;
#declare Soak_Subsurface_Samples = <100, 20>;
#declare Soak_Ambient = 0.03;
#include "soak.inc"
global_settings { assumed_gamma 1.0 ambient_light 1 Soak_Subsurface_Settings() }
camera { location <0, -140, 80> look_at <0, 12, 16> sky z up z right -x * 4 / 3 angle 42 }
light_source { <-0.35, 0.8, 0.9> * 1e6 rgb 1.2 parallel point_at 0 }   // the sun, behind left
sky_sphere { pigment { gradient z color_map { [0 rgb 0.3] [1 rgb <0.08, 0.12, 0.22>] } } }
// the ground: dark dry asphalt
box { <-3000, -3000, -5>, <3000, 3000, 0> Soak_Wet_Material("asphalt", "water", 0) }
// the blocks: dry (left), wet (right)
#declare Blk = box { <0, 0, 0>, <44, 30, 26> }
object { Blk translate <-50, 0, 0> Soak_Wet_Subsurface_Material("marble", "water", 0) }
object { Blk translate <6, 0, 0> Soak_Wet_Subsurface_Material("marble", "water", 1) }
// thin fins (3 mm) on the blocks' back halves
box { <-46, 22, 26>, <-10, 25, 40> Soak_Wet_Subsurface_Material("marble", "water", 0) }
box { <10, 22, 26>, <46, 25, 40> Soak_Wet_Subsurface_Material("marble", "water", 1) }
