#!/bin/bash
# Renders the POV-Ray seed scenes (scenes/povray/) into OUT: small (tests:
# 64 px, and checks what each scene must show) or full (make demo: 480 px).
# usage: povray/render_scenes.sh SOAK OUT [small|full]
set -eu
SOAK=$1 OUT=$2 SIZE=${3:-full}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
command -v povray >/dev/null || { echo "FAIL: povray not found (installed by the README's set-up)"; exit 1; }
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
if [ "$SIZE" = small ]; then W=64; Q=(+A0.3 +R1); else W=480; Q=(+A0.05 +R2); fi
H=$((W * 3 / 4))
pov() { # scene output width height [declares...]
  local scene=$1 out=$2 w=$3 h=$4; shift 4
  ( cd "${POV_DIR:-$OUT}" && povray "+I$ROOT/scenes/povray/$scene" "+O$OUT/$out" +FE "+W$w" "+H$h" -D -V +WT2 \
      "+L$ROOT/povray" "+L$OUT" Output_Alpha=off "${Q[@]}" "$@" >"$OUT/$out.log" 2>&1 ) \
    || { echo "FAIL: povray $scene (exit $?), see $OUT/$out.log"; tail -5 "$OUT/$out.log"; exit 1; }
  oiiotool "$OUT/$out" --colorconvert linear sRGB -d uint8 -o "$OUT/${out%.exr}.png"
}
pov wet_paper.pov paper_front.exr "$H" "$H"
pov wet_paper.pov paper_back.exr "$H" "$H" Declare=Back=1
pov beach_rock.pov beach_rock.exr "$W" "$((W * 3 / 8))"
# the porosity sweep: clay at alpha_poro 0 ... 0.5 (soak export --variant, scenes/gallery/variants.txt),
# exported from a file of clay and water alone (seconds, not the whole set) into a folder of its own
mkdir -p "$OUT/variants"
/usr/bin/python3 -c 'import json, sys; d = json.load(open(sys.argv[1]))
d["materials"] = [m for m in d["materials"] if m["name"] == "clay"]; d["liquids"] = [l for l in d["liquids"] if l["name"] == "water"]
json.dump(d, open(sys.argv[2], "w"))' "$ROOT/c_core/data/materials.json" "$OUT/variants/clay.json"
mapfile -t VARIANTS < <(grep '^clay_p' "$ROOT/scenes/gallery/variants.txt")
"$SOAK" export --target povray --materials "$OUT/variants/clay.json" "${VARIANTS[@]/#/--variant=}" \
  -o "$OUT/variants/soak_materials.inc" >/dev/null
FW=$W; [ "$SIZE" = small ] && FW=$((W * 3))   # the test measures each pot's body: 32 px a pot
POV_DIR=$OUT/variants pov flowerpot_porosity.pov flowerpot_porosity.exr "$FW" "$((FW * 3 / 8))"
pov film_copper.pov film_copper.exr "$W" "$H"
pov marble_subsurface.pov marble_subsurface.exr "$W" "$H"  # subsurface: needs +Q9 (the default)
pov macro_gallery.pov macro_gallery.exr "$W" "$H"
# drying bricks: a 16-bit wet map from soak bake, 4 frames of the animation
"$SOAK" bake turbulence --width 256 --height 256 --threshold -0.2 --softness 0.3 --seed 3 --threads 2 \
  -o "$OUT/brick_wet.png" >/dev/null
frames=()
for k in 0 1 2 3; do
  pov bricks_drying.pov "bricks_$k.exr" "$H" "$H" Declare=Use_Map=1 "Clock=0.$((k * 3))"
  frames+=("$OUT/bricks_$k.png")
done
oiiotool "${frames[@]}" --mosaic 4x1 -o "$OUT/bricks_drying.png"
# gauze lit from behind (media): a coffee spill as a df3 wetness volume from soak bake
"$SOAK" bake turbulence --width 256 --height 256 --frequency 3 --threshold 0.05 --softness 0.08 --seed 5 --threads 2 \
  -o "$OUT/gauze_wet.png" >/dev/null
"$SOAK" bake volume --material cotton --liquid coffee --map "$OUT/gauze_wet.png" --unit mm --size 100,100,0.03 \
  --depth 1 --dims 128,128,2 --format df3 --threads 2 -o "$OUT/gauze_vol" >/dev/null
pov gauze_media.pov gauze_media.exr "$W" "$((W * 3 / 8))" Declare=Use_Map=1
# wet-map placement: one 16-bit map from soak bake, placed, turned, tiled, on UVs
"$SOAK" bake turbulence --width 128 --height 128 --threshold -0.1 --softness 0.2 --seed 7 --threads 2 \
  -o "$OUT/place_wet.png" >/dev/null
pov map_placement.pov map_placement.exr "$W" "$((W / 2))"
echo "rendered into $OUT"
