// Gallery: a carved limestone panel after a shower ([Hnat06] sec. 3.3.1, Fig. 7). The
// wet map is `soak bake rain` on the panel's own mesh (relief.obj, written with
// relief.inc by relief_mesh.py; render_gallery.sh bakes it): ten minutes of fine rain
// from the viewer's side and steeply above, no runoff (the stone takes the water where
// it lands), so the faces open to the rain are wet, the tops of the cornice and the
// string course wettest, and the strips sheltered under them stay dry. The camera, the
// sun from the left and the uniform sky (radiance 0.55; 0.3 of it as the diffuse light's
// ambient, a vertical face seeing half the sky) are the soak render column's
// (scenes/gallery/bas_relief_rain.json). Declare=Dry=1 renders the panel, its wall and
// the paving before the shower: render_gallery.sh puts that render's left half beside
// this one's right half and pastes the baked map (white = wet) into the lower right corner.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.3;
#include "soak.inc"
#include "relief.inc"
#ifndef(Dry) #declare Dry = 0; #end
camera { location <1.3, -4.6, 0.95> look_at <1.3, 0, 0.62> sky z up z right -x * image_width / image_height angle 42 }
light_source { <-1.6, -1, 0.8> * 1e4 rgb <3.6, 3.2, 2.7> / pi parallel point_at 0 }
sky_sphere { pigment { rgb 0.55 } }
#declare Wet = #if (Dry) function { 0 } #else Soak_Map_Fn("relief_wet.png") #end
object { Relief Soak_Wet_Material_UV_Fn("limestone", "water", Wet) }
// the wall around the panel: the open wall's wetness in the same bake (u, v = 0.05, 0.55)
#declare Wall_Wet = (Dry ? 0 : Wet(0.05, 0.55, 0));
#debug concat("bas_relief_rain: the open wall's wetness ", str(Wall_Wet, 0, 3), "\n")
box { <-2, 0.001, -0.2>, <4, 0.4, 1.6> Soak_Wet_Material("limestone", "water", Wall_Wet) }
// the paving: open to the same shower (the bake's open horizontal surface: about 0.9 mm
// of water, w = 1 - exp(-0.9 / 0.2) = 0.99)
#declare Pave_Wet = (Dry ? 0 : 0.99);
plane { z, 0 Soak_Wet_Material_Bumped("concrete", "water", function { Pave_Wet }, normal { granite 0.03 scale 0.3 }) }
