// Wet paper, lit from the front (the wet spot is darker) or from behind
// (Back=1: the wet spot is brighter), [JLD99] sec. 4.1.
// povray +Iwet_paper.pov +Lpovray Declare=Back=1
#version 3.7;
#ifndef(Back) #declare Back = 0; #end
global_settings { assumed_gamma 1.0 }
#include "soak.inc"
camera { orthographic location <0.5, 0.5, 3> look_at <0.5, 0.5, 0> up y right -x sky y }
#if (Back)
  light_source { <0.3, 0.2, -1> * 1e4 rgb 2 parallel point_at 0 }
  background { rgb 0 }
#else
  light_source { <0.3, 0.2, 1> * 1e4 rgb 1 parallel point_at 0 }
  background { rgb 0.1 }
#end
// a round wet spot, 0.3 across, with a soft edge
#declare Spot = function { min(max((0.3 - sqrt((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5))) / 0.05 + 0.5, 0), 1) }
// a thin sheet: one surface, no_shadow so the light from behind reaches its back side
box { <0, 0, -0.001>, <1, 1, 0> Soak_Wet_Material_Fn("paper", "water", Spot) no_shadow }
