// Gallery: a sheet of paper with a wet blot ([JLD99] sec. 4.1, Fig. 5), lying on an
// oak desk and lit from the front (the blot is darker), or (Declare=Back=1) held up
// against a bright window, lit from behind (the blot is brighter: water lets more
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
#else
  camera { location <0.5, -0.75, 1.1> look_at <0.5, 0.62, 0> sky z up z right -x * image_width / image_height angle 48 }
  light_source { <-0.6, -0.4, 1> * 1e4 rgb 1 parallel point_at 0 }
  sky_sphere { pigment { rgb 0.9 } }
  box { <0, 0, 0>, <1, 1.3, 0.001> Soak_Wet_Material_Fn("paper", "water", function { Blot(x, y - 0.15, 0) }) }
  box { <-2, -2, -0.05>, <3, 3, 0> Soak_Wet_Material("oak", "water", 0) }
#end
