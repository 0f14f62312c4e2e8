#!/bin/bash
# soak bake volume / rain from the command line: good runs write their files,
# bad inputs exit non-zero with a message naming the culprit and leave no
# output (nor temporaries) behind.
set -u
: "${SOAK:?}" "${SOAK_TMP:?}"
. "$(dirname "$0")/lib.bash"   # uv_plane_obj
D="$SOAK_TMP/bake_volume_rain"
rm -rf "$D"
mkdir -p "$D"
fail=0

# expect CODE PATTERN -- command...: exit code and a stderr pattern.
expect() {
    local code=$1 pattern=$2
    shift 3
    "$@" >"$D/out.txt" 2>"$D/err.txt"
    local got=$?
    if [ "$got" != "$code" ] || ! grep -q -- "$pattern" "$D/err.txt" "$D/out.txt"; then
        echo "FAIL: $* -> exit $got (want $code), output:"
        cat "$D/err.txt" "$D/out.txt"
        fail=1
    else
        echo "ok   exit $code, '$pattern': $*"
    fi
}

# no_files GLOB...: nothing matching (outputs or temporaries) exists.
no_files() {
    for g in "$@"; do
        if compgen -G "$g" >/dev/null; then
            echo "FAIL: left behind: $(compgen -G "$g" | tr '\n' ' ')"
            fail=1
        fi
    done
}

RAW=(--dry-sigma-s 100 --dry-sigma-a 1,2,3 --wet-g1 0.8)

# ---- volume ----
expect 0 "usage: soak bake volume" -- "$SOAK" bake volume --help
expect 2 "\-o/--output" -- "$SOAK" bake volume "${RAW[@]}"
expect 2 "\-\-dims" -- "$SOAK" bake volume "${RAW[@]}" --dims 4,4 -o "$D/v"
expect 2 "\-\-dims" -- "$SOAK" bake volume "${RAW[@]}" --dims 0,4,4 -o "$D/v"
expect 2 "\-\-dry-sigma-a" -- "$SOAK" bake volume --dry-sigma-s 1 --dry-sigma-a -1 -o "$D/v"
expect 2 "\-\-wet-g1" -- "$SOAK" bake volume "${RAW[@]}" --wet-g1 1.5 -o "$D/v"
expect 2 "\-\-format" -- "$SOAK" bake volume "${RAW[@]}" --format obj -o "$D/v"
expect 2 "\-\-material" -- "$SOAK" bake volume --material no_such_thing -o "$D/v"
expect 2 "conductor" -- "$SOAK" bake volume --material copper -o "$D/v"
expect 2 "exclude" -- "$SOAK" bake volume --material sand "${RAW[@]}" -o "$D/v"
expect 1 "missing.png" -- "$SOAK" bake volume "${RAW[@]}" --map "$D/missing.png" --dims 4,4,4 -o "$D/v"
expect 1 "no_dir" -- "$SOAK" bake volume "${RAW[@]}" --dims 4,4,4 -o "$D/no_dir/v"
expect 2 "unknown option" -- "$SOAK" bake volume "${RAW[@]}" --bogus -o "$D/v"
no_files "$D/v*" "$D/.v*" "$D/no_dir"

expect 0 "8x6x4 voxels" -- "$SOAK" bake volume "${RAW[@]}" --dims 8,6,4 --size 0.1,0.1,0.02 --depth 0.01 \
    --threads 2 --format grid,df3 -o "$D/v"
for f in v.json v.raw v_df3.json v.inc v_sigma_s_r.df3 v_wetness.df3 v_g2.df3; do
    [ -s "$D/$f" ] || { echo "FAIL: $f missing"; fail=1; }
done
# grid .raw = 10 channels * 8*6*4 voxels * 4 bytes; df3 = 6 + (10*8*6) * 2 bytes
[ "$(stat -c %s "$D/v.raw")" = $((10 * 8 * 6 * 4 * 4)) ] || { echo "FAIL: v.raw size"; fail=1; }
[ "$(stat -c %s "$D/v_g1.df3")" = $((6 + 10 * 8 * 6 * 2)) ] || { echo "FAIL: v_g1.df3 size"; fail=1; }
# OpenVDB output: written when the build has OpenVDB, else a clear refusal.
if "$SOAK" bake volume "${RAW[@]}" --dims 4,4,4 --format vdb -o "$D/vv" >"$D/out.txt" 2>"$D/err.txt"; then
    [ -s "$D/vv.vdb" ] || { echo "FAIL: vv.vdb missing"; fail=1; }
    echo "ok   vdb written"
elif grep -q "no OpenVDB support" "$D/err.txt"; then
    echo "ok   vdb refused: $(cat "$D/err.txt")"
    no_files "$D/vv*"
else
    echo "FAIL: --format vdb: $(cat "$D/err.txt")"
    fail=1
fi
expect 0 "grid" -- "$SOAK" bake volume --material sand --noise --seed 3 --dims 6,6,6 --format grid -o "$D/sand"
no_files "$D/.*tmp*"

# ---- rain ----
uv_plane_obj "$D/plane.obj" "$D/nouv.obj"
expect 0 "usage: soak bake rain" -- "$SOAK" bake rain --help
expect 2 "MESH" -- "$SOAK" bake rain -o "$D/r.exr"
expect 1 "no UVs" -- "$SOAK" bake rain "$D/nouv.obj" --width 16 --height 16 -o "$D/r.exr"
expect 1 "missing.obj" -- "$SOAK" bake rain "$D/missing.obj" --width 16 --height 16 -o "$D/r.exr"
expect 2 "\-\-rays" -- "$SOAK" bake rain "$D/plane.obj" --rays 0 -o "$D/r.exr"
expect 2 "\-\-rain-dir" -- "$SOAK" bake rain "$D/plane.obj" --rain-dir 0,-1,0 -o "$D/r.exr"
expect 2 "\-\-up" -- "$SOAK" bake rain "$D/plane.obj" --up w -o "$D/r.exr"
expect 2 "\-\-spread" -- "$SOAK" bake rain "$D/plane.obj" --spread nan -o "$D/r.exr"
expect 2 "\-\-frames" -- "$SOAK" bake rain "$D/plane.obj" --frames 3-1 -o "$D/r.%04d.exr"
expect 2 "plane.obj" -- "$SOAK" bake rain "$D/plane.obj" -o "$D/plane.obj"
expect 1 "no_dir" -- "$SOAK" bake rain "$D/plane.obj" --width 16 --height 16 -o "$D/no_dir/r.exr"
no_files "$D/r*" "$D/.r*"
expect 0 "rain wetness" -- "$SOAK" bake rain "$D/plane.obj" --width 32 --height 32 --rays 16 --duration 60 \
    --steps 2 --exposure "$D/e.exr" --water "$D/w.exr" -o "$D/r.exr"
for f in r.exr e.exr w.exr; do [ -s "$D/$f" ] || { echo "FAIL: $f missing"; fail=1; }; done
no_files "$D/.*tmp*"

exit $fail
