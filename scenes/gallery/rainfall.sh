#!/bin/bash
# The "Rainfall over time" section of docs/gallery.md ([Hnat06] sec. 3.3 and 4, issue 37
# item 5): the bas-relief of the gallery's rain scene through a shower, dry -> spotted by
# drops -> wet with the film running down its walls -> a puddle with rings at its foot,
# rendered by POV-Ray (povray/soak.inc) and by Blender's Cycles (the add-on's Rain wiring)
# from the same bakes, at the times TIMES (seconds since the rain began). Writes
#   OUT/rainfall_povray.png, OUT/rainfall_blender.png   the frames tiled 3 x 2 (< 400 KB)
#   OUT/rainfall.webp                                   both renderers side by side, animated (< 2 MB)
# usage: scenes/gallery/rainfall.sh SOAK OUT [povray|blender|both]   (make rainfall-gallery)
# Environment: RAIN_BLENDER (3.4, 4.3 or 5.2; default 3.4) through tests/blender/run_blender.sh
# with the add-on zip RAIN_ADDON (default build/soak_blender.zip); RAIN_SAMPLES (Cycles, 24);
# RAIN_WORK=DIR keeps the bakes in DIR and reuses them on the next run (delete DIR/baked to re-bake).
#
# Per frame at time t the wet map of each surface is our composition of two bakes:
#   w(t) = max(S * drops(t), rain(t))
# drops(t): `soak bake drops` (pore filling by drop splats, weighted by the sky exposure of
# the rain bake; at most 1: pores full); S: the preset's saturation wetness; rain(t): `soak bake rain
# --duration t` (the water that stays: the falling film on the walls, puddles on the paving).
# rain_at() is the one place that makes rain(t): switch it to `soak bake rain --frames`
# (one run for all frames) when that exists; the physics is the same.
set -eu
SOAK=$(realpath "$1") OUT=$(mkdir -p "$2" && cd "$2" && pwd) WHICH=${3:-both}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
SCN=$ROOT/scenes/gallery
PY=/usr/bin/python3
TIMES=(0 1 4 15 240 1200)                # seconds since the rain began (6 frames)
RATE=12                                  # mm/h, a moderate shower
FW=400 FH=225                            # one frame's size (the strip is 3 x 2 of them)
MW=400 MH=200                            # relief map (2.6 x 1.3 m: 6.5 mm texels)
GW=380 GH=160                            # paving map (3.8 x 1.6 m: 1 cm texels)
command -v oiiotool >/dev/null || { echo "FAIL: oiiotool not found (openimageio-tools)"; exit 1; }
$PY -c 'import PIL' 2>/dev/null || { echo "FAIL: /usr/bin/python3 has no Pillow (python3-pil, installed with python3-matplotlib)"; exit 1; }
if [ -n "${RAIN_WORK:-}" ]; then   # keep the bakes there and reuse them (re-rendering after a scene change)
  WORK=$(mkdir -p "$RAIN_WORK" && cd "$RAIN_WORK" && pwd)
else
  WORK=$(mktemp -d)
  trap 'rm -rf "$WORK"' EXIT
fi
cd "$WORK"
step() { echo "rainfall: $*"; }

# ---- meshes and bakes -------------------------------------------------------------
bake() {
$PY "$ROOT/scenes/povray/gallery/relief_mesh.py" "$WORK" 160 >/dev/null
$PY "$SCN/rain_ground.py" "$WORK" 190
RELIEF=(relief.obj --up z --rain-dir 0,-0.55,1 --spread 15 --rainfall "$RATE" --drop-size 0.001 --splat 0.004
        --saturation 0.00005 --width "$MW" --height "$MH" --rays 16 --threads 2)
GROUND=(ground.obj --up z --rainfall "$RATE" --width "$GW" --height "$GH" --rays 4 --threads 2)
rain_at() { # which t out: rain(t) of `which` (relief|ground) as a 16-bit PNG
  local -n args=${1^^}
  local size=$MW'x'$MH; [ "$1" = relief ] || size=$GW'x'$GH
  if [ "$2" = 0 ]; then   # no rain yet (--duration 0 means the exposure alone)
    oiiotool --pattern constant:color=0 "$size" 1 -d uint16 -o "$3"
  else
    "$SOAK" bake rain "${args[@]}" --duration "$2" -o "$3" >/dev/null
  fi
}
read -r S_STONE S_PAVING < <("$SOAK" export --target json -o export.json >/dev/null 2>&1 && $PY -c 'import json
m = {x["name"]: x for x in json.load(open("export.json"))["materials"]}
print(m["limestone"]["saturation_wetness"], m["concrete"]["saturation_wetness"])')
rm -f walls.txt
step "sky exposure of the relief"
"$SOAK" bake rain "${RELIEF[@]}" --duration 0 --exposure exposure.exr -o exposure_wet.png >/dev/null
for k in "${!TIMES[@]}"; do
  t=${TIMES[$k]} f=$(printf %04d $((k + 1)))
  step "bakes at t = $t s (frame $((k + 1)))"
  "$SOAK" bake drops --exposure exposure.exr --map-size 2.6 --width "$MW" --height "$MH" --rate "$RATE" \
    --duration 100000 --capacity 0.00005 --time "$t" --seed 1 --threads 2 -o drops_relief.png >/dev/null
  "$SOAK" bake drops --map-size 3.8 --no-wrap --width "$GW" --height "$GH" --rate "$RATE" \
    --duration 100000 --capacity 0.00005 --time "$t" --seed 2 --threads 2 -o drops_ground.png >/dev/null
  rain_at relief "$t" rain_relief.png
  rain_at ground "$t" rain_ground.png
  oiiotool drops_relief.png --ch 0 --mulc "$S_STONE" rain_relief.png --ch 0 --max -d uint16 -o "relief_wet.$f.png"
  oiiotool drops_ground.png --ch 0 --mulc "$S_PAVING" rain_ground.png --ch 0 --max -d uint16 -o "ground_wet.$f.png"
  # the wall round the panel (both renderers): the panel's open wall (u 0.02-0.08, v 0.5-0.6) on average
  oiiotool "relief_wet.$f.png" --cut "$((MW / 16))x$((MH / 10))+$((MW / 50))+$((MH * 2 / 5))" \
    -d float --printstats | sed -n 's/.*Stats Avg: *\([0-9.e-]*\).*/\1/p' | head -1 >>walls.txt
done
step "ripple flipbook (64 frames over 2.56 s, 0.5 m tile, and its --far version)"
"$SOAK" bake ripples --rate "$RATE" --width 256 --frames 0-63 --threads 2 -o ripples.%04d.exr \
  --far ripples_far.%04d.exr >/dev/null
}
[ -f "$WORK/baked" ] || { bake; touch "$WORK/baked"; }

# ---- renders ------------------------------------------------------------------------
strip() { # renderer frame-files...: 3 x 2 mosaic, 8-bit sRGB, palette-optimised to < 400 KB
  local r=$1; shift
  oiiotool "$@" --mosaic:pad=6 3x2 -d uint8 -o "strip_$r.png"
  $PY - "strip_$r.png" "$OUT/rainfall_$r.png" <<'PY'
import io, sys
from PIL import Image
img = Image.open(sys.argv[1]).convert("RGB")
for n in (256, 192, 128, 96):
    buf = io.BytesIO()
    img.quantize(n, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.FLOYDSTEINBERG).save(buf, "PNG", optimize=True)
    if buf.tell() < 390 * 1024:
        break
open(sys.argv[2], "wb").write(buf.getvalue())
PY
  echo "rainfall: $OUT/rainfall_$r.png $(( $(stat -c %s "$OUT/rainfall_$r.png") / 1024 )) KB"
}
inset() { # frame close-up: the close-up (half size) into the frame's lower right corner, a white frame round it
  oiiotool "$2" --pattern constant:color=1,1,1 "$((FW / 2 + 4))x$((FH / 2 + 4))" 3 --paste +2+2 -d uint8 -o inset.png
  oiiotool inset.png "$1" --paste "+$((FW / 2 - 6))+$((FH / 2 - 6))" -d uint8 -o "$1"
}
frames_pov=() frames_bl=()
if [ "$WHICH" != blender ]; then
  command -v povray >/dev/null || { echo "FAIL: povray not found (installed by the README's set-up)"; exit 1; }
  for k in "${!TIMES[@]}"; do
    f=$(printf %04d $((k + 1))) t0=$(date +%s)
    wall=$(sed -n "$((k + 1))p" walls.txt)
    povray "+I$SCN/rainfall.pov" "+Opov.$f.exr" +FE "+W$FW" "+H$FH" -D -V +WT2 "+L$ROOT/povray" "+L$WORK" \
      Output_Alpha=off +A0.05 +AM2 +R2 "Declare=Frame=$((k + 1))" "Declare=Time=${TIMES[$k]}" "Declare=WallWet=$wall" >"pov.$f.log" 2>&1 \
      || { echo "FAIL: povray rainfall.pov frame $f"; tail -5 "pov.$f.log"; exit 1; }
    oiiotool "pov.$f.exr" --colorconvert linear sRGB -d uint8 -o "pov.$f.png"
    frames_pov+=("pov.$f.png")
    step "POV-Ray frame $((k + 1)) (t = ${TIMES[$k]} s): $(( $(date +%s) - t0 )) s"
  done
  # the last frame's puddle close up, pasted into its lower right corner
  povray "+I$SCN/rainfall.pov" +Opov.close.exr +FE "+W$((FW / 2))" "+H$((FH / 2))" -D -V +WT2 "+L$ROOT/povray" "+L$WORK" \
    Output_Alpha=off +A0.05 +AM2 +R2 "Declare=Frame=${#TIMES[@]}" "Declare=Time=${TIMES[-1]}" Declare=Close=1 \
    "Declare=WallWet=$wall" >pov.close.log 2>&1 || { echo "FAIL: povray rainfall.pov close-up"; tail -5 pov.close.log; exit 1; }
  oiiotool pov.close.exr --colorconvert linear sRGB -d uint8 -o pov.close.png
  inset "${frames_pov[-1]}" pov.close.png
  strip povray "${frames_pov[@]}"
fi
if [ "$WHICH" != povray ]; then
  ADDON=${RAIN_ADDON:-$ROOT/build/soak_blender.zip}
  [ -f "$ADDON" ] || { echo "FAIL: no add-on zip $ADDON (make addon)"; exit 1; }
  mkdir -p "$WORK/blender_user"
  BLENDER_USER_SCRIPTS=$WORK/blender_user BLENDER_USER_CONFIG=$WORK/blender_user/config \
    BLENDER_USER_EXTENSIONS=$WORK/blender_user/extensions SOAK_BLENDER=${RAIN_BLENDER:-3.4} \
    SOAK_BLENDER43_ROOT=${SOAK_BLENDER43_ROOT:-$ROOT/build/trixie-root} \
    SOAK_BLENDER52_ROOT=${SOAK_BLENDER52_ROOT:-$ROOT/build/sid-root} \
    nice -n 5 bash "$ROOT/tests/blender/run_blender.sh" "$SCN/rainfall_blender.py" --addon "$ADDON" --work "$WORK" \
      --frames "${#TIMES[@]}" --size "${FW}x${FH}" --samples "${RAIN_SAMPLES:-24}" >blender.log 2>&1 \
    || { echo "FAIL: Blender, see the log:"; tail -15 blender.log; exit 1; }
  grep '^rainfall' blender.log || true
  for k in "${!TIMES[@]}"; do frames_bl+=("bl.$(printf %04d $((k + 1))).png"); done
  inset "${frames_bl[-1]}" bl.close.png
  strip blender "${frames_bl[@]}"
fi
# the animation: the frames side by side (POV-Ray left, Blender right), a second each
anim=("${frames_pov[@]}" "${frames_bl[@]}")
$PY - "$OUT/rainfall.webp" "${#TIMES[@]}" "${anim[@]}" <<'PY'
import sys
from PIL import Image
out, n, files = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
cols = [files[i:i + n] for i in range(0, len(files), n)]
frames = []
for k in range(n):
    ims = [Image.open(c[k]).convert("RGB") for c in cols]
    w, h = sum(i.width for i in ims) + 6 * (len(ims) - 1), ims[0].height
    f = Image.new("RGB", (w, h), (255, 255, 255))
    x = 0
    for i in ims:
        f.paste(i, (x, 0))
        x += i.width + 6
    frames.append(f)
frames[0].save(out, save_all=True, append_images=frames[1:], duration=[1000] * (n - 1) + [2500], loop=0,
               quality=70, method=4)
PY
echo "rainfall: $OUT/rainfall.webp $(( $(stat -c %s "$OUT/rainfall.webp") / 1024 )) KB"
for f in "$OUT"/rainfall_*.png; do
  kb=$(( $(stat -c %s "$f") / 1024 )); [ "$kb" -lt 400 ] || { echo "FAIL: $f is $kb KB (limit 400)"; exit 1; }
done
[ "$(stat -c %s "$OUT/rainfall.webp")" -lt 2097152 ] || { echo "FAIL: rainfall.webp is over 2 MB"; exit 1; }
