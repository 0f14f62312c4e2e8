#!/usr/bin/env bash
# The mesh reader (issue 21, items 2 and 3):
#  - malformed files: every accepted format (ASCII and binary PLY, STL,
#    OBJ, OFF, glTF, GLB) cut short is either read or refused with exit 1
#    and a message naming the file, never by the reader's time limit (the
#    header checks refuse before Assimp runs); here one cut per format
#    through the CLI, every tenth in tests/fuzz/sweep_malformed.c;
#  - inputs that are not regular files (a folder, a FIFO) are refused before
#    they are opened for reading, with a message saying what they are;
#  - the mesh reader's child dies with its parent: SIGTERM and SIGKILL sent
#    to soak alone mid-import leave no process behind.
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/mesh_containment"
rm -rf "$D" && mkdir -p "$D/sweep"
C="$SOAK_ROOT/tests/fuzz/corpus/mesh"

scene_with() { # scene_with MESH > file
  printf '{"camera": {"position": [0, -4, 0], "look_at": [0, 0, 0]}, "environment": {"type": "constant", "radiance": 1},
 "materials": {"m": {"type": "lambert", "albedo": 0.5}}, "objects": [{"type": "mesh", "file": "%s", "material": "m"}]}\n' "$1"
}

# Source files: the corpus (first byte selects the format), plus binary PLY
# and STL triangles written here.
for pair in obj_quad:obj ply_ascii:ply stl_ascii:stl off_tri:off gltf_tri:gltf glb_tri:glb; do
  tail -c +2 "$C/${pair%%:*}" >"$D/src_${pair%%:*}.${pair##*:}"
done
python3 - "$D" <<'PY'
import struct, sys
d = sys.argv[1]
tri = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
with open(f"{d}/src_ply_binary.ply", "wb") as f:
    f.write(b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            b"property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n")
    for v in tri: f.write(struct.pack("<3f", *v))
    f.write(struct.pack("<B3i", 3, 0, 1, 2))
with open(f"{d}/src_stl_binary.stl", "wb") as f:
    f.write(b"\0" * 80 + struct.pack("<I", 1) + struct.pack("<3f", 0, 0, 1))
    for v in tri: f.write(struct.pack("<3f", *v))
    f.write(b"\0\0")
PY

# The full sweep -- these eight sources cut at every tenth, 80 cases -- runs
# in process through soak_mesh_load, the reader `soak render` uses, in
# tests/fuzz/sweep_malformed.c (ctest fuzz_sweep_malformed, with every other
# format Soak reads); 80 soak processes here cost a minute. Here each source
# cut at half its length goes through `soak render`: exit 1 naming the file,
# never the time limit.
for src in "$D"/src_*; do
  base=$(basename "$src")
  ext=${base##*.}
  size=$(stat -c %s "$src")
  cut=$((size / 2))
  m="$D/sweep/${base%.*}_5.$ext"
  head -c "$cut" "$src" >"$m"
  scene_with "$m" >"$D/sweep/${base%.*}_5.json"
  "$SOAK" render "$D/sweep/${base%.*}_5.json" --width 4 --height 4 --spp 1 -o "$D/o.exr" >/dev/null 2>"$D/err"
  rc=$?
  what="$base cut at 5/10 ($cut bytes) through soak render"
  if [ $rc -eq 1 ] && ! grep -qF "$m" "$D/err"; then
    bad "$what: message does not name the file: $(head -c 300 "$D/err")"
  elif [ $rc -ne 0 ] && [ $rc -ne 1 ]; then
    bad "$what: exit $rc: $(head -c 300 "$D/err")"
  elif grep -q "did not finish within" "$D/err"; then
    bad "$what: reached the time limit instead of a header check"
  else
    ok "$what: exit $rc"
  fi
done

# Not regular files: refused by what they are, at once.
mkdir -p "$D/folder.obj"
scene_with "$D/folder.obj" >"$D/folder.json"
expect_exit 1 "a folder as a mesh" -- "$SOAK" render "$D/folder.json" --width 4 --height 4 --spp 1 -o "$D/o.exr"
expect_stderr "folder\.obj: cannot read this mesh file: it is a folder, not a regular file" "a folder is called a folder"
rm -f "$D/fifo.obj" && mkfifo "$D/fifo.obj"
scene_with "$D/fifo.obj" >"$D/fifo.json"
expect_exit 1 "a FIFO as a mesh (no blocking open)" -- timeout 120 "$SOAK" render "$D/fifo.json" --width 4 --height 4 --spp 1 -o "$D/o.exr"
expect_stderr "fifo\.obj: cannot read this mesh file: it is a FIFO \(pipe\), not a regular file" "a FIFO is refused as not a regular file"

# Orphans: a large valid OBJ keeps the reader busy; soak alone is killed
# while its child runs, and the child must be gone at once.
awk 'BEGIN { n = 700; for (j = 0; j <= n; ++j) for (i = 0; i <= n; ++i) printf "v %d %d %g\nvt %g %g\n", i, j, (i * j) % 7, i / n, j / n;
  for (j = 0; j < n; ++j) for (i = 0; i < n; ++i) { a = j * (n + 1) + i + 1; b = a + 1; c = a + n + 1; e = c + 1;
  printf "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n", a, a, b, b, e, e, a, a, e, e, c, c } }' >"$D/big.obj"
scene_with "$D/big.obj" >"$D/big.json"
for sig in TERM KILL; do
  "$SOAK" render "$D/big.json" --width 4 --height 4 --spp 1 -o "$D/big.exr" >/dev/null 2>&1 &
  pid=$!
  child=
  for _ in $(seq 1 1200); do # wait for the reader (start-up is slow under sanitizers)
    child=$(cat /proc/$pid/task/*/children 2>/dev/null | tr -s ' ' '\n' | grep -m1 .)
    [ -n "$child" ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.05
  done
  if [ -z "$child" ]; then
    skip "the import ended before SIG$sig could be sent" "orphan SIG$sig"
    wait $pid 2>/dev/null
    continue
  fi
  kill -$sig $pid
  wait $pid 2>/dev/null
  gone=0
  for _ in $(seq 1 40); do
    kill -0 "$child" 2>/dev/null || { gone=1; break; }
    [ "$(awk '{ print $3 }' /proc/$child/stat 2>/dev/null)" = Z ] && { gone=1; break; }
    sleep 0.05
  done
  if [ $gone = 1 ]; then ok "SIG$sig to soak mid-import: the mesh reader $child is gone"; else
    bad "SIG$sig to soak mid-import: the mesh reader $child survives"
    kill -KILL "$child" 2>/dev/null
  fi
done
finish
