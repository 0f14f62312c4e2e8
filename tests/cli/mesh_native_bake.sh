#!/usr/bin/env bash
# The native OBJ/PLY reader (issue 47 item 6) through `soak bake rain`:
# the same wetness map, byte for byte, as with Assimp alone
# (SOAK_MESH_READER=assimp), on the rain benchmark surface as OBJ with
# normals, as OBJ without them (smooth normals made by the reader) and as
# binary PLY, and on the project's own models (tests/cli/meshes/
# make_models.py: quad.obj, quad.ply), with a sequence of frames and the water flowing (the map
# depends on the triangles' order through the overlap rule and on the
# normals through the faces' orientation). Triangle-by-triangle equality
# is test_mesh_native's.
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
finish
