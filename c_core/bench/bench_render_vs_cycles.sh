#!/bin/bash
# Benchmark (not a test): `soak render` vs Blender Cycles on the same wet scene
# (scenes/bench_wet_sphere.json: a wet sphere with a scattering interior on a wet
# ground plane, one sun, constant sky), CPU, same image size and thread count, no
# denoising. Same geometry: the sphere is Blender's 192x96 UV-sphere mesh for both
# (cycles_render_scene.py --export-sphere writes it; soak loads it as a mesh object,
# so its walk queries the BVH instead of the analytic sphere). Each renderer is compared with its OWN long converged
# reference (the materials are equivalent, not identical: see
# cycles_render_scene.py), then renders at increasing spp give time vs RMSE, and the
# time to reach RMSE = TARGET x mean reference pixel value is interpolated for both.
# Prints a Markdown report (table, target, times, ratio soak/Cycles, soak rays/s and
# paths/s); also writes it to out/bench/render_vs_cycles.md when out/bench exists
# (c_core/bench/run.sh creates it and runs this from the repository root).
#
# Times, the render call for both, as CPU time (user + system of every thread: on a
# shared machine wall time counts other jobs' turns): soak = the `cpu:` it prints
# (soak_render: the path tracing; scene parse, mesh load and BVH build come before
# it); Cycles = time.process_time() around bpy.ops.render.render (scene sync, BVH
# build, path tracing). Wall times are kept and their ratio printed too. Start-ups
# are reported separately. Runs are interleaved by rounds: soak renders every spp,
# then a Blender session renders every spp (after an untimed warm-up render), the
# order swapped every other round, REPEAT times; the minimum over the rounds decides
# (the median's ratio is printed beside it). Sun units are checked first: a white
# Lambert plane under the scene's sun alone, rendered by both, must give E cos/pi;
# Cycles' sun strength is scaled by the measured soak/Cycles ratio (1 when both agree).
# The machine may be shared: the load average is printed with the results.
#
# usage: bench_render_vs_cycles.sh [BUILD_DIR] [REF_SPP] [SPP_LIST] [THREADS] [TARGET]
#   defaults: build 2048 "4 8 16 32 64 128 256 512 1024" 2 0.02      (soak = BUILD_DIR/bin/soak)
#   BENCH_REPEAT=N times every run N times, interleaved (min and median; default 3).
#   BENCH_KEEP=1 keeps the renders (the folder is named on stderr).
#   BENCH_SCENE=FILE benchmarks another scene (default scenes/bench_wet_sphere.json); the
#   three of the benchmark (issue 38): bench_wet_sphere.json, bench_wet_paper.json (a
#   back-lit wet sheet: subsurface box), bench_wet_puddles.json (a wet quad with a
#   puddle map, scenes/bench_puddles.png). bench_render_scenes.sh runs all three.
# Takes about 5-6 minutes on 2 cores with 3 repeats.
set -eu
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
SOAK="${1:-build}/bin/soak"
REF_SPP="${2:-2048}"
SPPS="${3:-4 8 16 32 64 128 256 512 1024}"
THREADS="${4:-2}"
TARGET="${5:-0.02}"
REPEAT="${BENCH_REPEAT:-3}"
case "$REPEAT" in '' | *[!0-9]* | 0) echo "BENCH_REPEAT must be a positive integer"; exit 1 ;; esac
SCENE_SRC="${BENCH_SCENE:-$ROOT/scenes/bench_wet_sphere.json}"
[ -f "$SCENE_SRC" ] || { echo "no scene $SCENE_SRC"; exit 1; }
PY=/usr/bin/python3
REF_SEED=1000 # references use another seed than the runs: independent noise
RUN_SEED=1

[ -x "$SOAK" ] || { echo "soak not found at $SOAK (give the build dir as \$1)"; exit 1; }
command -v blender >/dev/null || { echo "blender not on PATH"; exit 1; }
command -v oiiotool >/dev/null || { echo "oiiotool not on PATH"; exit 1; }
"$PY" -c "import numpy" 2>/dev/null || { echo "$PY has no numpy"; exit 1; }
MD=""
[ -d out/bench ] && MD="out/bench/render_vs_cycles.md"
W="$(mktemp -d)"
if [ -n "${BENCH_KEEP:-}" ]; then echo "keeping the renders in $W" >&2; else trap 'rm -rf "$W"' EXIT; fi
SCENE="$W/scene.json" # Cycles reads this copy (beside its maps); soak its mesh copy (below)
cp "$SCENE_SRC" "$SCENE"
if grep -q '"bench_puddles.png"' "$SCENE"; then cp "$(dirname "$SCENE_SRC")/bench_puddles.png" "$W/"; fi
now() { date +%s.%N; }
blend() { blender -b --factory-startup --python-exit-code 1 --python "$HERE/cycles_render_scene.py" -- "$@"; }
avg_r() { oiiotool "$1" --printstats 2>/dev/null | sed -n 's/.*Stats Avg: *\([0-9.eE+-]*\).*/\1/p' | head -1; }

# --- 1. sun units: white Lambert plane, sun only, seen from above ---------------
"$PY" - "$SCENE" "$W/cal.json" <<'EOF'
import json, sys
sc = json.load(open(sys.argv[1]))
sun = dict(sc["lights"][0])
# Units only: a sun from below (a back-lit sheet) is mirrored above the plane.
sun["direction"] = [sun["direction"][0], sun["direction"][1], abs(sun["direction"][2])]
json.dump({"render": {"width": 32, "height": 24},
           "camera": {"position": [0, 0, 10], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 5},
           "lights": [sun],
           "materials": {"white": {"type": "lambert", "albedo": 1}},
           "objects": [{"type": "plane", "center": [0, 0, 0], "normal": [0, 0, 1], "size": [100, 100],
                        "material": "white"}]}, open(sys.argv[2], "w"))
EOF
"$SOAK" render "$W/cal.json" -o "$W/soak_cal.exr" --spp 16 --threads "$THREADS" -q
blend --calibrate "$SCENE" "$W/cycles_cal.exr" "$THREADS" >"$W/blender_cal.log" 2>&1 ||
    { cat "$W/blender_cal.log"; exit 1; }
soak_cal=$(avg_r "$W/soak_cal.exr")
cycles_cal=$(avg_r "$W/cycles_cal.exr")
expected=$("$PY" -c "
import json, math, sys
s = json.load(open('$SCENE'))['lights'][0]
d, e = s['direction'], s['irradiance']
e = e[0] if isinstance(e, list) else e
print('%.6f' % (e * abs(d[2]) / math.sqrt(sum(x * x for x in d)) / math.pi))")
SUN_SCALE=$(echo "$soak_cal / $cycles_cal" | bc -l)

# --- 1b. same geometry: soak traces Blender's UV sphere -------------------------
blend --export-sphere "$W/uvsphere.obj" >"$W/blender_sphere.log" 2>&1 || { cat "$W/blender_sphere.log"; exit 1; }
sphere_info=$(sed -n 's/^CYCLES_SPHERE //p' "$W/blender_sphere.log")
"$PY" - "$SCENE" "$W/scene_mesh.json" <<'EOF'
import json, sys
sc = json.load(open(sys.argv[1]))
for o in sc["objects"]:
    if o["type"] == "sphere":
        c, r = o.pop("center"), o.pop("radius")
        o.update({"type": "mesh", "file": "uvsphere.obj", "translate": c, "scale": r})
json.dump(sc, open(sys.argv[2], "w"), indent=1)
EOF
SOAK_SCENE="$W/scene_mesh.json"

# --- 2. soak: reference -----------------------------------------------------------
# times.tsv: one line per timed render of every round: renderer kind spp wall_s cpu_s image
: >"$W/times.tsv"
soak_startup=1000000
for _ in 1 2 3; do
    t0=$(now)
    "$SOAK" render --help >/dev/null
    t1=$(now)
    soak_startup=$(echo "t = $t1 - $t0; if (t < $soak_startup) t else $soak_startup" | bc -l)
done
soak_run() { # kind spp seed out -> appends to times.tsv, keeps stdout in out.log
    "$SOAK" render "$SOAK_SCENE" -o "$4" --spp "$2" --seed "$3" --threads "$THREADS" >"$4.log"
    printf 'soak\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$(sed -n 's/^time: \([0-9.]*\) s.*/\1/p' "$4.log")" \
        "$(sed -n 's/^cpu: \([0-9.]*\) s.*/\1/p' "$4.log")" "$4" >>"$W/times.tsv"
}
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
soak_run ref "$REF_SPP" "$REF_SEED" "$W/soak_ref.exr"
soak_paths_s=$(sed -n 's/^paths: .*(\([0-9]*\) paths\/s).*/\1/p' "$W/soak_ref.exr.log")
soak_rays_s=$(sed -n 's/^rays: .*(\([0-9]*\) rays\/s).*/\1/p' "$W/soak_ref.exr.log")
soak_rays=$(sed -n 's/^rays: \([0-9]*\) .*/\1/p' "$W/soak_ref.exr.log")
soak_paths=$(sed -n 's/^paths: \([0-9]*\) .*/\1/p' "$W/soak_ref.exr.log")
soak_inner=$(sed -n 's/^time: \([0-9.]*\) s.*/\1/p' "$W/soak_ref.exr.log")
soak_inner_cpu=$(sed -n 's/^cpu: \([0-9.]*\) s.*/\1/p' "$W/soak_ref.exr.log")

# --- 3. Cycles reference, then the rounds, interleaved ----------------------------
# Odd rounds run soak first, even rounds Cycles first: a drift of the load over the
# run falls on both alike.
cycles_session() { # name jobs... -> appends its CYCLES_RENDER lines to times.tsv
    local name=$1 kind spp seed wall cpu
    shift
    # shellcheck disable=SC2068
    blend "$SCENE" "$W" "$THREADS" "$SUN_SCALE" 1:0 $@ >"$W/blender_$name.log" 2>&1 || { cat "$W/blender_$name.log"; exit 1; }
    while read -r _ spp seed wall cpu; do
        kind=run
        [ "$seed" = "$REF_SEED" ] && kind=ref
        printf 'Cycles\t%s\t%s\t%s\t%s\t%s\n' "$kind" "$spp" "$wall" "$cpu" "$W/cycles_${spp}_${seed}.exr" >>"$W/times.tsv"
    done < <(grep '^CYCLES_RENDER ' "$W/blender_$name.log")
}
t_launch=$(now)
cycles_session ref "$REF_SPP:$REF_SEED"
t_exit=$(now)
t_start=$(sed -n 's/^CYCLES_SCRIPT_START //p' "$W/blender_ref.log")
blender_startup=$(echo "$t_start - $t_launch" | bc -l)
blender_total=$(echo "$t_exit - $t_launch" | bc -l)
soak_round() { for spp in $SPPS; do soak_run run "$spp" "$RUN_SEED" "$W/soak_$spp.exr"; done; }
cycles_round() {
    local jobs="" spp
    for spp in $SPPS; do jobs="$jobs $spp:$RUN_SEED"; done
    # shellcheck disable=SC2086
    cycles_session "round$1" $jobs
}
for round in $(seq "$REPEAT"); do
    if [ $((round % 2)) = 1 ]; then
        soak_round
        cycles_round "$round"
    else
        cycles_round "$round"
        soak_round
    fi
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
"$PY" "$HERE/render_times.py" "$W" "$SPPS"

# --- 4. report ------------------------------------------------------------------
{
    echo "# soak render vs Blender Cycles $(blender -b --factory-startup -noaudio --version 2>/dev/null | head -1 | sed 's/Blender //')"
    echo
    echo "Scene \`$(basename "$SCENE_SRC")\`, $(sed -n 's/.*"width": *\([0-9]*\), *"height": *\([0-9]*\).*/\1x\2/p' "$SCENE" | head -1)," \
        "$THREADS threads, CPU, no denoising, one run; RMSE over RGB against each renderer's own" \
        "$REF_SPP-spp reference (seed $REF_SEED; runs seed $RUN_SEED)."
    echo "Same geometry: a sphere is Blender's UV-sphere mesh ($sphere_info) in both renderers." \
        "Times are the **CPU time** (user + system, all threads) of the render call for both: soak's printed \`cpu:\` (path tracing)," \
        "Cycles' \`time.process_time()\` around \`bpy.ops.render.render\` (sync, BVH, path tracing)." \
        "$REPEAT rounds, interleaved (soak all spp, then a Blender session all spp after an untimed warm-up; the order swapped every other round);" \
        "the table and the fit use the **minimum** over the rounds per spp; the ratios from the median and from wall times follow it (references: one render each)."
    echo
    printf -- "- sun units (red channel): white Lambert plane, expected E cos/pi = %s; soak %s, Cycles %s -> Cycles sun strength scale %.4f\n" \
        "$expected" "$soak_cal" "$cycles_cal" "$SUN_SCALE"
    printf -- "- soak reference run: %s paths, %s rays; **%s paths/s, %s rays/s** (%s s wall, %s s CPU inside the render loop, %s threads)\n" \
        "$soak_paths" "$soak_rays" "$soak_paths_s" "$soak_rays_s" "$soak_inner" "$soak_inner_cpu" "$THREADS"
    printf -- "- start-up: soak %.2f s (\`soak render --help\`: shared-library loading); Blender %.2f s (launch to script start); whole Blender process %.1f s\n" \
        "$soak_startup" "$blender_startup" "$blender_total"
    echo "- load average before / after: $load_before / $load_after (machine shared with other jobs)"
} | "$PY" "$HERE/render_convergence.py" "$W/runs_cpu_min.tsv" "$TARGET" ${MD:+"$MD"}
for v in cpu_median wall_min wall_median; do
    ratio=$("$PY" "$HERE/render_convergence.py" "$W/runs_$v.tsv" "$TARGET" </dev/null |
        sed -n 's/^- \*\*time-to-target ratio soak \/ Cycles: \([0-9.a-z]*\)\*\* = \(.*\)$/\1 (\2)/p')
    echo "- time-to-target ratio soak / Cycles from the ${v/_/ } times: $ratio"
done
echo "- every timed render (renderer, kind, spp, wall s, CPU s):"
echo
cut -f1-5 "$W/times.tsv" | tr '\t' ' ' | sed 's/^/    /'
