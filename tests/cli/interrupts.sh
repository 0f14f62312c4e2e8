#!/bin/bash
# Interrupts (issue 13, item 6): --time and Ctrl-C stop the caustic photon
# pass (1e9 photons used to run on for minutes), and no temporary file
# survives an interrupt or a kill at any moment of a run, the final write
# included: outputs are staged in anonymous files (soak/staged.h).
set -u
: "${SOAK:?}" "${SOAK_TMP:?}"
source "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/interrupts"
rm -rf "$D" && mkdir -p "$D/out"

cat >"$D/caustic.json" <<'J'
{"render": {"width": 32, "height": 32, "spp": 4, "caustic_photons": 1000000000, "caustic_radius": 0.05},
 "camera": {"position": [0, -4, 1.5], "look_at": [0, 0, 0.3]},
 "environment": {"type": "constant", "radiance": 0.2},
 "lights": [{"type": "sun", "direction": [0.1, -0.2, 1], "irradiance": 3}],
 "materials": {"glass": {"type": "dielectric", "ior": 1.5},
   "milk": {"type": "wet", "film": {"ior": 1.33},
            "base": {"type": "medium", "sigma_s": 20, "sigma_a": 0.5, "g1": 0.5, "g2": 0, "w": 1, "ior": 1.33}}},
 "objects": [{"type": "sphere", "center": [0, 0, 1.2], "radius": 0.4, "material": "glass"},
   {"type": "box", "min": [-1, -1, -0.5], "max": [1, 1, 0], "material": "milk"}]}
J

# --time 1 bounds the whole run, photon pass included (generous margin for
# the shared machine: start-up is ~0.3 s).
t0=$(date +%s.%N)
expect_exit 0 "--time 1 with 1e9 caustic photons" -- timeout 60 "$SOAK" render "$D/caustic.json" --time 1 -o "$D/out/t.exr"
t1=$(date +%s.%N)
secs=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }')
awk -v s="$secs" 'BEGIN { exit !(s < 10) }' && ok "--time 1 run took $secs s" || bad "--time 1 run took $secs s"
grep -q "stopped early" "$SOAK_TMP/last.out" && ok "reports the early stop" || bad "no early stop reported"

# Ctrl-C during the photon pass: exit 130 promptly, the partial image kept.
"$SOAK" render "$D/caustic.json" -o "$D/out/i.exr" >/dev/null 2>"$D/int.err" &
pid=$! # soak itself, not a `timeout` wrapper: the signal must reach soak (ctest's TIMEOUT bounds a hang)
# Wait for soak render's SIGINT handler (SigCgt bit 2), i.e. past start-up
# and scene loading (slow under sanitizers), then into the photon pass.
for _ in $(seq 1 600); do
    cgt=$(awk '/^SigCgt/ { print $2 }' /proc/$pid/status 2>/dev/null)
    [ -n "$cgt" ] && (( 0x$cgt & 2 )) && break
    sleep 0.05
done
sleep 0.5
t0=$(date +%s.%N)
kill -INT $pid
wait $pid
rc=$?
t1=$(date +%s.%N)
secs=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }')
[ $rc = 130 ] && ok "SIGINT in the photon pass: exit 130" || bad "SIGINT in the photon pass: exit $rc $(cat "$D/int.err")"
awk -v s="$secs" 'BEGIN { exit !(s < 10) }' && ok "stopped $secs s after SIGINT" || bad "stopped $secs s after SIGINT"
[ -s "$D/out/i.exr" ] && ok "the partial render was written" || bad "no partial render"

# Kill a bake at many moments, most of them in the last quarter of the run
# where the EXR is encoded and written (a probe run measures its length):
# the folder only ever holds the previous output or the complete new one.
"$SOAK" bake turbulence --width 2048 --height 2048 --seed 1 -o "$D/out/big.exr" 2>/dev/null
t0=$(date +%s.%N)
"$SOAK" bake turbulence --width 2048 --height 2048 --seed 3 -o "$D/out/big.exr" 2>/dev/null
t1=$(date +%s.%N)
left=0
for sig in INT KILL; do
    for frac in 0.5 0.78 0.85 0.92 0.97; do
        delay=$(awk -v a="$t0" -v b="$t1" -v f="$frac" 'BEGIN { printf "%.2f", f * (b - a) }')
        "$SOAK" bake turbulence --width 2048 --height 2048 --seed 2 -o "$D/out/big.exr" 2>/dev/null &
        pid=$!
        sleep "$delay"
        kill -$sig $pid 2>/dev/null
        wait $pid 2>/dev/null
        extra=$(ls -A "$D/out" | grep -v -x -e big.exr -e t.exr -e i.exr)
        if [ -n "$extra" ]; then left=1; bad "SIG$sig after $delay s left: $extra"; (cd "$D/out" && rm -f $extra); fi
        iinfo "$D/out/big.exr" >/dev/null 2>&1 || bad "SIG$sig after $delay s: big.exr unreadable"
    done
done
[ $left = 0 ] && ok "no temporary after 10 interrupts and kills"

finish
