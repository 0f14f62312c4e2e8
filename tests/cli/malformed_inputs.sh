#!/bin/bash
# Malformed input is a clear error naming the file (issue 13, items 5, 8, 9):
# every mesh reproducer under tests/fuzz/reproducers/mesh (first byte: the
# format, rest: the file) through `soak render` and `soak bake rain`, an
# unsupported mesh format, NaN pixels in an environment map, and an image
# whose header asks for more memory than the documented limit. Header checks
# (mesh_check.c) now refuse most of the mesh reproducers before Assimp runs.
set -u
: "${SOAK:?}" "${SOAK_TMP:?}" "${SOAK_ROOT:?}"
source "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/malformed"
rm -rf "$D" && mkdir -p "$D"
R="$SOAK_ROOT/tests/fuzz/reproducers"
export SOAK_MESH_TIMEOUT=2

scene_with() { # scene_with OBJECT_JSON ENV_JSON > file
    printf '{"camera": {"position": [0, -4, 0], "look_at": [0, 0, 0]}, "environment": %s,
 "materials": {"m": {"type": "lambert", "albedo": 0.5}}, "objects": [%s]}\n' "$2" "$1"
}
CONST='{"type": "constant", "radiance": 1}'

# reproducer name -> the specific reason expected on stderr
declare -A WHY=(
    [off_8byte_triangulate_abort]="malformed mesh file: the OFF header claims 3 vertices and 1 faces"
    [off_face_count_abort]="malformed mesh file: the OFF header claims 3 vertices and 2 faces"
    [ply_no_end_header_hang]="malformed mesh file: PLY header without end_header"
    [obj_nan_vertex]="line 3: 'nan' is not a finite number"
    [obj_inf_vertex]="line 3: 'inf' is not a finite number"
    [stl_truncated_facet]="malformed mesh file: ASCII STL without 'endsolid'"
    [stl_binary_short]="malformed mesh file: binary STL header claims 1000 triangles"
    [off_fuzz_segv]="crashed on this file \((signal 11|exit status)"
    [stl_fuzz_segv]="malformed mesh file: ASCII STL without 'endsolid'"
)
exts=(obj ply stl off gltf glb)
for f in "$R"/mesh/*; do
    name=$(basename "$f")
    sel=$(head -c 1 "$f" | od -An -tu1 | tr -d ' ')
    mesh="$D/$name.${exts[$((sel % 6))]}"
    tail -c +2 "$f" >"$mesh"
    scene_with "{\"type\": \"mesh\", \"file\": \"$mesh\", \"material\": \"m\"}" "$CONST" >"$D/$name.json"
    if [ -n "${WHY[$name]:-}" ]; then
        expect_exit 1 "render $name" -- "$SOAK" render "$D/$name.json" --width 8 --height 8 --spp 1 -o "$D/o.exr"
        expect_stderr "$name\.[a-z]+: .*${WHY[$name]}" "render $name: names the file and the reason"
    else
        "$SOAK" render "$D/$name.json" --width 8 --height 8 --spp 1 -o "$D/o.exr" >/dev/null 2>"$D/err"
        rc=$?
        [ $rc -le 1 ] && ok "render $name: handled (exit $rc)" || bad "render $name: exit $rc $(cat "$D/err")"
    fi
done
# The same containment on the baker's path.
tail -c +2 "$R/mesh/off_fuzz_segv" >"$D/abort.off"
expect_exit 1 "bake rain on an OFF that crashes Assimp" -- "$SOAK" bake rain "$D/abort.off" --width 8 --height 8 -o "$D/r.exr"
expect_stderr "abort\.off: .*crashed" "bake rain: names the file"
[ ! -e "$D/r.exr" ] && ok "bake rain: no output" || bad "bake rain wrote an output"
# Formats outside the fuzzed set are refused by name.
cp "$D/obj_inf_vertex.obj" "$D/model.max"
scene_with "{\"type\": \"mesh\", \"file\": \"$D/model.max\", \"material\": \"m\"}" "$CONST" >"$D/max.json"
expect_exit 1 "mesh .max" -- "$SOAK" render "$D/max.json" --width 8 --height 8 --spp 1 -o "$D/o.exr"
expect_stderr "model\.max: unsupported mesh format: .max .*export FBX" "mesh .max: unsupported format named with the reason"
# The OBJ header check parses plain numbers and indices by hand (mesh_check.c):
# what strtod/strtoll refused is still refused, what they read still reads.
tri_obj() { printf 'v %s 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 %s/3\n' "$1" "$2" >"$D/$3.obj"; }
tri_obj 1e999 3 huge_exp
expect_exit 1 "OBJ 1e999" -- "$SOAK" bake rain "$D/huge_exp.obj" --width 8 --height 8 --rays 1 -o "$D/r.exr"
expect_stderr "huge_exp\.obj: .*line 1: '1e999' is not a finite number" "OBJ 1e999: refused as not finite"
tri_obj 0 0 index_zero
expect_exit 1 "OBJ index 0" -- "$SOAK" bake rain "$D/index_zero.obj" --width 8 --height 8 --rays 1 -o "$D/r.exr"
expect_stderr "index_zero\.obj: .*face names vertex '0' of 3" "OBJ index 0: refused"
tri_obj 0 99999999999999999999 index_huge
expect_exit 1 "OBJ index 1e20" -- "$SOAK" bake rain "$D/index_huge.obj" --width 8 --height 8 --rays 1 -o "$D/r.exr"
expect_stderr "index_huge\.obj: .*face names vertex '99999999999999999999' of 3" "OBJ index 1e20: refused"
tri_obj 0 -4 index_minus4
expect_exit 1 "OBJ index -4" -- "$SOAK" bake rain "$D/index_minus4.obj" --width 8 --height 8 --rays 1 -o "$D/r.exr"
expect_stderr "index_minus4\.obj: .*face names vertex '-4' of 3" "OBJ index -4 of 3: refused"
tri_obj -.5 -1 plain_ok
expect_exit 0 "OBJ -.5 and index -1 read" -- "$SOAK" bake rain "$D/plain_ok.obj" --width 8 --height 8 --rays 1 --duration 0 -o "$D/r.exr"

# NaN pixels in an environment map were silently read as 0.
tail -c +2 "$R/image/exr_nan_pixels" >"$D/sky_nan.exr"
SPHERE='{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}'
scene_with "$SPHERE" "{\"type\": \"map\", \"file\": \"$D/sky_nan.exr\"}" >"$D/nan_sky.json"
expect_exit 1 "NaN environment map" -- "$SOAK" render "$D/nan_sky.json" --width 8 --height 8 --spp 1 -o "$D/o.exr"
expect_stderr "sky_nan\.exr: pixel \(0, 0\) channel 0 is NaN" "NaN map: names the file and the pixel"
# A 267-byte PNG whose header claims 16000 x 16000: refused before decoding.
tail -c +2 "$R/image/png_16000x16000_header" >"$D/huge.png"
scene_with "$SPHERE" "{\"type\": \"map\", \"file\": \"$D/huge.png\"}" >"$D/huge_sky.json"
expect_exit 1 "16000^2 environment map" -- "$SOAK" render "$D/huge_sky.json" --width 8 --height 8 --spp 1 -o "$D/o.exr"
expect_stderr "huge\.png: a 16000x16000 image needs 2929 MiB .* the limit is 1024 MiB" "huge map: states the memory and the limit"

# A 16384^2 render took 10.6 GB and ignored --time: refused up front.
scene_with "$SPHERE" "$CONST" >"$D/plain.json"
expect_exit 2 "16384^2 render" -- "$SOAK" render "$D/plain.json" --width 16384 --height 16384 --time 5 -o "$D/o.exr"
expect_stderr "16384x16384 render needs 13312 MiB .* the limit is 4096 MiB" "16384^2 render: states memory and limit"

# Silent acceptance in scenes and options (item 8): each a specific error.
S="$R/scene"
expect_exit 1 "duplicate key" -- "$SOAK" render "$S/duplicate_key.json" -o "$D/o.exr"
expect_stderr 'duplicate_key\.json: duplicate key "camera"' "duplicate key: named"
expect_exit 1 "render.width 31.7" -- "$SOAK" render "$S/fractional_width.json" -o "$D/o.exr"
expect_stderr "render\.width: must be a whole number, got 31\.7" "width 31.7: not truncated"
expect_exit 1 "render.spp 2.9" -- "$SOAK" render "$S/fractional_spp.json" -o "$D/o.exr"
expect_stderr "render\.spp: must be a whole number, got 2\.9" "spp 2.9: not truncated"
expect_exit 1 "100k nested arrays" -- "$SOAK" render "$S/nested_arrays_100k.json" -o "$D/o.exr"
expect_stderr "nested deeper than 1000 levels" "nesting: says so"
expect_exit 1 "NaN in a scene" -- "$SOAK" render "$S/syntax_nan.json" -o "$D/o.exr"
expect_stderr "JSON syntax error \(NaN/Infinity are not JSON numbers\)" "NaN: hint given"
expect_exit 1 "trailing comma" -- "$SOAK" render "$S/syntax_comma.json" -o "$D/o.exr"
expect_stderr "column 25: JSON syntax error$" "trailing comma: no NaN hint"
expect_exit 2 "--dims 1,2" -- "$SOAK" bake volume --dry-sigma-s 1 --dry-sigma-a 1 --dims 1,2 -o "$D/v"
expect_stderr "\-\-dims: expected three sizes NX,NY,NZ, got '1,2'" "--dims 1,2: asks for three sizes"

finish
