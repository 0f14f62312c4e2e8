#!/usr/bin/env bash
# soak bake rain MESH --per-vertex OUT (issue 47 item 3), against
# independent references:
#  (a) an open flat ground of shared vertices (ground.ply, 9 vertices, UVs):
#      every vertex's value equals the UV-map bake of the same mesh sampled
#      at its UV (a second method) and the analytic wetness of the rain that
#      fell, w = 1 - exp(-r t / s) (r t = 10 mm/h x 60 s = 0.1667 mm,
#      s = 0.2 mm: 0.5654); tolerance 0.01 = about 5 sd of the drop count
#      (0.2 mm drops: ~45,000 per texel, sd 0.5 % of the depth, 0.002 in w);
#  (b) the same ground without UVs under a roof (roofed.stl): the vertex
#      under the roof (0, 0, 0: 0.45 m inside its edge at 0.3 m height, past
#      the 10 degree rain cone) is dry (< 0.02), the 8 open ground vertices
#      and the 4 roof vertices have the open value;
#  (c) the STL bakes with --per-vertex and is refused without it, the
#      message pointing at --per-vertex;
#  (d) the PLY reads back: vertex count = the mesh's (9; the STL's 13
#      distinct positions, counted in the file), values in [0, 1], the grey
#      colour the sRGB encoding of the value; the CSV holds the same values;
#      Blender's own PLY import gives a colour attribute whose linear value
#      is the wetness (Blender's sRGB decoding, a second implementation);
#  (e) glTF (.gltf, base64 buffer; .glb): the structure checked by hand
#      against the glTF 2.0 specification (per_vertex_models.py gltf),
#      COLOR_0 = _WETNESS = the CSV's wetness vertex by vertex (a second
#      writer; 5e-6: the CSV's 6 digits), the file re-read by soak's own
#      contained Assimp reader with the STL's vertex and face counts, and
#      Blender's glTF importer (3.4 host; 4.3 and 5.2 roots where made)
#      giving a colour attribute equal to the CSV's wetness;
#  (f) POV-Ray (.inc, a mesh2 with a texture per vertex, povray/soak_mesh.inc):
#      rendered, the pixels next to the dry and the wet vertices equal the
#      core's exported colours within named terms (per_vertex_povray.py);
#      a mesh file name with quotes, '#' directives, newlines and a
#      backslash reaches the .inc only escaped: one #declare (--pov-name),
#      POV-Ray parses it and writes no file;
#  refusals: a map too small for the atlas (the size needed named), -o or
#  --uv-set with --per-vertex, an output that is not .ply/.csv, the mesh as output.
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/per_vertex"
rm -rf "$D" && mkdir -p "$D"
PY="$(cd "$(dirname "$0")" && pwd)/meshes/per_vertex_models.py"
python3 "$PY" make "$D" || { bad "per_vertex_models.py make failed"; finish; }
R=(--width 64 --height 64 --rays 16 --duration 60 --steps 4 --rainfall 10 --evaporation 0 --saturation 0.0002
   --drop-size 0.0002)
W_OPEN=$(awk 'BEGIN { printf "%.4f", 1 - exp(-(10 / 3.6e6 * 60) / 0.0002) }')

# (a) + (d) on the ground with UVs.
expect_exit 0 "ground.ply --per-vertex bakes" -- "$SOAK" bake rain "$D/ground.ply" "${R[@]}" --per-vertex "$D/g.ply"
grep -q "wetness of 9 vertices (8 faces)" "$SOAK_TMP/last.out" && ok "the report counts 9 vertices, 8 faces" \
  || bad "report: $(cat "$SOAK_TMP/last.out")"
if python3 "$PY" read "$D/g.ply" >"$D/g.txt" 2>"$D/g.err"; then
  ok "g.ply reads back (header, colours the sRGB grey of the wetness, faces)"
  [ "$(head -1 "$D/g.txt")" = "9 8" ] && ok "g.ply: the mesh's 9 vertices, 8 faces" \
    || bad "g.ply counts '$(head -1 "$D/g.txt")', want '9 8'"
else
  bad "g.ply does not read back: $(cat "$D/g.err")"
fi
if command -v oiiotool >/dev/null; then
  expect_exit 0 "ground.ply UV-map bake" -- "$SOAK" bake rain "$D/ground.ply" "${R[@]}" -o "$D/g.exr"
  oiiotool --dumpdata "$D/g.exr" >"$D/g.dump"
  python3 "$PY" uvmap "$D/g.dump" "$D/ground.ply" 64 64 >"$D/uv.txt"
  i=0
  while read -r uvw; do
    i=$((i + 1))
    pv=$(sed -n "$((i + 1))p" "$D/g.txt" | awk '{print $4}')
    close "$pv" "$uvw" 0.01 "vertex $i: per-vertex vs the UV map at its UV"
  done <"$D/uv.txt"
  [ "$i" = 9 ] || bad "UV map sampled at $i vertices, want 9"
else
  skip "oiiotool not on PATH" "per-vertex vs the UV-map bake"
fi
while read -r x y z w; do
  close "$w" "$W_OPEN" 0.01 "open ground ($x, $z): analytic 1 - exp(-r t / s)"
done < <(tail -n +2 "$D/g.txt")

# (c) the STL without UVs.
expect_exit 1 "roofed.stl without --per-vertex is refused" -- "$SOAK" bake rain "$D/roofed.stl" "${R[@]}" -o "$D/r.exr"
expect_stderr "roofed.stl: mesh has no UVs.*--per-vertex" "the refusal points at --per-vertex"
expect_exit 0 "roofed.stl --per-vertex bakes" -- "$SOAK" bake rain "$D/roofed.stl" "${R[@]}" --per-vertex "$D/r.ply"

# (b) rain shadow, (d) counts.
if python3 "$PY" read "$D/r.ply" >"$D/r.txt" 2>"$D/r.err"; then
  want=$(python3 "$PY" unique "$D/roofed.stl")
  [ "$(head -1 "$D/r.txt")" = "$want 10" ] && ok "r.ply: $want vertices (the STL's distinct positions), 10 faces" \
    || bad "r.ply counts '$(head -1 "$D/r.txt")', want '$want 10'"
  while read -r x y z w; do
    if [ "$x $y $z" = "0 0 0" ]; then
      awk -v w="$w" 'BEGIN { exit !(w < 0.02) }' && ok "under the roof (0, 0, 0): dry, w = $w" \
        || bad "under the roof (0, 0, 0): w = $w, want < 0.02"
    else
      close "$w" "$W_OPEN" 0.01 "in the open ($x, $y, $z)"
    fi
  done < <(tail -n +2 "$D/r.txt")
else
  bad "r.ply does not read back: $(cat "$D/r.err")"
fi
expect_exit 0 "roofed.stl --per-vertex to CSV" -- "$SOAK" bake rain "$D/roofed.stl" "${R[@]}" --per-vertex "$D/r.csv"
tail -n +2 "$D/r.csv" | cut -d, -f5 >"$D/csv_w.txt"
tail -n +2 "$D/r.txt" | awk '{print $4}' >"$D/ply_w.txt"
[ "$(head -1 "$D/r.csv")" = "index,x,y,z,wetness" ] && [ "$(wc -l <"$D/csv_w.txt")" = "$(wc -l <"$D/ply_w.txt")" ] &&
  paste "$D/csv_w.txt" "$D/ply_w.txt" | awk '$1 != $2 + 0 { exit 1 }' \
  && ok "the CSV holds the PLY's values (same seed)" || bad "CSV and PLY differ"

# Blender's PLY import reads the colours as a colour attribute whose linear
# value (the Color Attribute node's) is the file's wetness (tolerance: half
# an 8-bit sRGB step, 0.005).
if command -v blender >/dev/null; then
  if blender -b --factory-startup --python-exit-code 1 --python "$(dirname "$PY")/per_vertex_blender.py" -- "$D/r.ply" \
    >"$D/blender.log" 2>&1; then
    ok "Blender reads r.ply's colours as the wetness: $(grep -o 'attribute=.*' "$D/blender.log")"
  else
    bad "Blender's PLY import: $(grep -E 'Error|worst' "$D/blender.log" | tail -2)"
  fi
else
  skip "blender not on PATH" "Blender's PLY import of the colours"
fi

# (e) glTF outputs.
nv=$(head -1 "$D/r.txt" | cut -d' ' -f1)
export SOAK_BLENDER43_ROOT="${SOAK_BLENDER43_ROOT:-$SOAK_ROOT/build/trixie-root}"
export SOAK_BLENDER52_ROOT="${SOAK_BLENDER52_ROOT:-$SOAK_ROOT/build/sid-root}"
GB="$(dirname "$PY")/per_vertex_gltf_blender.py"
for ext in gltf glb; do
  expect_exit 0 "roofed.stl --per-vertex to .$ext" -- "$SOAK" bake rain "$D/roofed.stl" "${R[@]}" --per-vertex "$D/r.$ext"
  if python3 "$PY" gltf "$D/r.$ext" >"$D/$ext.txt" 2>"$D/$ext.err"; then
    ok "r.$ext: structure as the glTF 2.0 specification (header, alignment, min/max, COLOR_0 = _WETNESS)"
    [ "$(head -1 "$D/$ext.txt")" = "$nv 10" ] && ok "r.$ext: $nv vertices, 10 faces" \
      || bad "r.$ext counts '$(head -1 "$D/$ext.txt")', want '$nv 10'"
    tail -n +2 "$D/$ext.txt" | awk '{print $4}' | paste - "$D/csv_w.txt" \
      | awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > 5e-6) bad++ } END { exit bad > 0 || NR == 0 }' \
      && ok "r.$ext: COLOR_0 = the CSV's wetness at every vertex" || bad "r.$ext: COLOR_0 differs from the CSV"
  else
    bad "r.$ext: $(cat "$D/$ext.err")"
  fi
  expect_exit 0 "r.$ext re-read by soak's reader" -- "$SOAK" bake rain "$D/r.$ext" --width 32 --height 32 --rays 1 \
    --duration 0 --per-vertex "$D/rr_$ext.csv"
  grep -q "wetness of $nv vertices (10 faces)" "$SOAK_TMP/last.out" \
    && ok "r.$ext re-read (contained Assimp): $nv vertices, 10 faces" || bad "re-read: $(cat "$SOAK_TMP/last.out")"
done
blender_gltf() { # VERSION FILE: Blender's glTF importer on FILE against the CSV
  local v=$1 f=$2 log="$D/blender_$1_$(basename "$2").log"
  SOAK_BLENDER=$v bash "$SOAK_ROOT/tests/blender/run_blender.sh" "$GB" "$f" "$D/r.csv" >"$log" 2>&1
  local rc=$?
  if [ $rc = 0 ]; then ok "Blender $v imports $(basename "$f"): $(grep -o 'attribute=.*' "$log")"
  elif grep -q "No module named 'numpy'" "$log"; then # the set-up installs it: a root made before that is stale
    bad "Blender $v's root has no numpy for its glTF importer: remake it (scripts/setup-blender-root.sh $v)"
  else bad "Blender $v glTF import of $(basename "$f"): $(grep -E 'Error|assert|FAIL' "$log" | tail -2)"; fi
}
if command -v blender >/dev/null; then
  blender_gltf 3.4 "$D/r.gltf" # the .glb in 4.3 and 5.2 below
else
  skip "blender not on PATH" "Blender 3.4 glTF import"
fi
for v in 4.3 5.2; do
  root=$SOAK_BLENDER43_ROOT; [ $v = 5.2 ] && root=$SOAK_BLENDER52_ROOT
  if [ -x "$root/usr/bin/blender" ]; then blender_gltf $v "$D/r.glb"
  else skip "no Blender $v root at $root (scripts/setup-blender-root.sh $v)" "Blender $v glTF import"; fi
done

# (f) POV-Ray mesh2.
expect_exit 0 "roofed.stl --per-vertex to .inc" -- "$SOAK" bake rain "$D/roofed.stl" "${R[@]}" --per-vertex "$D/r.inc"
grep -q '^#declare Soak_Wet_Mesh = mesh2 {$' "$D/r.inc" && ok "r.inc declares Soak_Wet_Mesh, a mesh2" \
  || bad "r.inc: no '#declare Soak_Wet_Mesh = mesh2 {'"
if command -v povray >/dev/null && command -v oiiotool >/dev/null; then
  mkdir -p "$D/pov"
  if python3 "$(dirname "$PY")/per_vertex_povray.py" "$SOAK" "$SOAK_ROOT" "$D/pov" "$D/r.inc" "$D/r.csv" \
    "$D/roofed.stl" >"$D/pov.log" 2>&1; then
    ok "POV-Ray renders r.inc: the dry and wet vertices' pixels are the core's colours ($(grep -c '^ok' "$D/pov.log") checks)"
  else
    bad "POV-Ray render of r.inc: $(grep -E 'FAIL' "$D/pov.log" | head -3)"
  fi
else
  skip "povray or oiiotool not on PATH" "POV-Ray render of the mesh2"
fi
evil="$D/q\";#fopen P \"pwned.txt\" write #declare Z=\"y"$'\n'"#declare Soak_Wet_Mesh = 0"$'\n'"\\.stl"
cp "$D/roofed.stl" "$evil"
expect_exit 0 "a mesh named with quotes, directives, newlines" -- "$SOAK" bake rain "$evil" --width 32 --height 32 \
  --rays 1 --duration 0 --per-vertex "$D/evil.inc" --pov-name My_Mesh
[ "$(grep -c '^#declare' "$D/evil.inc")" = 1 ] && grep -q '^#declare My_Mesh = mesh2 {$' "$D/evil.inc" \
  && ok "evil.inc: one #declare, --pov-name's My_Mesh; the file name only escaped" \
  || bad "evil.inc: $(grep -n '^#' "$D/evil.inc" | head -5)"
if command -v povray >/dev/null; then
  printf '#version 3.7;\n#include "soak.inc"\n#include "soak_mesh.inc"\n#include "evil.inc"\nobject { My_Mesh }\n' \
    >"$D/evil.pov"
  (cd "$D" && povray +Ievil.pov +Oevil.png +W8 +H8 -D -V "+L$SOAK_ROOT/povray" >"$D/evil.log" 2>&1)
  rc=$?
  [ $rc = 0 ] && [ ! -e "$D/pwned.txt" ] && ok "POV-Ray parses evil.inc and writes no file" \
    || bad "evil.inc in POV-Ray: exit $rc, pwned.txt $( [ -e "$D/pwned.txt" ] && echo written || echo absent)"
fi
expect_exit 2 "--pov-name not an identifier" -- "$SOAK" bake rain "$D/roofed.stl" --per-vertex "$D/x.inc" \
  --pov-name 'a"b'
expect_stderr "--pov-name 'a\"b': a POV-Ray identifier" "the refusal says what an identifier is"
expect_exit 2 "--pov-name with a .ply" -- "$SOAK" bake rain "$D/roofed.stl" --per-vertex "$D/x.ply" --pov-name Wet
expect_stderr "--pov-name is for --per-vertex OUT.inc" "the refusal names the .inc output"
expect_exit 2 "--pov-name without --per-vertex" -- "$SOAK" bake rain "$D/ground.ply" -o "$D/x.exr" --pov-name Wet
[ ! -e "$D/x.inc" ] && [ ! -e "$D/x.ply" ] && ok "nothing written by the refusals" || bad "a refused run wrote"

# Refusals.
expect_exit 2 "a map too small for the atlas" -- "$SOAK" bake rain "$D/roofed.stl" --width 16 --height 16 --rays 1 \
  --duration 0 --per-vertex "$D/small.ply"
expect_stderr "10 triangles need a map of at least 24 x 24" "the refusal gives the size needed (ceil(sqrt(5)) x 8)"
[ ! -e "$D/small.ply" ] && ok "nothing written" || bad "small.ply written"
expect_exit 2 "-o with --per-vertex" -- "$SOAK" bake rain "$D/roofed.stl" --per-vertex "$D/x.ply" -o "$D/x.exr"
expect_stderr "-o is not taken with --per-vertex" "the refusal names -o"
expect_exit 2 "--uv-set with --per-vertex" -- "$SOAK" bake rain "$D/ground.ply" --uv-set 1 --per-vertex "$D/x.ply"
expect_stderr "--uv-set and --uv-outside are not taken with --per-vertex" "the refusal says the mesh's UVs are not used"
expect_exit 2 "a .txt output" -- "$SOAK" bake rain "$D/roofed.stl" --per-vertex "$D/x.txt"
expect_stderr "must end in .ply, .csv, .gltf, .glb or .inc" "the refusal names the extensions"
cp "$D/ground.ply" "$D/keep.ply"
expect_exit 2 "the mesh as its own output" -- "$SOAK" bake rain "$D/keep.ply" --rays 1 --duration 0 --per-vertex "$D/keep.ply"
cmp -s "$D/keep.ply" "$D/ground.ply" && ok "the input is untouched" || bad "the input was overwritten"
finish
