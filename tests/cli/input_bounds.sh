#!/usr/bin/env bash
# Every input has a type, size, time and memory bound (issue 35). Each case
# below was a finding of an attack on the release build; each is now a
# clear error from soak naming the file, in well under 1 GB. Large inputs
# are sparse files made here (truncate, a seek past a hole), FIFOs are made
# with mkfifo; memory is the peak resident size of soak and its children
# (/usr/bin/time's %M, from wait4's rusage). A hang fails through
# `timeout` (a bound, not a timing). Before -> after, release build:
#  - scene /dev/zero: grew to 10 GB in 9 s -> refused as a device;
#    a FIFO or /dev/stdin: blocked forever -> refused as a FIFO;
#    2 GiB sparse .json: 2.2 GB -> refused by SOAK_MAX_SCENE_MB;
#    out of memory: "soak render: @q\254|vU" -> a message naming the file;
#  - 1.16 MB PNG declaring 16384^2 with a 900 KB private chunk: 5.6 GB,
#    46.5 s, exit 0 -> refused: the ratio rule counts IDAT bytes only;
#  - 256 MiB of zeros named .png/.tif/.jpg/.exr: 18.5 s, 394 MB in the DICOM
#    reader -> refused by the signature the extension names; a PNG or HDR
#    header followed by 2 GiB of zeros: > 100 s -> refused by the chunk walk
#    / the header's end;
#  - bake drying of an 8192^2 mask (65 KB): 1.5 GB -> refused from the
#    header with the estimate (SOAK_MAX_MEMORY_MB raises the budget);
#  - a 65536x1 map: read by render, refused by bake -> one limit, one message;
#  - a glTF naming a 1.5 GB (sparse) buffer: the reader child took 1.5 GB
#    (5.1 GB with a real one) -> its memory limit ends it; buffers and OBJ
#    material libraries that are FIFOs are refused;
#  - Assimp's "ai_assert failure" and libpng's "libpng error" lines reached
#    the terminal -> one line, soak's own;
#  - -o a symbolic link: followed by every command (README).
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/input_bounds"
rm -rf "$D" && mkdir -p "$D"
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3
ONE_GB_KB=1048576
asan=0
ldd "$SOAK" 2>/dev/null | grep -q 'libasan' && asan=1

# bounded DESCRIPTION PATTERN -- command...: exit 1, one stderr line that
# matches PATTERN and starts with "soak ", peak memory under 1 GB.
bounded() {
  local what=$1 pattern=$2; shift 3
  /usr/bin/time -o "$D/rss" -f '%M' timeout 120 "$@" >"$D/out" 2>"$SOAK_TMP/last.err"
  local rc=$? kb
  kb=$(tail -n 1 "$D/rss")
  [ "$rc" = 1 ] && ok "$what: exit 1" || bad "$what: exit $rc (124: hung), stderr: $(head -c 300 "$SOAK_TMP/last.err")"
  expect_stderr "$pattern" "$what: the message"
  local lines
  lines=$(grep -vc '^$' "$SOAK_TMP/last.err")
  if [ "$lines" = 1 ] && head -n 1 "$SOAK_TMP/last.err" | grep -q '^soak '; then ok "$what: only soak speaks (one line)"
  else bad "$what: $lines lines on stderr: $(head -c 400 "$SOAK_TMP/last.err")"; fi
  if [ "$asan" = 1 ]; then skip "peak memory not measured in a sanitizer build (shadow memory)" "$what"
  elif number "$kb" && [ "$kb" -lt "$ONE_GB_KB" ]; then ok "$what: peak $kb KB < 1 GB"
  else bad "$what: peak '$kb' KB"; fi
}

# ---- scene files (and presets) ----
R=(render --width 4 --height 4 --spp 1 -o "$D/o.exr")
bounded "scene /dev/zero" "/dev/zero: cannot read this scene file: it is a device, not a regular file" -- "$SOAK" render /dev/zero "${R[@]:1}"
mkfifo "$D/fifo.json"
bounded "scene FIFO" "fifo\.json: cannot read this scene file: it is a FIFO \(pipe\), not a regular file" -- "$SOAK" render "$D/fifo.json" "${R[@]:1}"
bounded "scene /dev/stdin (a pipe)" "/dev/stdin: cannot read this scene file: it is a FIFO" -- "$SOAK" render /dev/stdin "${R[@]:1}" < <(:)
mkdir "$D/folder.json"
bounded "scene folder" "folder\.json: cannot read this scene file: it is a folder" -- "$SOAK" render "$D/folder.json" "${R[@]:1}"
truncate -s 2G "$D/sparse.json"
bounded "scene 2 GiB sparse" "sparse\.json: this scene file is 2147483648 bytes; the limit for a scene file is 16 MiB \(SOAK_MAX_SCENE_MB raises it\)" \
  -- "$SOAK" render "$D/sparse.json" "${R[@]:1}"
bounded "presets /dev/zero" "/dev/zero: cannot read this presets file: it is a device" -- "$SOAK" materials --materials /dev/zero
bounded "presets 2 GiB sparse" "sparse\.json: this presets file is 2147483648 bytes; the limit for a presets file is 16 MiB \(SOAK_MAX_PRESETS_MB" \
  -- "$SOAK" materials --materials "$D/sparse.json"
# The same limit and message in every command that reads the kind.
bounded "scene FIFO: advise" "fifo\.json: cannot read this scene file: it is a FIFO \(pipe\), not a regular file" \
  -- "$SOAK" advise "$D/fifo.json" --tol 0.1
mkfifo "$D/fifo_presets.json"
for cmd in "materials" "export --target json -o $D/e.json" "albedo --material sand --wetness 1"; do
  # shellcheck disable=SC2086
  bounded "presets FIFO: ${cmd%% *}" "fifo_presets\.json: cannot read this presets file: it is a FIFO \(pipe\)" \
    -- "$SOAK" $cmd --materials "$D/fifo_presets.json"
done
# Out of memory while reading: raise the cap, lower the address space.
if [ "$asan" = 1 ]; then skip "ulimit -v cannot be used in a sanitizer build" "scene out of memory"
else
  truncate -s 3G "$D/huge.json"
  (ulimit -v 1500000; SOAK_MAX_SCENE_MB=4000 "$SOAK" render "$D/huge.json" "${R[@]:1}") >/dev/null 2>"$SOAK_TMP/last.err"
  rc=$?
  [ "$rc" = 1 ] && ok "scene out of memory: exit 1" || bad "scene out of memory: exit $rc"
  expect_stderr "^soak render: .*huge\.json: out of memory for the 3221225472 bytes of this scene file$" \
    "scene out of memory: a message naming the file (was uninitialised bytes)"
fi

# ---- images ----
"$PY" - "$D" <<'PY'
import random, struct, sys, zlib
d = sys.argv[1]
def chunk(t, data=b"", length=None):
    n = len(data) if length is None else length
    return struct.pack(">I", n) + t + data + struct.pack(">I", zlib.crc32(t + data) & 0xffffffff)
def png(w, h, idat, pad=0):
    head = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0))
    return head, chunk(b"IDAT", idat) + chunk(b"IEND")
def zeros(w, h, level=1):
    c = zlib.compressobj(level)
    row = b"\0" * (w + 1)
    return b"".join([c.compress(row) for _ in range(h)] + [c.flush()])
# The padded bomb: 16384^2 of zeros, a 900 KB private chunk (a hole here).
head, tail = png(16384, 16384, zeros(16384, 16384, 9))
with open(f"{d}/bomb.png", "wb") as f:
    f.write(head + struct.pack(">I", 900000) + b"prVt")
    f.seek(900000 + 4, 1)
    f.write(tail)
head, tail = png(8192, 8192, zeros(8192, 8192))
open(f"{d}/mask8k.png", "wb").write(head + tail)
head, tail = png(65536, 1, zlib.compress(b"\0" + b"\xc8" * 65536))
open(f"{d}/wide.png", "wb").write(head + tail)
open(f"{d}/pnghead.png", "wb").write(head)
open(f"{d}/hdrhead.hdr", "wb").write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n")
# Genuine pixel data: zero rows with enough random rows to make the IDAT
# N bytes (random bytes do not compress), so no padding is involved.
def payload(w, h, n):
    c, rnd, out = zlib.compressobj(9), random.Random(7), []
    noisy = max(1, n // w)
    for y in range(h):
        body = bytes(rnd.getrandbits(8) for _ in range(w)) if y % (h // noisy) == 0 else b"\0" * w
        out.append(c.compress(b"\0" + body))
    return b"".join(out + [c.flush()])
head, tail = png(16384, 16384, payload(16384, 16384, 1150000))
open(f"{d}/dense1g.png", "wb").write(head + tail)
head, tail = png(10800, 10800, payload(10800, 10800, 1650000))
open(f"{d}/dense445.png", "wb").write(head + tail)
PY
bounded "padded PNG bomb" "bomb\.png: the PNG header claims 16384x16384x1 pixels \(1024 MiB as float\) from [0-9]+ bytes of pixel data \(IDAT\)" \
  -- "$SOAK" bake drying "$D/bomb.png" --time 0.5 -o "$D/o.png"
# 1.5 MB of real pixel data decoding to 1 GiB of floats: render peaked at
# 1.2 GB when the rule allowed 1024 float bytes per byte; at 256 it is refused.
map_scene() { # map_scene MAP > scene
  printf '{"camera": {"position": [0, -4, 0], "look_at": [0, 0, 0]}, "environment": {"type": "constant", "radiance": 1},
 "materials": {"w": {"type": "wet", "base": {"type": "lambert", "albedo": 0.5}}},
 "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "w", "wetness": {"type": "map", "file": "%s"}}]}\n' "$1"
}
map_scene dense1g.png >"$D/dense1g.json"
bounded "1.5 MB of pixel data claiming 1 GiB" "dense1g\.png: the PNG header claims 16384x16384x1 pixels \(1024 MiB as float\) from [0-9]+ bytes of pixel data \(IDAT\): more than 256 float bytes" \
  -- "$SOAK" render "$D/dense1g.json" "${R[@]:1}"
# 1.9 MB decoding to 445 MiB of floats is within the rule: read, rendered
# within 1 GB (the goal for any input under 2 MB).
map_scene dense445.png >"$D/dense445.json"
if [ "$asan" = 1 ]; then skip "a 445 MiB decode is not measured in a sanitizer build" "1.9 MB PNG decoding to 445 MiB"
else
  /usr/bin/time -o "$D/rss" -f '%M' timeout 120 "$SOAK" render "$D/dense445.json" "${R[@]:1}" >"$D/out" 2>"$SOAK_TMP/last.err"
  rc=$?; kb=$(tail -n 1 "$D/rss")
  [ "$rc" = 0 ] && ok "1.9 MB PNG decoding to 445 MiB: rendered" || bad "1.9 MB PNG decoding to 445 MiB: exit $rc: $(head -c 300 "$SOAK_TMP/last.err")"
  if number "$kb" && [ "$kb" -lt "$ONE_GB_KB" ]; then ok "1.9 MB PNG decoding to 445 MiB: peak $kb KB < 1 GB"
  else bad "1.9 MB PNG decoding to 445 MiB: peak '$kb' KB"; fi
fi
for ext in png tif jpg exr; do
  truncate -s 256M "$D/zeros.$ext"
  bounded "256 MiB of zeros named .$ext" "zeros\.$ext: not a valid [A-Za-z]+ file: it does not start with the [A-Za-z]+ signature" \
    -- "$SOAK" bake drying "$D/zeros.$ext" --time 0.5 -o "$D/o.png"
done
truncate -s 2G "$D/pnghead.png" "$D/hdrhead.hdr"
bounded "PNG header + 2 GiB of zeros" "pnghead\.png: PNG chunk 1 at byte 33 has no valid length and type" \
  -- "$SOAK" bake drying "$D/pnghead.png" --time 0.5 -o "$D/o.png"
bounded "HDR header + 2 GiB of zeros" "hdrhead\.hdr: Radiance HDR header without its end" \
  -- "$SOAK" bake drying "$D/hdrhead.hdr" --time 0.5 -o "$D/o.png"
"$SOAK" bake turbulence --width 64 --height 64 -o "$D/t.png" 2>/dev/null || bad "fixture t.png"
# Image reads have a time limit (the decoder runs in a child): a limit of
# 1 us has passed before the child has started, every time.
bounded "image reader past its time limit" "t\.png: the image reader did not finish within 1e-06 s: .*\(SOAK_IMAGE_TIMEOUT sets the limit\)" \
  -- env SOAK_IMAGE_TIMEOUT=1e-6 "$SOAK" bake drying "$D/t.png" --time 0.5 -o "$D/o.png"
"$PY" - "$D" <<'PY'
import sys
d = sys.argv[1]
b = bytearray(open(f"{d}/t.png", "rb").read())
i = b.index(b"IDAT")
for k in range(i + 20, i + 200): b[k] ^= 0x5A
open(f"{d}/corrupt.png", "wb").write(b)
PY
bounded "PNG with corrupt pixel data" "corrupt\.png: truncated or unreadable image data: PNG read error" \
  -- "$SOAK" bake drying "$D/corrupt.png" --time 0.5 -o "$D/o.png"
bounded "bake drying of an 8192^2 mask of 65 KB" \
  "mask8k\.png: drying a 8192x8192 mask needs about [0-9]+ MiB of working memory; the budget is 1024 MiB .*SOAK_MAX_MEMORY_MB sets it" \
  -- "$SOAK" bake drying "$D/mask8k.png" --time 0.5 -o "$D/o.png"
bounded "bake combine of two 8192^2 masks" \
  "mask8k\.png: combining 8192x8192 images needs about [0-9]+ MiB of working memory; the budget is 1024 MiB" \
  -- "$SOAK" bake combine max "$D/mask8k.png" "$D/mask8k.png" -o "$D/o.png"

# One side limit, one message, every command.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n' >"$D/tri.obj"
printf '{"camera": {"position": [0, -4, 0], "look_at": [0, 0, 0]}, "environment": {"type": "constant", "radiance": 1},
 "materials": {"w": {"type": "wet", "base": {"type": "lambert", "albedo": 0.5}}},
 "objects": [{"type": "mesh", "file": "tri.obj", "material": "w", "wetness": {"type": "map", "file": "wide.png"}}]}\n' >"$D/wide.json"
side="wide\.png: a 65536x1 image is larger than 16384 pixels on a side \(the limit of every command\)"
bounded "65536x1 map: render" "$side" -- "$SOAK" render "$D/wide.json" "${R[@]:1}"
bounded "65536x1 map: bake drying" "$side" -- "$SOAK" bake drying "$D/wide.png" --time 0.5 -o "$D/o.png"
bounded "65536x1 map: bake combine" "$side" -- "$SOAK" bake combine max "$D/wide.png" "$D/wide.png" -o "$D/o.png"

# ---- meshes and the files they name ----
mesh_scene() { # mesh_scene MESH > scene
  printf '{"camera": {"position": [0, -4, 0], "look_at": [0, 0, 0]}, "environment": {"type": "constant", "radiance": 1},
 "materials": {"m": {"type": "lambert", "albedo": 0.5}}, "objects": [{"type": "mesh", "file": "%s", "material": "m"}]}\n' "$1"
}
gltf() { # gltf BUFFER-URI > file
  printf '{"asset":{"version":"2.0"},"buffers":[{"uri":"%s","byteLength":1500000000}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],"min":[0,0,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}\n' "$1"
}
gltf big.bin >"$D/big.gltf"
mesh_scene big.gltf >"$D/big_scene.json"
if [ "$asan" = 1 ]; then skip "the reader's memory limit is off in a sanitizer build" "glTF naming a 1.5 GB buffer"
else
  truncate -s 1500000000 "$D/big.bin"
  bounded "glTF naming a 1.5 GB sparse buffer" "big\.gltf: .*memory limit .* MiB.*SOAK_MESH_MEMORY_MB" \
    -- "$SOAK" render "$D/big_scene.json" "${R[@]:1}"
fi
gltf fifo.bin >"$D/fifo_buf.gltf"
mkfifo "$D/fifo.bin"
mesh_scene fifo_buf.gltf >"$D/fifo_buf.json"
bounded "glTF buffer that is a FIFO" "fifo\.bin: cannot read this buffer named by .*fifo_buf\.gltf: it is a FIFO" \
  -- "$SOAK" render "$D/fifo_buf.json" "${R[@]:1}"
# Binary glTF: the same buffer "uri" inside the GLB's JSON chunk (glTF 2.0 sec. 4.4).
gltf fifo.bin | python3 -c '
import struct, sys
j = sys.stdin.buffer.read().rstrip(b"\n")
j += b" " * (-len(j) % 4)
sys.stdout.buffer.write(struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(j)) + struct.pack("<I4s", len(j), b"JSON") + j)' \
  >"$D/fifo_buf.glb"
mesh_scene fifo_buf.glb >"$D/fifo_glb.json"
bounded "GLB buffer that is a FIFO" "fifo\.bin: cannot read this buffer named by .*fifo_buf\.glb: it is a FIFO" \
  -- "$SOAK" render "$D/fifo_glb.json" "${R[@]:1}"
printf 'mtllib fifo.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$D/mtl.obj"
mkfifo "$D/fifo.mtl"
mesh_scene mtl.obj >"$D/mtl.json"
bounded "OBJ material library that is a FIFO" "fifo\.mtl: cannot read this material library named by .*mtl\.obj: it is a FIFO" \
  -- "$SOAK" render "$D/mtl.json" "${R[@]:1}"
tail -c +2 "$SOAK_ROOT/tests/fuzz/reproducers/mesh/off_triangulate_assert_26a8c915" >"$D/assert.off"
mesh_scene assert.off >"$D/assert.json"
bounded "Assimp assertion" "assert\.off: the mesh reader crashed on this file \(.*\): malformed file \(the reader said: ai_assert failure" \
  -- "$SOAK" render "$D/assert.json" "${R[@]:1}"

# ---- -o a symbolic link: followed by every command ----
mkdir -p "$D/real"
for cmd in render drying combine; do
  echo old >"$D/real/$cmd.png"
  ln -s "real/$cmd.png" "$D/link_$cmd.png"
done
"$SOAK" render "$SOAK_ROOT/scenes/sand.json" --width 8 --height 8 --spp 1 -o "$D/link_render.png" >/dev/null 2>&1
"$SOAK" bake drying "$D/t.png" --time 0.5 -o "$D/link_drying.png" >/dev/null 2>&1
"$SOAK" bake combine max "$D/t.png" "$D/t.png" -o "$D/link_combine.png" >/dev/null 2>&1
for cmd in render drying combine; do
  if [ -L "$D/link_$cmd.png" ] && [ "$(head -c 4 "$D/real/$cmd.png" | tail -c 3)" = PNG ]; then
    ok "-o a symbolic link ($cmd): the link stays, its target holds the new PNG"
  else bad "-o a symbolic link ($cmd): link or target wrong"; fi
done
finish
