#!/usr/bin/env bash
# The heavy I/O libraries are loaded only by the commands that need them
# (soak/plugin.h): `soak eval` and `soak albedo` map no OpenImageIO, OpenVDB
# or Assimp; an image command loads OpenImageIO and not the other two; a .vdb
# loads OpenVDB. Observed from outside soak: the dynamic loader's own trace
# (LD_DEBUG=libs, every object it initialises) and the kernel's
# /proc/PID/maps of a running eval. A missing module is a clear error.
. "$(dirname "$0")/lib.bash"

heavy='libOpenImageIO|libopenvdb|libassimp|libgdal|libavcodec|libsoak_(image|vdb|mesh)\.so'

# loaded NAME -- command...: the objects the loader initialised (one path
# a line) in $SOAK_TMP/NAME.libs; the command's exit status is returned.
loaded() {
  local name=$1; shift 2
  LD_DEBUG=libs LD_DEBUG_OUTPUT="$SOAK_TMP/$name.ld" "$@" > "$SOAK_TMP/$name.out" 2> "$SOAK_TMP/$name.err"
  local rc=$?
  cat "$SOAK_TMP/$name.ld".* 2> /dev/null | sed -n 's/.*calling init: //p' | sort -u > "$SOAK_TMP/$name.libs"
  rm -f "$SOAK_TMP/$name.ld".*
  return $rc
}

# Control: the trace sees the C library in any program.
loaded control -- "$SOAK" eval --model lambert --theta-i 0 --theta-o 0
grep -q 'libc\.so' "$SOAK_TMP/control.libs" && ok "LD_DEBUG trace lists libc ($(wc -l < "$SOAK_TMP/control.libs") objects)" \
  || bad "LD_DEBUG trace is empty: $(head -c 300 "$SOAK_TMP/control.err")"

for cmd in "eval --model ww --theta-i 20 --theta-o 65 --phi 150" "albedo --material sand --wetness 1" "materials"; do
  name=${cmd%% *}
  if loaded "$name" -- "$SOAK" $cmd; then
    found=$(grep -E "$heavy" "$SOAK_TMP/$name.libs" | tr '\n' ' ')
    [ -z "$found" ] && ok "soak $name loads none of OIIO/OpenVDB/Assimp ($(wc -l < "$SOAK_TMP/$name.libs") objects)" \
      || bad "soak $name loads $found"
  else
    bad "soak $cmd failed: $(head -c 300 "$SOAK_TMP/$name.err")"
  fi
done

# /proc/PID/maps of an eval caught while it writes: the pipe (64 KiB) is
# full long before its 190 KB of CSV are out, so it is alive and past its
# start-up when the first line arrives.
fifo="$SOAK_TMP/eval.fifo"
rm -f "$fifo" && mkfifo "$fifo"
"$SOAK" eval --model ww --csv --step 1 > "$fifo" &
pid=$!
exec 3< "$fifo"
IFS= read -r first <&3
maps=$(cat "/proc/$pid/maps" 2> /dev/null)
cat <&3 > /dev/null
exec 3<&-
wait "$pid"
rc=$?
rm -f "$fifo"
files=$(printf '%s\n' "$maps" | awk '$6 ~ /^\// { print $6 }' | sort -u)
if [ "$rc" != 0 ] || [ -z "$first" ] || ! printf '%s\n' "$files" | grep -q 'libc\.so'; then
  bad "eval --csv under observation: exit $rc, first line '$first', $(printf '%s\n' "$files" | grep -c .) mapped files"
else
  found=$(printf '%s\n' "$files" | grep -E "$heavy" | tr '\n' ' ')
  [ -z "$found" ] && ok "running eval maps $(printf '%s\n' "$files" | grep -c '\.so') shared objects, none of OIIO/OpenVDB/Assimp" \
    || bad "running eval maps $found"
fi

# An image command loads the image module and OpenImageIO (which itself
# links OpenVDB, its .vdb reader), not the mesh module or Assimp.
cd "$SOAK_TMP" || exit 1
rm -f m.png
if loaded image -- "$SOAK" bake turbulence --width 16 --height 16 --octaves 1 -o m.png && [ -s m.png ]; then
  grep -qE 'libsoak_image\.so' "$SOAK_TMP/image.libs" && grep -qE 'libOpenImageIO\.so' "$SOAK_TMP/image.libs" \
    && ok "image command loads libsoak_image.so and OpenImageIO" || bad "image command: no OpenImageIO in its trace"
  found=$(grep -E 'libassimp|libsoak_(vdb|mesh)' "$SOAK_TMP/image.libs" | tr '\n' ' ')
  [ -z "$found" ] && ok "image command loads neither Assimp nor the vdb/mesh modules" || bad "image command loads $found"
else
  bad "bake turbulence -o m.png failed: $(head -c 300 "$SOAK_TMP/image.err")"
fi

# A .vdb loads OpenVDB and no image library.
rm -f v.vdb
if "$SOAK" bake volume --help 2> /dev/null | grep -q vdb && loaded vdb -- "$SOAK" bake volume --material sand --dims 2,2,2 --format vdb -o v; then
  grep -qE 'libopenvdb' "$SOAK_TMP/vdb.libs" && ok "vdb output loads OpenVDB" || bad "vdb output: no OpenVDB in its trace"
  found=$(grep -E 'libOpenImageIO|libassimp' "$SOAK_TMP/vdb.libs" | tr '\n' ' ')
  [ -z "$found" ] && ok "vdb output loads no OpenImageIO/Assimp" || bad "vdb output loads $found"
elif grep -q "no OpenVDB support" "$SOAK_TMP/vdb.err" 2> /dev/null; then
  skip "this build has no OpenVDB" "vdb module"
else
  bad "bake volume --format vdb failed: $(head -c 300 "$SOAK_TMP/vdb.err")"
fi

# Started through an explicit loader (as the Blender 4.3 tests start soak in
# their chroot: /proc/self/exe is then the loader), a copy of soak still
# takes the modules beside it.
loader=$(readelf -l "$SOAK" 2> /dev/null | sed -n 's/.*program interpreter: \(.*\)]/\1/p')
if [ -x "$loader" ]; then
  inst="$SOAK_TMP/installed"
  rm -rf "$inst" && mkdir -p "$inst"
  cp "$SOAK" "$(dirname "$SOAK")"/libsoak_*.so "$inst/"
  rm -f l.png
  if loaded explicit -- "$loader" "$inst/soak" bake turbulence --width 8 --height 8 -o l.png && [ -s l.png ]; then
    grep -qx "$inst/libsoak_image.so" "$SOAK_TMP/explicit.libs" && ok "under $loader the image module beside the copy is used" \
      || bad "under $loader: $(grep libsoak_image "$SOAK_TMP/explicit.libs" || echo no image module) loaded, want $inst/libsoak_image.so"
  else
    bad "soak under $loader failed: $(head -c 300 "$SOAK_TMP/explicit.err")"
  fi
else
  skip "no program interpreter found in $SOAK" "explicit loader"
fi

# No module where soak looks: a clear error naming the module and the folder.
empty="$SOAK_TMP/no-modules"
mkdir -p "$empty"
rm -f n.png
expect_exit 1 "image output without the image module" -- env SOAK_PLUGIN_DIR="$empty" "$SOAK" bake turbulence --width 8 --height 8 -o n.png
expect_stderr "n\.png: cannot load the image I/O \(OpenImageIO\) module libsoak_image\.so: not found in $empty" \
  "message names the output, the module and the folder searched"
[ ! -e n.png ] && ok "nothing written without the module" || bad "n.png written without the module"
expect_exit 0 "eval without any module" -- env SOAK_PLUGIN_DIR="$empty" "$SOAK" eval --model lambert --theta-i 0 --theta-o 0

finish
