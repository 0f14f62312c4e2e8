#!/bin/bash
# Nothing lost (issue 13, items 1-4): a write that fails is an error, the
# previous output survives byte for byte, no temporary is left, multi-output
# bakes replace all their files or none, results lost on stdout fail the
# command, and bad -o paths are refused.
#
# A full disk is reproduced without privileges by the file size limit:
# `ulimit -f N` with SIGXFSZ ignored makes every write past N KiB fail with
# EFBIG, exactly where ENOSPC would. Where a mount namespace is available
# (root, or unprivileged user namespaces) a real 64 KiB tmpfs is used too.
set -u
: "${SOAK:?}" "${SOAK_TMP:?}"
source "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/outputs"
rm -rf "$D"
mkdir -p "$D"

# only FILE...: the folder holds exactly these names (no temporaries).
only() {
    local want got
    want=$(printf '%s\n' "$@" | sort | tr '\n' ' ')
    got=$(ls -A "$D" | sort | tr '\n' ' ')
    if [ "$want" = "$got" ]; then ok "folder holds only: $want"; else bad "folder holds '$got', want '$want'"; fi
}
# same A B WHAT: byte-identical files.
same() { if cmp -s "$1" "$2"; then ok "$3"; else bad "$3: $1 changed"; fi; }
# limited KIB command...: the command under a file size limit.
limited() {
    local kib=$1
    shift
    (ulimit -f "$kib"; trap '' XFSZ; exec "$@")
}

TURB=(bake turbulence --width 256 --height 256 --octaves 8)

# ---- 1. a failed write is an error and keeps the previous output ----
for ext in png exr tif tx; do
    rm -rf "$D" && mkdir -p "$D"
    "$SOAK" "${TURB[@]}" --seed 1 -o "$D/wet.$ext" 2>/dev/null
    cp "$D/wet.$ext" "$SOAK_TMP/good.$ext"
    expect_exit 1 "bake .$ext on a full disk fails" -- limited 4 "$SOAK" "${TURB[@]}" --seed 2 -o "$D/wet.$ext"
    expect_stderr "wet\.$ext.*(File too large|cannot write)" "error names wet.$ext and the reason"
    same "$D/wet.$ext" "$SOAK_TMP/good.$ext" "previous wet.$ext kept byte for byte"
    only "wet.$ext"
done

cat >"$D/../scene.json" <<'J'
{"camera": {"position": [0, -4, 0], "look_at": [0, 0, 0]}, "environment": {"type": "constant", "radiance": 1},
 "materials": {"m": {"type": "lambert", "albedo": 0.5}}, "lights": [{"type": "sun", "direction": [1, -1, 1], "irradiance": 3}],
 "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]}
J
SCENE="$D/../scene.json"
for ext in png jpg exr; do
    rm -rf "$D" && mkdir -p "$D"
    "$SOAK" render "$SCENE" --width 128 --height 128 --spp 1 --seed 1 -o "$D/r.$ext" >/dev/null 2>&1
    cp "$D/r.$ext" "$SOAK_TMP/good_r.$ext"
    expect_exit 1 "render .$ext on a full disk fails" -- limited 1 "$SOAK" render "$SCENE" --width 128 --height 128 \
        --spp 1 --seed 2 -o "$D/r.$ext"
    expect_stderr "r\.$ext" "error names r.$ext"
    same "$D/r.$ext" "$SOAK_TMP/good_r.$ext" "previous r.$ext kept"
    only "r.$ext"
done

# A real full file system, where this machine allows a private mount.
if unshare -rm true 2>/dev/null; then
    rm -rf "$D" && mkdir -p "$D"
    unshare -rm bash -c "mount -t tmpfs -o size=64k tmpfs '$D' && \
        '$SOAK' bake turbulence --width 32 --height 32 -o '$D/small.png' && \
        '$SOAK' ${TURB[*]} -o '$D/big.exr'; echo \$? > '$SOAK_TMP/tmpfs.rc'; ls -A '$D' > '$SOAK_TMP/tmpfs.ls'" \
        >/dev/null 2>"$SOAK_TMP/tmpfs.err"
    [ "$(cat "$SOAK_TMP/tmpfs.rc")" = 1 ] && ok "64 KiB tmpfs: big bake fails (exit 1)" || bad "64 KiB tmpfs: exit $(cat "$SOAK_TMP/tmpfs.rc"), $(cat "$SOAK_TMP/tmpfs.err")"
    grep -q "No space left" "$SOAK_TMP/tmpfs.err" && ok "tmpfs: error says No space left" || bad "tmpfs: $(cat "$SOAK_TMP/tmpfs.err")"
    [ "$(cat "$SOAK_TMP/tmpfs.ls")" = "small.png" ] && ok "tmpfs: no temporary left" || bad "tmpfs holds: $(cat "$SOAK_TMP/tmpfs.ls")"
else
    skip "no mount namespace here (the file size limit above covers it)" "real tmpfs check"
fi

# Without /proc (no anonymous temporaries) the named-temporary fallback
# must give the same guarantees.
# (Sanitizer builds need /proc to start: skipped there.)
if unshare -rm bash -c "mount -t tmpfs none /proc && '$SOAK' --version" >/dev/null 2>&1; then
    rm -rf "$D" && mkdir -p "$D"
    unshare -rm bash -c "mount -t tmpfs none /proc && '$SOAK' bake turbulence --width 64 --height 64 -o '$D/a.exr' && \
        cp '$D/a.exr' '$SOAK_TMP/fb_good.exr' && \
        (ulimit -f 4; trap '' XFSZ; exec '$SOAK' ${TURB[*]} --seed 2 -o '$D/a.exr'); echo \$? > '$SOAK_TMP/fb.rc'" \
        >/dev/null 2>&1
    [ "$(cat "$SOAK_TMP/fb.rc")" = 1 ] && ok "no /proc: failed write is an error" || bad "no /proc: exit $(cat "$SOAK_TMP/fb.rc")"
    same "$D/a.exr" "$SOAK_TMP/fb_good.exr" "no /proc: previous a.exr kept"
    only a.exr
else
    skip "soak cannot start without /proc here (sanitizer build or no user namespace; the release pass runs it)" \
        "no /proc fallback"
fi

# ---- 2. multi-output bakes replace all or none ----
rm -rf "$D" && mkdir -p "$D"
uv_plane_obj "$SOAK_TMP/plane.obj"
RAIN=(bake rain "$SOAK_TMP/plane.obj" --width 64 --height 64 --rays 8 --duration 60 --steps 2)
"$SOAK" "${RAIN[@]}" --seed 1 -o "$D/r.png" --exposure "$D/e.exr" >/dev/null 2>&1
cp "$D/r.png" "$SOAK_TMP/good_r.png"
# The exposure (second output) becomes a dangling link: it fails only after
# the wet map has been produced.
mv "$D/e.exr" "$SOAK_TMP/e_saved.exr"
ln -s "$D/nowhere/e.exr" "$D/e.exr"
expect_exit 1 "rain with an unwritable second output fails" -- "$SOAK" "${RAIN[@]}" --seed 2 -o "$D/r.png" \
    --exposure "$D/e.exr"
expect_stderr "e\.exr" "error names e.exr"
same "$D/r.png" "$SOAK_TMP/good_r.png" "rain: previous r.png kept"
only e.exr r.png
rm "$D/e.exr" && cp "$SOAK_TMP/e_saved.exr" "$D/e.exr"
# A full disk hitting only the larger second output (.tif, uncompressed-ish
# 16 bit, 64x64x1 > the limit > the wet png).
rsize=$(stat -c %s "$D/r.png")
"$SOAK" "${RAIN[@]}" --seed 1 -o "$D/probe.png" --exposure "$D/probe.tx" >/dev/null 2>&1
tsize=$(stat -c %s "$D/probe.tx")
rm -f "$D"/probe.*
kib=$(( (rsize + tsize) / 2048 ))
cp "$D/e.exr" "$SOAK_TMP/good_e.exr"
if [ "$kib" -gt $(( rsize / 1024 )) ] && [ $(( kib * 1024 )) -lt "$tsize" ]; then
    expect_exit 1 "rain: second output hits the full disk" -- limited "$kib" "$SOAK" "${RAIN[@]}" --seed 3 \
        -o "$D/r.png" --exposure "$D/e.tx"
    same "$D/r.png" "$SOAK_TMP/good_r.png" "rain: r.png untouched when e.tx fails"
    only e.exr r.png
else
    bad "rain: cannot place a size limit between r.png ($rsize) and e.tx ($tsize)"
fi

rm -rf "$D" && mkdir -p "$D"
VOL=(bake volume --dry-sigma-s 100 --dry-sigma-a 1,2,3 --wet-g1 0.8 --noise --dims 24,24,24)
if "$SOAK" "${VOL[@]}" --seed 1 --format vdb,grid -o "$D/v" >/dev/null 2>&1; then
    cp "$D/v.vdb" "$SOAK_TMP/good.vdb"
    cp "$D/v.json" "$SOAK_TMP/good.json"
    vsize=$(stat -c %s "$D/v.vdb")
    rawsize=$(stat -c %s "$D/v.raw")
    rm "$D/v.raw"
    kib=$(( (vsize + rawsize) / 2048 ))
    expect_exit 1 "volume: the grid's .raw hits the full disk" -- limited "$kib" "$SOAK" "${VOL[@]}" --seed 2 \
        --format vdb,grid -o "$D/v"
    same "$D/v.vdb" "$SOAK_TMP/good.vdb" "volume: previous v.vdb kept"
    same "$D/v.json" "$SOAK_TMP/good.json" "volume: previous v.json kept"
    only v.json v.vdb
else
    skip "no OpenVDB in this build" "volume vdb,grid"
fi

# ---- 3. results lost on stdout fail the command ----
expect_exit 1 "eval --list > /dev/full" -- bash -c "'$SOAK' eval --list > /dev/full"
expect_stderr "standard output" "says the results were lost"
expect_exit 1 "eval --csv > /dev/full" -- bash -c "'$SOAK' eval --model lambert --csv > /dev/full"
expect_exit 1 "albedo > /dev/full" -- bash -c "'$SOAK' albedo --material sand --wetness 1 > /dev/full"
expect_exit 1 "measure > /dev/full" -- bash -c "'$SOAK' measure --config film --base-albedo 0.5 --paths 2000 > /dev/full"
expect_exit 1 "render > /dev/full" -- bash -c "'$SOAK' render '$SCENE' --width 8 --height 8 --spp 1 -o '$D/s.exr' > /dev/full"

# ---- 4. -o paths ----
rm -rf "$D" && mkdir -p "$D/sub"
expect_exit 2 "-o folder/" -- "$SOAK" bake turbulence --width 8 --height 8 -o "$D/sub/"
expect_stderr "names a folder" "-o folder/: says it names a folder"
expect_exit 2 "-o existing folder" -- "$SOAK" bake turbulence --width 8 --height 8 -o "$D/sub"
expect_exit 2 "-o .exr" -- "$SOAK" bake turbulence --width 8 --height 8 -o "$D/.exr"
expect_stderr "no file name before the extension" "-o .exr: says the name is missing"
expect_exit 2 '-o ""' -- "$SOAK" bake turbulence --width 8 --height 8 -o ""
expect_stderr "output path is empty" '-o "": says the path is empty'
expect_exit 2 "volume -o d/" -- "$SOAK" bake volume --dry-sigma-s 1 --dry-sigma-a 1 --dims 4,4,4 -o "$D/sub/"
expect_stderr "prefix" "volume -o d/: asks for a prefix"
expect_exit 2 "render -o d/" -- "$SOAK" render "$SCENE" --width 8 --height 8 --spp 1 -o "$D/sub/"
mkfifo "$D/fifo.png"
expect_exit 2 "-o a fifo" -- "$SOAK" bake turbulence --width 8 --height 8 -o "$D/fifo.png"
expect_stderr "not a regular file" "-o fifo: refused"
only fifo.png sub
# Symbolic links are followed: the target is replaced, the link stays.
"$SOAK" bake turbulence --width 8 --height 8 --seed 1 -o "$D/sub/real.png" 2>/dev/null
cp "$D/sub/real.png" "$SOAK_TMP/real_before.png"
ln -s sub/real.png "$D/link.png"
expect_exit 0 "-o a symlink" -- "$SOAK" bake turbulence --width 8 --height 8 --seed 9 -o "$D/link.png"
[ -L "$D/link.png" ] && ok "the link is still a link" || bad "the link was replaced by a file"
cmp -s "$D/sub/real.png" "$SOAK_TMP/real_before.png" && bad "the link's target was not rewritten" || ok "the target holds the new map"
ln -s missing/x.png "$D/dangling.png"
expect_exit 1 "-o a dangling symlink" -- "$SOAK" bake turbulence --width 8 --height 8 -o "$D/dangling.png"
expect_stderr "symbolic link to a missing file" "dangling link: says so"

# ---- 5. same seed, same bytes (the clock no longer stamps EXR/TIFF) ----
rm -rf "$D" && mkdir -p "$D"
for ext in exr tif tx png; do
    "$SOAK" bake turbulence --width 100 --height 70 --seed 4 --threads 1 -o "$D/a.$ext" 2>/dev/null
done
sleep 1.1 # the DateTime stamp has one-second resolution
for ext in exr tif tx png; do
    "$SOAK" bake turbulence --width 100 --height 70 --seed 4 --threads 2 -o "$D/b.$ext" 2>/dev/null
    cmp -s "$D/a.$ext" "$D/b.$ext" && ok "bake .$ext: same bytes a second later on 2 threads" || bad "bake .$ext: bytes differ"
done

finish
