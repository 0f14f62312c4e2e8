// Gallery: a brick wall drying after a splash ([Hnat06] sec. 3.3, Fig. 6): the start map
// of `soak bake drying --start-map` (1 - t0 on wet texels) read as written by
// Soak_Drying_Map_Fn with the preset's fill time; Clock 0 .. 1 runs the animation (the
// gallery shows four frames). The borders of the wet patches dry first.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.2;
#include "soak.inc"
camera { location <0.8, -1.62, 0.5> look_at <0.8, 0, 0.45> sky z up z right -x * image_width / image_height angle 50 }
light_source { <-0.8, -1, 0.9> * 1e4 rgb 1.1 parallel point_at 0 }
#include "hdri_sky.inc"
Soak_HDRI_Sky("forest_x0.5.hdr", -60)      // as scenes/gallery/bricks_drying.json
#declare D = Soak_Drying_Map_Fn("brick_start.png", Soak_T_Fill("brick"), clock)
#declare W = function { D(x / 1.6, z / 0.9, 0) }   // the map over the wall's face
#declare Rows = 12;
#declare Cols = 7;
#declare J = 0;
#while (J < Rows)
  #declare I = -1;
  #while (I < Cols + 1)
    #declare X0 = I * 0.23 + mod(J, 2) * 0.115;
    #if (X0 < 1.6 & X0 + 0.22 > 0)
      box { <max(X0, 0), -0.004, J * 0.075 + 0.005>, <min(X0 + 0.22, 1.6), 0.1, J * 0.075 + 0.07>
        Soak_Wet_Material_Bumped("brick", "water", W, normal { granite 0.05 scale 0.03 }) }
    #end
    #declare I = I + 1;
  #end
  #declare J = J + 1;
#end
box { <0, 0, 0>, <1.6, 0.1, 0.9> Soak_Wet_Material_Fn("concrete", "water", W) }   // mortar, set back 4 mm
plane { z, 0 Soak_Wet_Material("concrete", "water", 0.1) }
