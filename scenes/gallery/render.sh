#!/bin/bash
# The soak render column of docs/gallery.md: the seven seed scenes (scenes/gallery/*.json,
# the same descriptions as the POV-Ray and Blender galleries where the tracer can draw
# them) rendered by the reference path tracer into OUT/soak_*.png, 8-bit sRGB with an
# optimised palette (< 400 KB). Meshes and wet maps are made in a temporary folder
# (meshes.py, the POV-Ray gallery's relief mesh, soak bake rain / turbulence / drying).
# Renders run one after another (make soak-gallery); SPP scales every scene's samples
# (default 1 = the scenes' own), LIMIT caps each render's seconds (soak render --time).
# The pictures are denoised (soak render --denoise: fireflies removed, an edge-avoiding
# filter guided by the pixels' variance and the camera's first hits; pictures only, no
# test reads them); SOAK_GALLERY_DENOISE=0 leaves the raw Monte Carlo.
# usage: scenes/gallery/render.sh SOAK OUT [SPP_SCALE] [LIMIT] [SCENE...]
set -eu
SOAK=$(realpath "$1") OUT=$2 SCALE=${3:-1} LIMIT=${4:-900}
shift $(( $# < 4 ? $# : 4 ))
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
SCN=$ROOT/scenes/gallery
PY=/usr/bin/python3
ALL="paper_front paper_back beach_rock cognac_table bricks_drying bas_relief_rain flowerpot_porosity film_copper film_thickness"
SCENES=${*:-$ALL}
command -v oiiotool >/dev/null || { echo "FAIL: oiiotool not found (openimageio-tools)"; exit 1; }
mkdir -p "$OUT"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
$PY "$SCN/meshes.py" "$WORK"
for m in spill paper_blot; do oiiotool "$WORK/$m.pgm" -d uint16 -o "$WORK/$m.png"; done
cp "$SCN"/*.json "$WORK/"

# the scene's samples times SPP_SCALE, and its size divided by GALLERY_DIV (a quick preview: 4)
opts_of() { $PY -c 'import json,sys; r = json.load(open(sys.argv[1]))["render"]; d = int(sys.argv[3])
print("--spp %d --width %d --height %d" % (max(1, round(r["spp"] * float(sys.argv[2]))), r["width"] // d, r["height"] // d))' \
  "$1" "$SCALE" "${GALLERY_DIV:-1}"; }
render() { # scene-name output.png (16-bit sRGB, the camera's exposure applied)
  local json=$WORK/$1.json t0=$(date +%s)
  local dn=--denoise
  [ "${SOAK_GALLERY_DENOISE:-1}" = 1 ] || dn=
  "$SOAK" render "$json" -o "$2" --threads 2 --seed 1 $(opts_of "$json") --time "$LIMIT" $dn >"$WORK/$1.log" 2>&1 \
    || { echo "FAIL: soak render $1.json, see the log:"; tail -5 "$WORK/$1.log"; exit 1; }
  echo "soak render $1: $(( $(date +%s) - t0 )) s, $(grep -m1 'samples per pixel' "$WORK/$1.log")$(grep -m1 -o '[0-9]* fireflies removed' "$WORK/$1.log" | sed 's/^/, denoised, /' || true)"
}
small_png() { # 16-bit sRGB PNG -> OUT/soak_NAME.png, sRGB, palette-optimised when Pillow is there
  local img=$1 name=$2
  oiiotool "$img" -d uint8 -o "$WORK/$name.8.png"
  if $PY -c 'import PIL' 2>/dev/null; then   # 256 colours, fewer if the noise will not fit in 400 KB
    $PY -c 'import io, sys; from PIL import Image
img = Image.open(sys.argv[1]).convert("RGB")
for n in (256, 192, 128):
    buf = io.BytesIO()
    img.quantize(n, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.FLOYDSTEINBERG).save(buf, "PNG", optimize=True)
    if buf.tell() < 390 * 1024:
        break
open(sys.argv[2], "wb").write(buf.getvalue())' "$WORK/$name.8.png" "$OUT/soak_$name.png"
  else
    cp "$WORK/$name.8.png" "$OUT/soak_$name.png"
  fi
}

for s in $SCENES; do
  case $s in
  bricks_drying)   # four frames of a splash drying (the POV-Ray gallery's map), t = 0, 0.2, 0.4, 0.6
    "$SOAK" bake turbulence --width 320 --height 180 --frequency 3 --threshold -0.05 --softness 0.25 --seed 11 \
      --threads 2 -o "$WORK/splash.png" >/dev/null
    "$SOAK" export --target json -o "$WORK/export.json" >/dev/null
    T_FILL=$($PY -c 'import json,sys; print(next(m["t_fill"] for m in json.load(open(sys.argv[1]))["materials"] if m["name"] == "brick"))' "$WORK/export.json")
    frames=()
    for k in 0 2 4 6; do
      "$SOAK" bake drying "$WORK/splash.png" --t-fill "$T_FILL" --time "0.$k" -o "$WORK/brick_wet.png" >/dev/null
      render bricks_drying "$WORK/bricks_$k.png"
      frames+=("$WORK/bricks_$k.png")
    done
    oiiotool "${frames[@]}" --mosaic:pad=8 2x2 -o "$WORK/bricks.png"
    small_png "$WORK/bricks.png" bricks_drying ;;
  bas_relief_rain) # the POV-Ray gallery's relief mesh and rain bake
    $PY "$ROOT/scenes/povray/gallery/relief_mesh.py" "$WORK" 240 >/dev/null
    "$SOAK" bake rain "$WORK/relief.obj" -o "$WORK/relief_wet.png" --up z --rain-dir 0,-0.55,1 --spread 15 --rainfall 6 \
      --duration 600 --drop-size 0.0005 --splat 0.004 --flow-iterations 0 --width 800 --height 400 --rays 32 --threads 2 >/dev/null
    render "$s" "$WORK/$s.png"
      # the baked map (white = wet) pasted into the lower right corner, as in the POV-Ray gallery
    read -r W H < <(oiiotool --info "$WORK/$s.png" | sed -E 's/.*: *([0-9]+) x +([0-9]+),.*/\1 \2/')
    IW=$((W / 4)) IH=$((W / 8))
    oiiotool "$WORK/relief_wet.png" --ch 0,0,0 --resize "${IW}x${IH}" -d uint16 -o "$WORK/inset_map.png"
    oiiotool "$WORK/inset_map.png" --pattern constant:color=0.92,0.92,0.92 "$((IW + 4))x$((IH + 4))" 3 --paste +2+2 \
      -d uint16 -o "$WORK/inset.png"
    oiiotool "$WORK/inset.png" "$WORK/$s.png" --paste "+$((W - IW - 16))+$((H - IH - 16))" -d uint16 -o "$WORK/${s}_inset.png"
    small_png "$WORK/${s}_inset.png" "$s" ;;
  *)
    [ -f "$WORK/$s.json" ] || { echo "FAIL: no scene $s in $SCN"; exit 1; }
    render "$s" "$WORK/$s.png"; small_png "$WORK/$s.png" "$s" ;;
  esac
  [ "${GALLERY_DIV:-1}" = 1 ] || continue
  kb=$(( $(stat -c %s "$OUT/soak_$s.png") / 1024 ))
  [ "$kb" -lt 400 ] || { echo "FAIL: $OUT/soak_$s.png is $kb KB (limit 400)"; exit 1; }
done
echo "rendered $SCENES into $OUT"
