// Gallery: a carved limestone panel after an hour of wind-driven rain (seed 002
// sec. 3.3.1, Fig. 7). The wet map is `soak bake rain` on the panel's own mesh
// (relief.obj, written with relief.inc by relief_mesh.py): the rain comes from the
// viewer's side and above, so the cornice's top, the string course, the medallions'
// upper faces and the open wall are wet; the strip sheltered under the cornice stays dry.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.18;
#include "soak.inc"
#include "relief.inc"
camera { location <1.0, -2.5, 1.25> look_at <1.0, 0, 0.58> sky z up z right -x * image_width / image_height angle 46 }
light_source { <-1, -0.5, 0.7> * 1e4 rgb 1.1 parallel point_at 0 }
sky_sphere { pigment { gradient z color_map { [0 rgb <0.75, 0.78, 0.8>] [1 rgb <0.45, 0.5, 0.58>] } } }
#declare Wet = Soak_Map_Fn("relief_wet.png")
object { Relief Soak_Wet_Material_UV_Fn("limestone", "water", Wet) }
// the wall around the panel and the paving, wet after the rain
box { <-2, 0.001, -0.2>, <4, 0.4, 1.6> Soak_Wet_Material("limestone", "water", 0.2) }
plane { z, 0 Soak_Wet_Material_Bumped("concrete", "water", function { 0.6 }, normal { granite 0.15 scale 0.08 }) }
