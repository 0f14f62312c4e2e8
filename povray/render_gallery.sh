#!/bin/bash
# The POV-Ray gallery of povray/README.md: the seven situations of the physics
# sources (seeds 000-002) as scenes an artist would show, scenes/povray/gallery/,
# rendered at 960x540 (make povray-gallery) into OUT as 8-bit sRGB PNGs (< 400 KB).
# usage: povray/render_gallery.sh SOAK OUT [WIDTH HEIGHT]
# POVRAY_GALLERY_SCENES picks scenes by name (default: all of ALL below);
# POVRAY_GALLERY_EXR=DIR keeps each picture's linear EXR there (for measuring).
set -eu
SOAK=$1 OUT=$2 W=${3:-960} H=${4:-540}
ALL="paper_front paper_back beach_rock cognac_table bricks_drying bas_relief_rain flowerpot_porosity film_copper film_thickness"
SCENES=${POVRAY_GALLERY_SCENES:-$ALL}
for s in $SCENES; do
  case " $ALL " in *" $s "*) ;; *) echo "FAIL: POVRAY_GALLERY_SCENES: unknown scene '$s' (one of: $ALL)"; exit 1 ;; esac
done
want() { case " $SCENES " in *" $1 "*) return 0 ;; esac; return 1; }
ROOT=$(cd "$(dirname "$0")/.." && pwd)
SCN=$ROOT/scenes/povray/gallery
command -v povray >/dev/null || { echo "FAIL: povray not found (installed by the README's set-up)"; exit 1; }
mkdir -p "$OUT"
# Blender's CC0 world HDRIs (Debian's blender-data), as .hdr for POV-Ray 3.7 (it reads no
# EXR), scaled by the scenes' strengths (a sky_sphere's pigment cannot be scaled): made
# once into build/hdri/, never into the repository (scenes/povray/gallery/hdri_sky.inc)
HDRI_SRC=${SOAK_HDRI_DIR:-/usr/share/blender/datafiles/studiolights/world}
HDRI=${SOAK_HDRI_CACHE:-$ROOT/build/hdri}
mkdir -p "$HDRI"
for h in courtyard:0.15 courtyard:0.45 forest:0.5 forest:0.45; do
  n=${h%%:*} s=${h#*:}
  [ -f "$HDRI_SRC/$n.exr" ] || { echo "FAIL: $HDRI_SRC/$n.exr not found (Blender's HDRIs: Debian's blender-data, installed by the README's set-up; or set SOAK_HDRI_DIR)"; exit 1; }
  if [ ! "$HDRI/${n}_x$s.hdr" -nt "$HDRI_SRC/$n.exr" ]; then
    oiiotool "$HDRI_SRC/$n.exr" --clamp:min=0 --mulc "$s" -o "$HDRI/${n}_x$s.tmp.hdr"
    mv "$HDRI/${n}_x$s.tmp.hdr" "$HDRI/${n}_x$s.hdr"
  fi
done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
pov() { # scene output width height [options...]: a linear EXR in WORK, then the sRGB PNG in OUT
  # (run in POV_DIR, default WORK: a soak_materials.inc there comes before povray/'s)
  local scene=$1 out=$2 w=$3 h=$4; shift 4
  local t0=$(date +%s)
  ( cd "${POV_DIR:-$WORK}" && povray "+I$SCN/$scene" "+O$WORK/$out.exr" +FE "+W$w" "+H$h" -D -V +WT2 "+L$ROOT/povray" "+L$WORK" "+L$HDRI" "+L$SCN" \
      Output_Alpha=off +A0.05 +AM2 +R2 "$@" >"$WORK/$out.log" 2>&1 ) \
    || { echo "FAIL: povray $scene (exit $?), see $WORK/$out.log"; tail -5 "$WORK/$out.log"; exit 1; }
  echo "$out: $((`date +%s` - t0)) s"
}
png() {
  oiiotool "$WORK/$1.exr" --colorconvert linear sRGB -d uint8 -o "$OUT/gallery_$1.tmp.png"
  mv "$OUT/gallery_$1.tmp.png" "$OUT/gallery_$1.png"
  [ -z "${POVRAY_GALLERY_EXR:-}" ] || { mkdir -p "$POVRAY_GALLERY_EXR" && cp "$WORK/$1.exr" "$POVRAY_GALLERY_EXR/"; }
}
# 1 wet paper, front- and back-lit
if want paper_front; then pov wet_paper.pov paper_front "$W" "$H"; png paper_front; fi
if want paper_back; then pov wet_paper.pov paper_back "$W" "$H" Declare=Back=1; png paper_back; fi
# 2 beach rock
if want beach_rock; then pov beach_rock.pov beach_rock "$W" "$H"; png beach_rock; fi
# 3 cognac on oak, with the glass's caustic (photons; one thread: photons differ between threaded runs)
if want cognac_table; then pov cognac_table.pov cognac_table "$W" "$H" +WT1; png cognac_table; fi
# 4 bricks drying: four frames of the animation from a baked start map, at the soak render
# column's times (scenes/gallery/render.sh): 0, 0.2, 0.4, 0.6 of the schedule
if want bricks_drying; then
  "$SOAK" bake turbulence --width 320 --height 180 --frequency 3 --threshold -0.05 --softness 0.25 --seed 11 --threads 2 \
    -o "$WORK/splash.png" >/dev/null
  "$SOAK" export --target json -o "$WORK/export.json" >/dev/null
  T_FILL=$(/usr/bin/python3 -c 'import json,sys; print(next(m["t_fill"] for m in json.load(open(sys.argv[1]))["materials"] if m["name"] == "brick"))' "$WORK/export.json")
  "$SOAK" bake drying "$WORK/splash.png" --start-map --t-fill "$T_FILL" \
    -o "$WORK/brick_start.png" >/dev/null
  frames=()
  for k in 0 2 4 6; do
    pov bricks_drying.pov "bricks_$k" $((W / 2 - 4)) $((H / 2 - 4)) "+K0.$k"   # clock 0, 0.2, 0.4, 0.6
    frames+=("$WORK/bricks_$k.exr")
  done
  oiiotool "${frames[@]}" --mosaic:pad=8 2x2 --resize "${W}x${H}" -o "$WORK/bricks_drying.exr"
  png bricks_drying
fi
# 5 bas-relief after a shower: the rain bake on the panel's mesh (2.6 x 1.3 m, 4.2 mm cells;
# the map 2:1 like the panel, 3.25 mm texels): ten minutes of fine rain (6 mm/h, 0.5 mm
# drops) from the front and steeply above, no runoff (--flow-iterations 0: the stone takes
# the water where it lands); the baked map pasted into the lower right corner (white = wet)
if want bas_relief_rain; then
  /usr/bin/python3 "$SCN/relief_mesh.py" "$WORK" 240
  t0=$(date +%s)
  "$SOAK" bake rain "$WORK/relief.obj" -o "$WORK/relief_wet.png" --up z --rain-dir 0,-0.55,1 --spread 15 --rainfall 6 \
    --duration 600 --drop-size 0.0005 --splat 0.004 --flow-iterations 0 --width 800 --height 400 --rays 32 --threads 2 >/dev/null
  echo "relief rain bake: $((`date +%s` - t0)) s"
  # the left half from a render of the same panel before the shower (Dry=1), the right
  # half after it, split at the middle rosette by a 2-pixel light line
  pov bas_relief_rain.pov bas_relief_wet "$W" "$H"
  pov bas_relief_rain.pov bas_relief_dry "$W" "$H" Declare=Dry=1
  oiiotool --pattern constant:color=0.92,0.92,0.92 "2x$H" 3 "$WORK/bas_relief_dry.exr" --cut "$((W / 2))x$H+0+0" \
    "$WORK/bas_relief_wet.exr" --paste +0+0 --paste "+$((W / 2 - 1))+0" -o "$WORK/bas_relief_rain.exr"
  png bas_relief_rain
  [ -z "${POVRAY_GALLERY_EXR:-}" ] || cp "$WORK/bas_relief_wet.exr" "$WORK/bas_relief_dry.exr" "$POVRAY_GALLERY_EXR/"
  IW=$((W / 4)) IH=$((W / 8))
  oiiotool "$WORK/relief_wet.png" --ch 0,0,0 --resize "${IW}x${IH}" -d uint8 -o "$WORK/inset_map.png"
  oiiotool "$WORK/inset_map.png" --pattern constant:color=0.92,0.92,0.92 "$((IW + 4))x$((IH + 4))" 3 --paste +2+2 \
    -d uint8 -o "$WORK/inset.png"
  oiiotool "$WORK/inset.png" "$OUT/gallery_bas_relief_rain.png" --paste "+$((W - IW - 16))+$((H - IH - 16))" \
    -d uint8 -o "$WORK/relief_inset.png"
  mv "$WORK/relief_inset.png" "$OUT/gallery_bas_relief_rain.png"
fi
# the presets the sweeps of [Hnat06] Fig. 5 (clay_p00 ... clay_p50: alpha_poro) and [Lag13]
# (concrete_f0 ... copper_f500: film depths) need, added by soak export --variant
# (scenes/gallery/variants.txt), in a soak_materials.inc of their own folder
mkdir -p "$WORK/variants"
mapfile -t VARIANTS < <(grep -v '^#' "$ROOT/scenes/gallery/variants.txt")
"$SOAK" export --target povray "${VARIANTS[@]/#/--variant=}" -o "$WORK/variants/soak_materials.inc" >/dev/null
# 6 flowerpot porosity sweep: clay at alpha_poro 0 ... 0.5, pores full (front) and dry (back)
if want flowerpot_porosity; then POV_DIR=$WORK/variants pov flowerpot_porosity.pov flowerpot_porosity "$W" "$H"; png flowerpot_porosity; fi
# 7 water films of increasing coverage into a puddle, copper under water
if want film_copper; then pov film_copper.pov film_copper "$W" "$H"; png film_copper; fi
# 7b [Lag13]'s film depths at full coverage: dry, 0, 0.5 mm, 50 cm over a ground and over copper
if want film_thickness; then POV_DIR=$WORK/variants pov film_thickness.pov film_thickness "$W" "$H"; png film_thickness; fi
# the soak render column of these scenes is docs/images/gallery/soak_*.png (make soak-gallery,
# scenes/gallery/*.json): one copy of each picture
# a picture over 390 KB (the beach's forest and bumpy rocks: 475 KB) as a dithered palette PNG
/usr/bin/python3 "$ROOT/scripts/png_palette.py" --max-kb 390 "$OUT"/gallery_*.png || [ $? = 77 ]
for f in "$OUT"/gallery_*.png; do
  kb=$(( $(stat -c %s "$f") / 1024 ))
  [ "$kb" -lt 400 ] || { echo "FAIL: $f is $kb KB (limit 400)"; exit 1; }
done
echo "rendered the gallery into $OUT"
