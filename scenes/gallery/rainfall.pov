// Rainfall over time (docs/gallery.md; [Hnat06] sec. 3.3 and 4): the gallery's carved
// limestone panel (relief.inc, relief_mesh.py) and the paving at its foot through a
// shower, one frame per run. rainfall.sh bakes, per frame, the panel's wet map
// relief_wet.FFFF.png (drop splats filling the pores + the rain bake's falling film)
// and the paving's ground_wet.FFFF.png (drops + the rain bake's puddle in its dip), and
// the ripple flipbook ripples.NNNN.exr (0.5 m tile, 64 frames over 2.56 s).
// Declare=Frame=F (1..) Declare=Time=T (seconds since the rain began)
// [Declare=WallWet=W: the wall round the panel, the panel's open wall on average]
// [Declare=Close=1: the puddle close up].
#version 3.7;
#ifndef (Frame) #declare Frame = 1; #end
#ifndef (Time) #declare Time = 0; #end
#ifndef (WallWet) #declare WallWet = 0; #end
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.22;
#include "soak.inc"
#include "relief.inc"
#ifndef (Close) #declare Close = 0; #end
#if (Close)   // the puddle close up (the inset of the last frame): its rings are a few pixels wide
  camera { location <1.3, -1.1, 0.25> look_at <1.3, -0.2, 0.02> sky z up z right -x * image_width / image_height angle 40 }
#else
  camera { location <1.3, -3.3, 1.75> look_at <1.3, 0, 0.3> sky z up z right -x * image_width / image_height angle 54 }
#end
light_source { <-1.6, -1, 0.8> * 1e4 rgb <1.2, 1.1, 0.95> parallel point_at 0 }
sky_sphere { pigment { gradient z color_map { [0 rgb <0.62, 0.64, 0.66>] [1 rgb <0.42, 0.45, 0.5>] } } }
#declare Wet = Soak_Map_Fn(Soak_Frame_File("relief_wet.", ".png", Frame))
object { Relief Soak_Wet_Material_UV_Fn("limestone", "water", Wet) }
box { <-2, 0.001, -0.2>, <4.6, 0.4, 1.6> Soak_Wet_Material("limestone", "water", WallWet) }
// the paving: its map spans x in [-0.6, 3.2], y in [-1.6, 0] (rain_ground.py); beyond it
// the open paving's value. Where the map reaches the puddle (w > Level) the rain's rings
// replace the paving's grain; the rest keeps its grain.
#declare Level = 0.98;
#declare G_Map = Soak_Map_Fn(Soak_Frame_File("ground_wet.", ".png", Frame))
#declare G_Open = G_Map(0.1, 0.2, 0);
#declare G_Fn = function { select((x + 0.6) * (3.2 - x), G_Open, select((y + 1.6) * (-y), G_Open, G_Map((x + 0.6) / 3.8, (y + 1.6) / 1.6, 0))) }
// the rings' height (Soak_Ripple_Height_Fn) as a bump with the baked slopes (Soak_Ripple_Normal's
// Amount = 4 A / L), its finite difference a fifth of a texel: POV-Ray's default accuracy (0.02 of
// the 0.5 m tile, 1 cm) is wider than half the rings' 1.7 cm wavelength and smooths them away
#declare Ripple_Fn = Soak_Ripple_Height_Fn("ripples.", ".exr", 64, 2.56, Time)
// Slopes x 10 (Exaggerate): the physical rings (0.3 mm high, slopes up to 0.1) do not show
// under this overcast light at this size
#declare Exaggerate = 10;
#declare Ripples = normal { function { Ripple_Fn(x, y, z) } Exaggerate * 4 * 0.0003 / 0.5 accuracy 0.001 }
#declare Ground_Normal = normal {
  function { min(max((G_Fn(x, y, z) - Level) / 0.01, 0), 1) }
  normal_map { [0 granite 0.15 scale 0.08] [1 Ripples scale 0.5] }
}
plane { z, 0 Soak_Wet_Material_Bumped("concrete", "water", G_Fn, Ground_Normal) }
