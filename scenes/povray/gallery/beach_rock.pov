// Gallery: the beach rock in four states ([JLD99] sec. 4.2, Fig. 6 a-d, left to
// right): dry; wet at its foot below the last wave's line; pores full; soaked, with a
// film. (a) stands on dry sand, (b)-(d) on sand the waves have soaked (as the soak render
// column, scenes/gallery/beach_rock.json: the same camera, sun and forest HDRI).
// The sun as soak render's (irradiance 3.3 W/m2: a light of 3.3 / pi); the sky's diffuse
// light as Soak_Ambient 0.3: the forest HDRI x0.45 gives 0.47 on a face turned up (its
// cosine-weighted mean radiance over the upper hemisphere) and about half that on a
// vertical face; POV-Ray lights nothing from the sky_sphere itself.
// tests/povray/gallery_claims.py renders it with Declare=Dry_Rocks=1 (every rock dry: the
// same pixels' reference) and Declare=No_Sky=1 (a black sky).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#ifndef(Dry_Rocks) #declare Dry_Rocks = 0; #end
#ifndef(No_Sky) #declare No_Sky = 0; #end
#declare Soak_Ambient = 0.3;
#include "soak.inc"
camera { location <0, -9.5, 2.6> look_at <0, 0, 0.5> sky z up z right -x * image_width / image_height angle 50 }
light_source { <-0.7, -0.35, 0.35> * 1e4 rgb <1.25, 1.1, 0.9> parallel point_at 0 }
#include "hdri_sky.inc"
#if (!No_Sky) Soak_HDRI_Sky("forest_x0.45.hdr", -60) #end    // as scenes/gallery/beach_rock.json
// sand: dry under (a), soaked from x = -2.4 on, behind a wavy water line: pores full and
// a third of the preset's film (wetness 0.6; sand's saturation is 0.395), damp sand the
// last wave left, not the standing water of wetness 1 (a mirror)
#declare Sea = function { 0.6 * min(max((x + 2.4 + 0.25 * sin(y * 1.7) + 0.15 * sin(y * 4.1 + 1)) / 0.35 + 0.5, 0), 1) }
plane { z, 0 Soak_Wet_Material_Bumped("sand", "water", Sea, normal { bumps 0.05 scale 0.2 }) }
#declare Sat = Soak_Preset_Saturation[Soak_Preset_Index("limestone")];
#declare Wave = function { min(max((0.55 - z) / 0.08 + 0.5, 0), 1) }
#declare States = array[4]
#declare States[0] = function { 0 }
#declare States[1] = function { Wave(x, y, z) * (1 - Dry_Rocks) }
#declare States[2] = function { Sat * (1 - Dry_Rocks) }
#declare States[3] = function { 1 - Dry_Rocks }
// (c), water over the whole rock: the preset at its saturation (albedo 0.62x dry; the
// core's film over the dry rock, limestone's albedo_film at pore fill 0, is 0.61x) under a
// clear layer of water: Fresnel reflection at water's index and the sun's glint, on a
// surface smoother than the rock's (the film fills its grain)
#declare Water = Soak_Liquid_Index("water");
#declare Glaze = texture {
  pigment { rgbt 1 }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on }
    #if (Soak_Highlights) specular albedo Soak_Liquid_F0[Water] roughness 0.003 #end }
  normal { granite 0.06 scale 0.5 }
}
#declare I = 0;
#while (I < 4)
  #declare F = function { States[I](x, y, z) }
  sphere { 0, 1 scale <1, 0.9, 0.7> rotate z * (25 * I - 30) translate <(I - 1.5) * 2.4, 0, 0.6>
    #if (I = 2 & !Dry_Rocks)
      #declare Pores_Full = Soak_Wet_Texture("limestone", "water", Sat);
      texture { Pores_Full normal { granite 0.3 scale 0.5 } }
      texture { Glaze }
      Soak_Wet_Interior("water")
    #else
      Soak_Wet_Material_Bumped("limestone", "water", F, normal { granite 0.3 scale 0.5 })
    #end
  }
  #undef F
  #declare I = I + 1;
#end
