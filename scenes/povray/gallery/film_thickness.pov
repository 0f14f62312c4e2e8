// Gallery: [Lag13]'s film-depth sweep, the scene of scenes/gallery/film_thickness.json:
// left to right dry, then fully covered by water 0, 0.5 mm and 50 cm deep; back
// row a rough dielectric ground (the concrete class with the soak column's colour
// (0.45, 0.3, 0.2)), front row copper (the preset, polished). The depths are the
// presets concrete_f0 ... copper_f500, which `soak export --variant` adds (render
// through povray/render_gallery.sh, or export the lines of
// scenes/gallery/variants.txt into a soak_materials.inc beside this scene).
// A round lamp far behind, which the films and the copper mirror.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.35;
#include "soak.inc"
camera { location <0, -2.3, 1.1> look_at <0, 0.2, 0> sky z up z right -x * image_width / image_height angle 51 }
light_source { <0, 6, 2.2> rgb 60 fade_distance 1 fade_power 2
  looks_like { sphere { 0, 0.4 pigment { rgb 1 } finish { emission 1 diffuse 0 ambient 0 } } } }
sky_sphere { pigment { rgb 0.35 } }
plane { z, -0.001 pigment { rgb 0.05 } finish { ambient 0.35 diffuse 1 } }
#declare Ground = pigment { rgb <0.45, 0.3, 0.2> }
#declare Films = array[4] { "", "_f0", "_f05", "_f500" }
#declare I = 0;
#while (I < 4)
  #declare W = (I > 0);
  box { <-0.98 + 0.5 * I, 0.3, -0.01>, <-0.52 + 0.5 * I, 0.76, 0>
    Soak_Wet_User_Material(concat("concrete", Films[I]), "water", W, Ground) }
  box { <-0.98 + 0.5 * I, -0.25, -0.01>, <-0.52 + 0.5 * I, 0.21, 0>
    Soak_Wet_Material(concat("copper", Films[I]), "water", W) }
  #declare I = I + 1;
#end
