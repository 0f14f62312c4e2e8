// Gallery: spilled cognac on an oak table ([JLD99] sec. 4.3, Fig. 7), against the
// light of a low sun through the window behind it (the mullions' shadows cross the
// boards). The table is the user's own pigment, oak boards from POV-Ray's wood
// pattern, wetted by the core's any-colour table (Soak_Wet_User_Texture_Fn): in the
// pool the wood is darkest and carries the liquid's Fresnel film, which mirrors the
// window and the glass; round it, a margin the wood has drawn in is darker without
// the film. The pool's surface is geometry, a height field of the same pool function
// 3 mm above the wood with a rounded edge (the meniscus): a normal such as
// Soak_Spill_Normal cannot be added to a user texture's texture_map. The glass throws
// its caustic towards the viewer (photons). Liquid: cola, the presets' nearest to
// cognac (clear, caramel-coloured; no measured cognac in the core).
#version 3.7;
global_settings {
  assumed_gamma 1.0 ambient_light 1 max_trace_level 12
  photons { spacing 0.0012 autostop 0 jitter 0.4 }
}
#declare Soak_Ambient = 0.1;
#include "soak.inc"
camera { location <0.02, -0.62, 0.27> look_at <0.07, 0.06, 0.0> sky z up z right -x * image_width / image_height angle 52 }
// a low sun behind the table, a faint fill from the room
light_source { <-0.1, 0.9, 0.36> * 3 rgb <1.5, 1.3, 1.05> parallel point_at 0 photons { refraction on reflection on } }
light_source { <1.5, -2, 2> * 10 rgb 0.2 shadowless photons { refraction off reflection off } }
// the room: a dim back wall with a wide low window (its mullions cast the shadows; the
// pool mirrors its panes), the sky behind it
#declare Wall_Y = 2.1;
#declare Win_X0 = -1.2; #declare Win_X1 = 0.8;
#declare Win_Z0 = 0.45; #declare Win_Z1 = 0.98;
union {
  difference {
    box { <-5, Wall_Y, -1>, <5, Wall_Y + 0.1, 3.5> }
    box { <Win_X0, Wall_Y - 0.1, Win_Z0>, <Win_X1, Wall_Y + 0.2, Win_Z1> }
  }
  #for (I, 1, 3) box { <Win_X0 + I * (Win_X1 - Win_X0) / 4 - 0.02, Wall_Y + 0.02, Win_Z0>, <Win_X0 + I * (Win_X1 - Win_X0) / 4 + 0.02, Wall_Y + 0.08, Win_Z1> } #end
  pigment { rgb <0.3, 0.24, 0.19> } finish { ambient 0.15 diffuse 0.3 }
}
plane { z, -0.75 pigment { rgb <0.2, 0.16, 0.13> } finish { ambient 0.2 diffuse 0.4 } }
// the courtyard HDRI the other two columns reflect (hdri_sky.inc), seen through the window
#include "hdri_sky.inc"
Soak_HDRI_Sky("courtyard_x0.15.hdr", 38)
// the table: oak boards 15 cm wide, the user's own pigment: POV-Ray's wood rings around
// an axis along each board, a little below its face and tilted (the arches of flat-sawn oak)
#declare Board_W = 0.15;
#declare Board_K = function(y) { floor((y - 0.04) / Board_W) }
#declare Hash = function(k, s) { sin(k * 12.9898 + s * 78.233) * 43758.5453 - floor(sin(k * 12.9898 + s * 78.233) * 43758.5453) }
#declare Rings = function { pattern { wood turbulence 0.06 octaves 3 lambda 2.2 scale 0.011 } }
#declare Grain = function {
  Rings(y - 0.04 - Board_W * (Board_K(y) + 0.5) + 0.05 * (Hash(Board_K(y), 1) - 0.5),
        -0.02 - 0.06 * Hash(Board_K(y), 2) + 0.12 * (Hash(Board_K(y), 3) - 0.5) * x,
        0.3 * x + 7 * Hash(Board_K(y), 4))
}
#declare Seam = function { select(abs(y - 0.04 - Board_W * (Board_K(y) + 0.5)) - (Board_W / 2 - 0.0012), 0, 1) }
// the dry albedo (linear), a function of x, y only: the pool's raised surface shows the same grain
#declare Oak = pigment { function { select(Seam(x, y, 0) - 0.5, 0.96 * Grain(x, y, 0), 1) }
  color_map { [0 rgb <0.5, 0.34, 0.18>] [0.45 rgb <0.46, 0.3, 0.15>] [0.75 rgb <0.34, 0.205, 0.092>] [0.96 rgb <0.44, 0.285, 0.14>]
              [0.97 rgb <0.1, 0.06, 0.03>] [1 rgb <0.1, 0.06, 0.03>] } }
// the spill: Edge > 0 inside (m), a blob with wandering edges
#declare Blob = function { pattern { bozo turbulence 0.6 octaves 4 scale 0.12 } }
#declare Edge = function { 0.15 - sqrt(pow(x + 0.05, 2) + pow(y + 0.02, 2) * 1.6) + 0.12 * (Blob(x, y, 0) - 0.5) }
// the liquid lying on the wood: 1 inside, across a 4 mm edge
#declare Pool = function { min(max(Edge(x, y, 0) / 0.004 + 0.5, 0), 1) }
// the wetness: the pool (film) and a 2 cm margin the wood has drawn in (pores part filled)
#declare Spill = function { max(Pool(x, y, 0), 0.45 * min(max(Edge(x, y, 0) / 0.02 + 1, 0), 1)) }
// the liquid's surface: 3 mm above the wood over the pool, a rounded edge
#declare Depth = 0.003;
#declare Hf_X0 = -0.42; #declare Hf_Y0 = -0.32;
#declare Hf_W = 0.74; #declare Hf_H = 0.6;
#declare Smooth = function(s) { s * s * (3 - 2 * s) }
union {
  box { <-1.2, -1.2, -0.04>, <1.2, 1.35, 0> }
  height_field { function 740, 600 { Smooth(Pool(Hf_X0 + x * Hf_W, Hf_Y0 + y * Hf_H, 0)) + 0.0004 }
    smooth
    rotate 90 * x scale <Hf_W, Hf_H, Depth> translate <Hf_X0, Hf_Y0, 0> }
  Soak_Wet_User_Texture_Fn("oak", "cola", Spill, Oak)
  Soak_Wet_Interior("cola")
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
  translate <0.04, 0.23, 0>
  photons { target refraction on reflection on collect off }
}
