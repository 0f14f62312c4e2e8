#!/usr/bin/env bash
# Budgets up front (issue 51 item 3): in-range options of `bake drops`,
# `bake ripples` and `bake rain` that took 31-79 s, 2.6-2.7 GB, ran past 300 s or until
# memory ran out (17 h estimated for one) must be refused before any work:
# exit 2 within a bound (`timeout 20`: the refusal is immediate; the bakes
# took 31 s and more), peak memory of soak under 1 GB (/usr/bin/time's %M),
# a message giving the estimate's terms and the variable that raises the
# budget. Bakes inside the budget still run.
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/budgets"
rm -rf "$D" && mkdir -p "$D"
cd "$D" || exit 1
TIME=/usr/bin/time
[ -x "$TIME" ] || { skip "budgets" "/usr/bin/time not on PATH"; finish; }

# refused VARIABLE -- soak arguments...
refused() {
  local var=$1
  shift 2
  timeout 20 "$TIME" -f '%M' -o mem.txt "$SOAK" "$@" >/dev/null 2>err.txt
  local rc=$? kb
  kb=$(tail -1 mem.txt 2>/dev/null)
  [ $rc -eq 2 ] && ok "refused (exit 2): $*" || bad "$*: exit $rc, want 2 (124 = still running after 20 s)"
  grep -q -- "$var" err.txt && grep -q "refused before any work" err.txt && ok "message names $var" \
    || bad "message lacks $var: $(head -c 300 err.txt)"
  [ -n "$kb" ] && [ "$kb" -lt 1048576 ] && ok "peak memory ${kb} KB < 1 GB" || bad "peak memory '${kb}' KB"
  [ -z "$(ls -A | grep -v -e err.txt -e mem.txt)" ] && ok "nothing written" || bad "files written: $(ls -A)"
}

refused SOAK_MAX_MEMORY_MB -- bake drops --width 16 --height 16 --texel 2 -o d.exr
refused SOAK_MAX_MEMORY_MB -- bake drops --width 16 --height 16 --texel 100 -o d.exr
refused SOAK_MAX_BAKE_S -- bake drops --rate 500 --duration 1e6 -o d.exr
refused SOAK_MAX_MEMORY_MB -- bake ripples --width 64 --tile 100 -o r.exr
refused SOAK_MAX_BAKE_S -- bake ripples --width 64 --ring-width 10 -o r.exr
refused SOAK_MAX_BAKE_S -- bake ripples --width 64 --lifetime 1e3 -o r.exr
refused SOAK_MAX_BAKE_S -- bake ripples --width 64 --wavelength 10 -o r.exr
grep -q "4.56e+07 impacts" <(cd "$D" && "$SOAK" bake drops --width 16 --height 16 --texel 2 -o d.exr 2>&1) \
  && ok "the drops estimate: 4451 impacts/m^2/s (Marshall-Palmer x Atlas, 10 mm/h) x 1024 m^2 x 10 s = 4.56e7" \
  || bad "the drops estimate is not flux x area x duration"

# Rain (issue 51's remaining gap): a sequence's time steps up to its last
# frame, the single map's --steps, both over texels, refused before the mesh
# is read. The first took over an hour before the budget (0.001 fps, 1000
# frames: 999000 s of simulated time in steps of 600 s / 32).
printf 'v 0 0 0\nv 1 0 0.5\nv 1 1 0.5\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' >"$SOAK_TMP/plane.obj"
refused SOAK_MAX_BAKE_S -- bake rain "$SOAK_TMP/plane.obj" --fps 0.001 --frames 0-999 -o 'w.%04d.exr'
refused SOAK_MAX_MEMORY_MB -- bake rain "$SOAK_TMP/plane.obj" --width 16384 --height 16384 --steps 1 --rays 1 -o w.exr
refused SOAK_MAX_BAKE_S -- bake rain "$SOAK_TMP/plane.obj" --width 2048 --height 2048 --steps 20000 -o w.exr
grep -q "5.428e+04 time steps of 18.75 s" <("$SOAK" bake rain "$SOAK_TMP/plane.obj" --fps 0.001 --frames 0-999 \
  -o "$D/w.%04d.exr" 2>&1) \
  && ok "the rain estimate: floor(999000 s / (600 s / 32)) = 53280 whole steps + 1000 frames' cut steps" \
  || bad "the rain estimate is not whole steps to the last frame plus one per frame"
rm -f "$D"/w.*

# The variable raises the budget; inside it the bakes run.
expect_exit 0 "ripples at the documented size, 4 frames" -- "$SOAK" bake ripples --width 64 --frames 0-3 -o 'ok%d.exr'
expect_exit 0 "drops at the defaults" -- "$SOAK" bake drops --width 64 --height 64 -o ok.exr
expect_exit 0 "rain at the defaults, 4 frames" -- "$SOAK" bake rain "$SOAK_TMP/plane.obj" --width 32 --height 32 \
  --frames 0-3 -o 'okr%d.exr'
expect_exit 0 "rain's single map at the defaults, 256^2" -- "$SOAK" bake rain "$SOAK_TMP/plane.obj" --width 256 --height 256 -o okr.exr
expect_exit 2 "SOAK_MAX_BAKE_S sets the work budget (1e-6 s refuses a small loop)" -- env SOAK_MAX_BAKE_S=1e-6 \
  "$SOAK" bake ripples --width 64 --frames 0-3 -o 'no%d.exr'
finish
