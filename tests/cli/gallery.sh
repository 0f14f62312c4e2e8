#!/usr/bin/env bash
# docs/gallery.md: every picture it shows exists and is 960x540 (the rainfall strips:
# under 400 KB), each of the seed
# scenes has its three renderers (soak render, POV-Ray, Blender), the soak column
# stays under 400 KB a picture, and every soak render scene of scenes/gallery/
# loads and traces (8x4 pixels, 1 sample, with the meshes of meshes.py and
# placeholder wet maps) without a NaN path or a geometry error.
. "$(dirname "$0")/lib.bash"

DOC=$SOAK_ROOT/docs/gallery.md
PY=/usr/bin/python3
[ -f "$DOC" ] && ok "docs/gallery.md exists" || bad "docs/gallery.md missing"
# png_size FILE: "W H" from the PNG header (IHDR), without any image library
png_size() { $PY -c 'import struct,sys; d = open(sys.argv[1], "rb").read(24)
print(*struct.unpack(">II", d[16:24]) if d[:8] == b"\x89PNG\r\n\x1a\n" else "not-a-png")' "$1"; }
images=$(grep -oE '\]\([^)]+\.png\)' "$DOC" | sed -E 's/^\]\(//; s/\)$//' | sort -u)
n=0
for img in $images; do
  f=$SOAK_ROOT/docs/$img
  n=$((n + 1))
  if [ ! -f "$f" ]; then bad "$img: referenced by docs/gallery.md, missing"; continue; fi
  size=$(png_size "$f")
  case $img in
  */rainfall_*.png) [ "$size" != not-a-png ] && ok "$img: a PNG (a 3 x 2 strip of frames)" || bad "$img: not a PNG" ;;
  *) [ "$size" = "960 540" ] && ok "$img: 960x540" || bad "$img: $size, want 960 540" ;;
  esac
  bytes=$(stat -c %s "$f")   # every column's pictures (scripts/png_palette.py fits the Blender ones)
  [ "$bytes" -lt 400000 ] && ok "$img: $bytes bytes < 400 KB" || bad "$img: $bytes bytes, over 400 KB"
done
[ "$n" -ge 24 ] && ok "$n pictures referenced (8 rows of 3)" || bad "only $n pictures referenced, want 24"
for s in paper_front paper_back beach_rock cognac_table bricks_drying bas_relief_rain flowerpot_porosity film_copper film_thickness; do
  f=$SOAK_ROOT/docs/images/gallery/soak_$s.png
  grep -q "images/gallery/soak_$s.png" "$DOC" && ok "soak_$s.png in the gallery" || bad "soak_$s.png not referenced"
  [ -f "$f" ] && [ "$(stat -c %s "$f")" -lt 409600 ] && ok "soak_$s.png < 400 KB" || bad "soak_$s.png missing or >= 400 KB"
done
for f in "$SOAK_ROOT"/docs/images/gallery/*.png; do
  grep -q "images/gallery/$(basename "$f")" "$DOC" || bad "$(basename "$f") is in docs/images/gallery but not in docs/gallery.md"
done

# the scenes trace: meshes and maps as scenes/gallery/render.sh makes them (smaller)
if ! command -v oiiotool >/dev/null; then
  skip "oiiotool not on PATH" "gallery scenes"
else
  W=$SOAK_TMP/scenes
  rm -rf "$W"; mkdir -p "$W"
  $PY "$SOAK_ROOT/scenes/gallery/meshes.py" "$W" && oiiotool "$W/spill.pgm" -d uint16 -o "$W/spill.png" \
    && oiiotool "$W/paper_blot.pgm" -d uint16 -o "$W/paper_blot.png"
  $PY "$SOAK_ROOT/scenes/povray/gallery/relief_mesh.py" "$W" 24 >/dev/null
  for m in relief_wet brick_wet; do oiiotool --pattern constant:color=0.5,0.5,0.5 16x8 3 -d uint16 -o "$W/$m.png"; done
  cp "$SOAK_ROOT"/scenes/gallery/*.json "$W/"
  sed -i -E 's/"caustic_photons": [0-9]+/"caustic_photons": 2000/' "$W"/*.json   # the photon pass in seconds
  for scene in "$W"/*.json; do
    name=$(basename "$scene" .json)
    expect_exit 0 "render gallery scene $name" -- "$SOAK" render "$scene" -o "$W/$name.exr" --width 8 --height 4 --spp 1 --threads 2
    line=$(grep -E '^capped paths: ' "$SOAK_TMP/last.out")
    close "$(sed -nE 's/.*NaN paths: ([0-9]+).*/\1/p' <<< "$line")" 0 0 "$name: NaN paths"
    close "$(sed -nE 's/.*geometry errors: ([0-9]+).*/\1/p' <<< "$line")" 0 0 "$name: geometry errors"
  done
fi
finish
