#!/usr/bin/env bash
# Meshes as users bring them (issue 47; issue 51 item 8), each against an
# independent reference:
#  - every format of the reader's table that the project can write (OBJ in
#    UTF-8 and UTF-16, PLY, glTF 2.0 and 1.0 as .gltf and .glb, Collada, X,
#    AC3D, 3DS, MS3D, LWO; FBX and .blend from Blender) holds the same unit
#    square with UVs over u in [0, 0.5]: at 64 x 64 exactly 2048 texel
#    centres lie in it (make_models.py), and every format must bake exactly
#    those; STL (no UVs in the format) and left-out formats are refused
#    with their reason;
#  - UV sets by index and name (FBX's "Half" = 2048 texels, "Full" = 4096);
#  - UVs over u in [0, 1.5]: wrapped, the map is covered (4096) and the
#    texels under u < 0.5 are under both copies (2048 shared); skipped:
#    empty map, a warning, --strict fails and writes nothing; refused;
#  - UDIM: quads in tiles 1001 and 1002, one map per tile, 2048 texels each;
#    with --frames, one sequence per tile;
#  - overlapping UVs: a small square under a larger one on the same UVs;
#    the larger (more surface per texel) wins in either face order, so the
#    exposure is ~1 (open sky) and both orders give identical maps;
#  - partial UVs and the tricky UVs of issue 51 (one point, a line, a
#    degenerate-only mesh, vt nan, negative and tile-2 UVs): a warning with
#    the numbers or a refusal, never a silent empty map;
#  - a map whose covered texels all have exposure 0 (a square facing away
#    from --up, which no rain direction reaches) warns;
#  - the README's format table is the one --help prints.
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/mesh_formats"
rm -rf "$D" && mkdir -p "$D/m" "$D/wide"
HERE="$(cd "$(dirname "$0")" && pwd)"
python3 "$HERE/meshes/make_models.py" "$D/m" || { bad "make_models.py failed"; finish; }
python3 "$HERE/meshes/make_models.py" "$D/wide" --u 1.5
B=(--width 64 --height 64 --rays 1 --duration 0)

covered() { sed -n 's/.*uv: \([0-9]*\) of [0-9]* texels covered.*/\1/p' "$SOAK_TMP/last.out" | head -1; }
shared_pct() { sed -n 's/.*covered ([0-9.]* %), \([0-9.]*\) % of them.*/\1/p' "$SOAK_TMP/last.out" | head -1; }

for f in quad.obj quad_utf16le.obj quad_utf16be.obj quad.ply quad.gltf quad.glb quad_v1.gltf quad_v1.glb quad.dae \
         quad.x quad.ac quad.3ds quad.ms3d quad.lwo; do
  expect_exit 0 "$f bakes" -- "$SOAK" bake rain "$D/m/$f" "${B[@]}" -o "$D/o.exr"
  close "$(covered)" 2048 0 "$f: texels covered (analytic 2048 of 4096)"
done
expect_exit 1 "STL, which holds no UVs, is refused" -- "$SOAK" bake rain "$D/m/quad.stl" "${B[@]}" -o "$D/o.exr"
expect_stderr "quad.stl: mesh has no UVs" "the STL refusal names the file and the reason"
printf 'HIERARCHY\n' >"$D/walk.bvh"
expect_exit 1 "a motion-capture file is refused" -- "$SOAK" bake rain "$D/walk.bvh" "${B[@]}" -o "$D/o.exr"
expect_stderr "walk.bvh: unsupported mesh format: .bvh .*no surface" "the refusal says why (no surface)"
cp "$D/m/quad.obj" "$D/quad.unknownext"
expect_exit 1 "an unknown extension is refused" -- "$SOAK" bake rain "$D/quad.unknownext" "${B[@]}" -o "$D/o.exr"
expect_stderr "not one of the mesh formats Soak reads" "the refusal points at the list"

# FBX and .blend from Blender, two UV sets.
if command -v blender >/dev/null; then
  blender -b --factory-startup --python-exit-code 1 --python "$HERE/meshes/make_blender_models.py" -- "$D/m" \
    >"$D/blender.log" 2>&1 || bad "Blender could not write the FBX/.blend models: $(tail -3 "$D/blender.log")"
  for s in 0:2048 Half:2048 1:4096 Full:4096; do
    expect_exit 0 "quad.fbx --uv-set ${s%%:*}" -- "$SOAK" bake rain "$D/m/quad.fbx" --uv-set "${s%%:*}" "${B[@]}" -o "$D/o.exr"
    close "$(covered)" "${s##*:}" 0 "quad.fbx UV set ${s%%:*}: texels covered (analytic ${s##*:})"
  done
  expect_exit 1 "a UV set the file lacks is refused" -- "$SOAK" bake rain "$D/m/quad.fbx" --uv-set 2 "${B[@]}" -o "$D/o.exr"
  expect_stderr "no UV set 2 \(it has sets 0, 1: 'Half', 'Full'\)" "the refusal lists the sets the file has"
  expect_exit 1 "a .blend of Blender 3.1+ is refused" -- "$SOAK" bake rain "$D/m/quad.blend" "${B[@]}" -o "$D/o.exr"
  expect_stderr "quad.blend: .*reads .blend files of Blender 2.5 to 3.0" "the .blend refusal says which versions Assimp reads"
else
  skip "blender not on PATH" "FBX and .blend models"
fi

# UVs outside [0, 1]: u over [0, 1.5].
expect_exit 0 "u in [0, 1.5] wraps by default" -- "$SOAK" bake rain "$D/wide/quad.obj" "${B[@]}" -o "$D/o.exr"
close "$(covered)" 4096 0 "wrapped: texels covered (analytic 4096)"
close "$(shared_pct)" 50.0 0.05 "wrapped: share under both copies (analytic 2048 of 4096 = 50 %)"
rm -f "$D/skip.exr"
expect_exit 0 "--uv-outside skip bakes" -- "$SOAK" bake rain "$D/wide/quad.obj" --uv-outside skip "${B[@]}" -o "$D/skip.exr"
expect_stderr "warning: .*the map is empty.*0 of 4096 texels covered.*2 outside" "skipping every face warns with the numbers"
expect_exit 1 "--strict fails on the empty map" -- "$SOAK" bake rain "$D/wide/quad.obj" --uv-outside skip --strict "${B[@]}" -o "$D/strict.exr"
[ ! -e "$D/strict.exr" ] && ok "--strict wrote nothing" || bad "--strict wrote $D/strict.exr"
expect_exit 1 "--uv-outside refuse" -- "$SOAK" bake rain "$D/wide/quad.obj" --uv-outside refuse "${B[@]}" -o "$D/o.exr"
expect_stderr "2 of 2 faces have UVs outside \[0, 1\]\^2" "the refusal counts the faces"

# UDIM: one quad in tile 1001 (u 0..0.5), one in 1002 (u 1.25..1.75).
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nv 3 1 0\nv 2 1 0\nvt 0 0\nvt 0.5 0\nvt 0.5 1\nvt 0 1\nvt 1.25 0\nvt 1.75 0\nvt 1.75 1\nvt 1.25 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\nf 5/5 6/6 7/7\nf 5/5 7/7 8/8\n' >"$D/udim.obj"
expect_exit 0 "a UDIM bake" -- "$SOAK" bake rain "$D/udim.obj" "${B[@]}" -o "$D/wet.<UDIM>.exr" --exposure "$D/exp.<UDIM>.exr"
[ -f "$D/wet.1001.exr" ] && [ -f "$D/wet.1002.exr" ] && [ -f "$D/exp.1002.exr" ] && [ ! -e "$D/wet.1003.exr" ] &&
  ok "UDIM: wet.1001, wet.1002 and exp.1002 written, no other tile" || bad "UDIM files: $(ls "$D" | tr '\n' ' ')"
close "$(covered)" 4096 0 "UDIM: texels covered in both tiles (analytic 2 x 2048)"
expect_exit 2 "UDIM needs <UDIM> in every output" -- "$SOAK" bake rain "$D/udim.obj" "${B[@]}" -o "$D/wet.<UDIM>.exr" --exposure "$D/e.exr"
# UDIM with --frames: tile 1001 of the two flat quads is, frame by frame, the
# sequence of its quad baked alone (a second bake: nothing shades or feeds
# one quad from the other on a flat ground), bit for bit.
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 0.5 0\nvt 0.5 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' >"$D/one.obj"
F=(--up z --width 32 --height 32 --rays 4 --duration 60 --fps 0.1 --frames 1-3)
expect_exit 0 "a UDIM frame sequence" -- "$SOAK" bake rain "$D/udim.obj" "${F[@]}" -o "$D/uw.<UDIM>.%04d.exr" \
  --water "$D/uh.<UDIM>.%04d.exr" --exposure "$D/ue.<UDIM>.exr"
expect_exit 0 "the first tile's quad alone" -- "$SOAK" bake rain "$D/one.obj" "${F[@]}" -o "$D/ow.%04d.exr" \
  --water "$D/oh.%04d.exr" --exposure "$D/oe.exr"
same=0
for f in 1 2 3; do
  cmp -s "$D/uw.1001.000$f.exr" "$D/ow.000$f.exr" && cmp -s "$D/uh.1001.000$f.exr" "$D/oh.000$f.exr" && same=$((same + 1))
done
cmp -s "$D/ue.1001.exr" "$D/oe.exr" && same=$((same + 1))
[ $same = 4 ] && [ -f "$D/uw.1002.0003.exr" ] && [ -f "$D/uh.1002.0001.exr" ] \
  && ok "UDIM frames: tile 1001's 3 frames and exposure equal the quad's own bake; tile 1002's frames written" \
  || bad "UDIM frames: $same of 4 equal; files: $(ls "$D" | grep '^u' | tr '\n' ' ')"
expect_exit 2 "UDIM frames need <UDIM> in --water too" -- "$SOAK" bake rain "$D/udim.obj" "${F[@]}" \
  -o "$D/uw.<UDIM>.%04d.exr" --water "$D/uh.%04d.exr"

# Overlapping UVs: a unit square at z = 0 under a 2 x 2 square at z = 1, both on UVs [0, 1]^2.
small='v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n' big='v -0.5 -0.5 1\nv 1.5 -0.5 1\nv 1.5 1.5 1\nv -0.5 1.5 1\n'
uv='vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n'
printf "$small$big$uv"'f 1/1 2/2 3/3\nf 1/1 3/3 4/4\nf 5/1 6/2 7/3\nf 5/1 7/3 8/4\n' >"$D/over_a.obj"
printf "$small$big$uv"'f 5/1 6/2 7/3\nf 5/1 7/3 8/4\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' >"$D/over_b.obj"
O=(--up z --width 32 --height 32 --rays 16 --duration 0 --gutter 0)
expect_exit 0 "overlap, small square first" -- "$SOAK" bake rain "$D/over_a.obj" "${O[@]}" -o "$D/wa.exr" --exposure "$D/ea.exr"
close "$(shared_pct)" 100.0 0 "overlap: every covered texel is under both squares"
expect_exit 0 "overlap, large square first" -- "$SOAK" bake rain "$D/over_b.obj" "${O[@]}" -o "$D/wb.exr" --exposure "$D/eb.exr"
if command -v oiiotool >/dev/null; then
  mean=$(oiiotool --stats "$D/ea.exr" 2>&1 | awk '/Stats Avg/ { print $3; exit }')
  close "$mean" 1 0.1 "overlap: the larger square (open sky, exposure 1) wins, not the covered one (0)"
  oiiotool "$D/ea.exr" "$D/eb.exr" --diff >/dev/null 2>&1 && ok "overlap: the same map in either face order" ||
    bad "overlap: face order changes the map"
else
  skip "oiiotool not on PATH" "overlap maps"
fi

# Partial UVs: two objects, one with UVs.
printf 'o a\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\no b\nv 2 0 0\nv 3 0 0\nv 3 1 0\nf 5 6 7\n' >"$D/partial.obj"
expect_exit 0 "partial UVs bake the faces that have them" -- "$SOAK" bake rain "$D/partial.obj" "${B[@]}" -o "$D/o.exr"
expect_stderr "warning: .*partial UVs: 1 of 3 faces have none" "partial UVs are stated as partial"
close "$(covered)" 4096 0 "partial: the faces with UVs cover the map (analytic 4096)"
expect_exit 1 "--strict fails on partial UVs" -- "$SOAK" bake rain "$D/partial.obj" --strict "${B[@]}" -o "$D/o.exr"

# Tricky UVs (issue 51 item 8).
quad_with() { printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n%bf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' "$1" >"$2"; }
quad_with 'vt 0.3 0.3\nvt 0.3 0.3\nvt 0.3 0.3\nvt 0.3 0.3\n' "$D/point.obj"
quad_with 'vt 0 0\nvt 0.5 0.5\nvt 1 1\nvt 0.25 0.25\n' "$D/line.obj"
quad_with 'vt 1 0\nvt 1.5 0\nvt 1.5 1\nvt 1 1\n' "$D/tile2.obj"
quad_with 'vt -1 -1\nvt -0.5 -1\nvt -0.5 0\nvt -1 0\n' "$D/negative.obj"
quad_with 'vt nan 0\nvt 0.5 0\nvt 0.5 1\nvt 0 1\n' "$D/nan.obj"
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n' >"$D/flat3d.obj"
for m in point line flat3d; do
  expect_exit 0 "$m UVs: exit 0" -- "$SOAK" bake rain "$D/$m.obj" "${B[@]}" -o "$D/o.exr"
  expect_stderr "warning: .*the map is empty.*0 of 4096 texels covered.*degenerate" "$m UVs: the empty map is a warning with the numbers"
done
expect_exit 1 "one-point UVs with --strict" -- "$SOAK" bake rain "$D/point.obj" --strict "${B[@]}" -o "$D/o.exr"
for m in tile2 negative; do
  expect_exit 0 "$m UVs bake" -- "$SOAK" bake rain "$D/$m.obj" "${B[@]}" -o "$D/o.exr"
  close "$(covered)" 2048 0 "$m UVs wrapped into the map (analytic 2048)"
done
expect_exit 1 "vt nan is refused" -- "$SOAK" bake rain "$D/nan.obj" "${B[@]}" -o "$D/o.exr"
expect_stderr "nan.obj: .*line 5: .nan. is not a finite number" "vt nan: the refusal names the file, the line and the reason"
expect_exit 0 "bake drops on a one-point-UV mesh" -- "$SOAK" bake drops "$D/point.obj" --width 16 --height 16 --rays 1 --duration 1 --frames 0-0 --fps 1 -o "$D/d%d.exr"
expect_stderr "warning: .*the map is empty" "bake drops warns about the empty map too"

# Covered but dry: the square faces +z; with --up -z it faces down, so no
# rain direction reaches it (n.u < 0 over the whole cone): exposure 0.
expect_exit 0 "a square facing away from --up bakes" -- "$SOAK" bake rain "$D/m/quad.obj" --up -z "${B[@]}" -o "$D/o.exr"
expect_stderr "warning: .*no covered texel sees the sky \(exposure 0 on all 2048\)" "a dry map of covered texels warns"
expect_exit 1 "--strict fails on it" -- "$SOAK" bake rain "$D/m/quad.obj" --up -z --strict "${B[@]}" -o "$D/o.exr"

# One table: the README's rows are --help's.
"$SOAK" bake rain --help | python3 "$HERE/meshes/formats_table.py" --check "$SOAK_ROOT/README.md" >"$D/table.log" 2>&1 &&
  ok "README's mesh format table matches soak bake rain --help" || bad "README's format table: $(head -5 "$D/table.log")"
finish
