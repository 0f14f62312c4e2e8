// Gallery: spilled cognac on a polished oak table (seed 000 sec. 4.3, Fig. 7): the
// spill darkens the wood and leaves a raised rim where it dries (Soak_Spill_Normal);
// the glass beside it throws its caustic on the table (photons). Liquid: cola, the
// presets' nearest to cognac (clear, caramel-coloured; no measured cognac in the core).
#version 3.7;
global_settings {
  assumed_gamma 1.0 ambient_light 1 max_trace_level 12
  photons { spacing 0.004 autostop 0 jitter 0.4 }
}
#declare Soak_Ambient = 0.1;
#include "soak.inc"
camera { location <0.15, -0.95, 0.55> look_at <0.1, 0.05, 0.04> sky z up z right -x * image_width / image_height angle 42 }
light_source { <-1.2, 1.4, 1.1> * 10 rgb 1.3 photons { refraction on reflection on } }   // window light, behind the glass
light_source { <1.5, -2, 2> * 10 rgb 0.25 shadowless photons { refraction off reflection off } }
sky_sphere { pigment { gradient z color_map { [0 rgb 0.35] [1 rgb <0.5, 0.55, 0.65>] } } }
// the spill: a blob with wandering edges (0 dry, 1 soaked)
#declare Blob = function { pattern { bozo turbulence 0.6 octaves 4 scale 0.12 } }
#declare Spill = function { 0.8 * min(max((0.15 - sqrt(pow(x + 0.05, 2) + pow(y + 0.02, 2) * 1.6) + 0.12 * (Blob(x, y, 0) - 0.5)) / 0.01 + 0.5, 0), 1) }
box { <-1.2, -1, -0.04>, <1.2, 1, 0>
  Soak_Wet_Material_Bumped("oak", "cola", Spill, Soak_Spill_Normal(Spill, 0.12))
}
// the glass, a third full of cognac
#declare Glass = material {
  texture { pigment { rgbf <1, 1, 1, 0.97> } finish { ambient 0 diffuse 0 reflection { 0.02, 1 fresnel on } specular albedo 0.3 roughness 0.002 } }
  interior { ior 1.5 }
}
#declare Cognac = material {
  texture { pigment { rgbf <1, 0.75, 0.4, 0.9> } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } } }
  interior { ior 1.36 fade_distance 0.03 fade_power 1001 fade_color <0.85, 0.45, 0.12> }
}
union {
  difference { cylinder { <0, 0, 0>, <0, 0, 0.16>, 0.05 } cylinder { <0, 0, 0.01>, <0, 0, 0.17>, 0.046 } material { Glass } }
  cylinder { <0, 0, 0.0101>, <0, 0, 0.06>, 0.04599 material { Cognac } }
  translate <0.27, 0.12, 0>
  photons { target refraction on reflection on collect off }
}
