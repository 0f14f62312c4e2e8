#!/usr/bin/env bash
# The native OBJ/PLY/STL reader (issue 47 item 6) through `soak bake rain`:
# the same wetness map, byte for byte, as with Assimp alone
# (SOAK_MESH_READER=assimp), on the rain benchmark surface as OBJ with
# normals, as OBJ without them (smooth normals made by the reader) and as
# binary PLY, and on the project's own models (tests/cli/meshes/
# make_models.py: quad.obj, quad.ply), with a sequence of frames and the water flowing (the map
# depends on the triangles' order through the overlap rule and on the
# normals through the faces' orientation). Triangle-by-triangle equality
# is test_mesh_native's. STL (no UVs): the per-vertex CSV (vertex
# numbering, positions and wetness) of the surface as binary STL and of
# quad.stl (ASCII, corners joined), byte for byte, and the refusal of a
# wetness map for want of UVs with the same message.
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/mesh_native_bake"
rm -rf "$D" && mkdir -p "$D"
python3 "$SOAK_ROOT/c_core/bench/rain_mesh.py" "$D/surf.obj" 24
python3 "$SOAK_ROOT/c_core/bench/rain_mesh.py" "$D/surf.ply" 24
# The OBJ without vn lines, faces as v/vt.
grep -v '^vn ' "$D/surf.obj" | sed -E 's#([0-9]+)/([0-9]+)/[0-9]+#\1/\2#g' >"$D/plain.obj"
python3 "$SOAK_ROOT/tests/cli/meshes/make_models.py" "$D/models" >/dev/null
cp "$D/models/quad.obj" "$D/quad.obj" && cp "$D/models/quad.ply" "$D/quad.ply"
for m in surf.obj plain.obj surf.ply quad.obj quad.ply; do
  for r in auto assimp; do
    expect_exit 0 "$m through $r" -- env SOAK_MESH_READER=$r "$SOAK" bake rain "$D/$m" --rays 4 --duration 300 \
      --width 32 --height 32 -o "$D/$m.$r.exr"
  done
  if cmp -s "$D/$m.auto.exr" "$D/$m.assimp.exr"; then ok "$m: native and Assimp bake the same map"
  else bad "$m: the maps differ between the native reader and Assimp"; fi
done
python3 "$SOAK_ROOT/c_core/bench/rain_mesh.py" "$D/surf.stl" 12
cp "$D/models/quad.stl" "$D/quad.stl"
for m in surf.stl quad.stl; do
  for r in auto assimp; do
    expect_exit 0 "$m per vertex through $r" -- env SOAK_MESH_READER=$r "$SOAK" bake rain "$D/$m" --rays 4 \
      --duration 2 --rainfall 1 --width 96 --height 96 --per-vertex "$D/$m.$r.csv"
  done
  if cmp -s "$D/$m.auto.csv" "$D/$m.assimp.csv"; then ok "$m: native and Assimp give the same per-vertex CSV"
  else bad "$m: the per-vertex CSVs differ between the native reader and Assimp"; fi
  for r in auto assimp; do
    expect_exit 1 "$m: a map without UVs refused through $r" -- env SOAK_MESH_READER=$r "$SOAK" bake rain "$D/$m" \
      --rays 4 --width 32 --height 32 -o "$D/$m.$r.exr"
    cp "$SOAK_TMP/last.err" "$D/$m.$r.err"
  done
  if cmp -s "$D/$m.auto.err" "$D/$m.assimp.err" && grep -q "mesh has no UVs" "$D/$m.auto.err"; then
    ok "$m: the same 'mesh has no UVs' refusal both ways"
  else bad "$m: the refusals differ: $(head -c 200 "$D/$m.auto.err") / $(head -c 200 "$D/$m.assimp.err")"; fi
done
finish
