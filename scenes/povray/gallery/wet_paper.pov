// Gallery: a sheet of paper with a wet blot ([JLD99] sec. 4.1, Fig. 5), lying on an
// oak desk over a pencil and lit from the front (the blot is darker), or (Declare=Back=1) held up
// against a bright window (its pane and glazing bars seen beside the sheet), lit from behind (the blot is brighter: water lets more
// light through the fibres).
#version 3.7;
#ifndef(Back) #declare Back = 0; #end
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = (Back ? 0.02 : 0.12);
#include "soak.inc"
#declare Blot = function { min(max((0.22 - sqrt(pow(x - 0.55, 2) + pow(y - 0.5, 2) * 1.3)) / 0.03 + 0.5, 0), 1) }
#if (Back)
  camera { location <0.5, -1.55, 0.72> look_at <0.5, 0, 0.62> sky z up z right -x * image_width / image_height angle 45 }
  light_source { <0.2, 1, 0.15> * 1e4 rgb <1, 0.85, 0.68> * 3 parallel point_at 0 }  // a warm window; the 0.1 mm sheet passes 20-35 %
  background { rgb 0.015 }
  box { <0, 0, 0>, <1, 0.001, 1.3> Soak_Wet_Material_Fn("paper", "water", function { Blot(x, z - 0.15, 0) }) no_shadow }
  // the window the light comes through, seen beside the sheet: a bright pane (it lights
  // nothing itself; the parallel light is its sun) behind dark glazing bars
  box { <-2, 1.5, -1>, <3, 1.51, 2.5> pigment { rgb <1, 0.93, 0.82> } finish { ambient 0 diffuse 0 emission 1 } no_shadow }
  #for (X, 0, 1) box { <-0.62 + 2.18 * X, 1.45, -1>, <-0.56 + 2.18 * X, 1.49, 2.5> pigment { rgb 0.05 } no_shadow } #end
  box { <-2, 1.45, 0.86>, <3, 1.49, 0.92> pigment { rgb 0.05 } no_shadow }
#else
  camera { location <0.5, -0.75, 1.1> look_at <0.5, 0.62, 0> sky z up z right -x * image_width / image_height angle 48 }
  light_source { <-0.6, -0.4, 1> * 1e4 rgb 1 parallel point_at 0 }
  sky_sphere { pigment { rgb 0.9 } }
  // the sheet lies on a yellow pencil (JLD99's test of translucency) that crosses the blot and sticks out on the left
  box { <0, 0, 0.034>, <1, 1.3, 0.035> Soak_Wet_Material_Fn("paper", "water", function { Blot(x, y - 0.15, 0) }) }
  box { <-0.22, 0.633, 0>, <0.9, 0.667, 0.034> pigment { rgb <0.72, 0.5, 0.06> } finish { ambient Soak_Ambient diffuse 1 } }
  box { <-2, -2, -0.05>, <3, 3, 0> Soak_Wet_Material("oak", "water", 0) }
#end
