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
# Times, the render call for both: soak = the `time:` it prints (soak_render: the
# path tracing; scene parse, mesh load and BVH build come before it); Cycles = the
# bpy.ops.render.render call (scene sync, BVH build, path tracing). Start-ups are
# reported separately. Runs are interleaved by rounds: soak renders every spp, then a
# Blender session renders every spp (after an untimed warm-up render), REPEAT times;
# the fastest of the repeats is kept for each. Sun units are checked first: a white
# Lambert plane under the scene's sun alone, rendered by both, must give E cos/pi;
# Cycles' sun strength is scaled by the measured soak/Cycles ratio (1 when both agree).
# The machine may be shared: the load average is printed with the results.
#
# usage: bench_render_vs_cycles.sh [BUILD_DIR] [REF_SPP] [SPP_LIST] [THREADS] [TARGET]
#   defaults: build 2048 "4 8 16 32 64 128 256 512 1024" 2 0.02      (soak = BUILD_DIR/bin/soak)
#   BENCH_REPEAT=N times every run N times, interleaved, and keeps the fastest (default 3).
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

# --- 2. soak: reference, then the runs ----------------------------------------
: >"$W/runs.tsv"
soak_startup=1000000
for _ in 1 2 3; do
    t0=$(now)
    "$SOAK" render --help >/dev/null
    t1=$(now)
    soak_startup=$(echo "t = $t1 - $t0; if (t < $soak_startup) t else $soak_startup" | bc -l)
done
soak_run() { # spp seed out -> prints the render call's seconds, keeps stdout in out.log
    "$SOAK" render "$SOAK_SCENE" -o "$3" --spp "$1" --seed "$2" --threads "$THREADS" >"$3.log"
    sed -n 's/^time: \([0-9.]*\) s.*/\1/p' "$3.log"
}
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
secs=$(soak_run "$REF_SPP" "$REF_SEED" "$W/soak_ref.exr")
printf 'soak\tref\t%s\t%s\t%s\n' "$REF_SPP" "$secs" "$W/soak_ref.exr" >>"$W/runs.tsv"
soak_paths_s=$(sed -n 's/^paths: .*(\([0-9]*\) paths\/s).*/\1/p' "$W/soak_ref.exr.log")
soak_rays_s=$(sed -n 's/^rays: .*(\([0-9]*\) rays\/s).*/\1/p' "$W/soak_ref.exr.log")
soak_rays=$(sed -n 's/^rays: \([0-9]*\) .*/\1/p' "$W/soak_ref.exr.log")
soak_paths=$(sed -n 's/^paths: \([0-9]*\) .*/\1/p' "$W/soak_ref.exr.log")
soak_inner=$(sed -n 's/^time: \([0-9.]*\) s.*/\1/p' "$W/soak_ref.exr.log")

# --- 3. Cycles reference, then the rounds: soak, Cycles, soak, Cycles, ... -------
cycles_session() { # name jobs... -> appends CYCLES_RENDER lines to blender.log
    local name=$1; shift
    # shellcheck disable=SC2068
    blend "$SCENE" "$W" "$THREADS" "$SUN_SCALE" 1:0 $@ >"$W/blender_$name.log" 2>&1 || { cat "$W/blender_$name.log"; exit 1; }
    cat "$W/blender_$name.log" >>"$W/blender.log"
}
: >"$W/blender.log"
t_launch=$(now)
cycles_session ref "$REF_SPP:$REF_SEED"
t_exit=$(now)
t_start=$(sed -n 's/^CYCLES_SCRIPT_START //p' "$W/blender_ref.log")
blender_startup=$(echo "$t_start - $t_launch" | bc -l)
blender_total=$(echo "$t_exit - $t_launch" | bc -l)
declare -A best
for round in $(seq "$REPEAT"); do
    for spp in $SPPS; do
        secs=$(soak_run "$spp" "$RUN_SEED" "$W/soak_$spp.exr")
        best[$spp]=$(echo "v = $secs; w = ${best[$spp]:-1000000000}; if (v < w) v else w" | bc -l)
    done
    jobs=""
    for spp in $SPPS; do jobs="$jobs $spp:$RUN_SEED"; done
    # shellcheck disable=SC2086
    cycles_session "round$round" $jobs
done
for spp in $SPPS; do
    printf 'soak\trun\t%s\t%s\t%s\n' "$spp" "${best[$spp]}" "$W/soak_$spp.exr" >>"$W/runs.tsv"
done
declare -A cbest
while read -r _ spp seed secs; do
    if [ "$seed" = "$REF_SEED" ]; then
        printf 'Cycles\tref\t%s\t%s\t%s\n' "$spp" "$secs" "$W/cycles_${spp}_${seed}.exr" >>"$W/runs.tsv"
    else
        cbest[$spp]=$(echo "v = $secs; w = ${cbest[$spp]:-1000000000}; if (v < w) v else w" | bc -l)
    fi
done < <(grep '^CYCLES_RENDER ' "$W/blender.log")
for spp in $SPPS; do
    [ -n "${cbest[$spp]:-}" ] || { echo "Cycles rendered no $spp-spp image"; exit 1; }
    printf 'Cycles\trun\t%s\t%s\t%s\n' "$spp" "${cbest[$spp]}" "$W/cycles_${spp}_${RUN_SEED}.exr" >>"$W/runs.tsv"
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

# --- 4. report ------------------------------------------------------------------
{
    echo "# soak render vs Blender Cycles $(blender -b --factory-startup -noaudio --version 2>/dev/null | head -1 | sed 's/Blender //')"
    echo
    echo "Scene \`$(basename "$SCENE_SRC")\`, $(sed -n 's/.*"width": *\([0-9]*\), *"height": *\([0-9]*\).*/\1x\2/p' "$SCENE" | head -1)," \
        "$THREADS threads, CPU, no denoising, one run; RMSE over RGB against each renderer's own" \
        "$REF_SPP-spp reference (seed $REF_SEED; runs seed $RUN_SEED)."
    echo "Same geometry: a sphere is Blender's UV-sphere mesh ($sphere_info) in both renderers." \
        "Times are the render call for both: soak's printed \`time:\` (path tracing), Cycles' \`bpy.ops.render.render\` (sync, BVH, path tracing);" \
        "runs interleaved by rounds (soak all spp, then a Blender session all spp after an untimed warm-up), each the fastest of $REPEAT rounds (references: one render each)."
    echo
    printf -- "- sun units (red channel): white Lambert plane, expected E cos/pi = %s; soak %s, Cycles %s -> Cycles sun strength scale %.4f\n" \
        "$expected" "$soak_cal" "$cycles_cal" "$SUN_SCALE"
    printf -- "- soak reference run: %s paths, %s rays; **%s paths/s, %s rays/s** (%s s inside the render loop, %s threads)\n" \
        "$soak_paths" "$soak_rays" "$soak_paths_s" "$soak_rays_s" "$soak_inner" "$THREADS"
    printf -- "- start-up: soak %.2f s (\`soak render --help\`: shared-library loading); Blender %.2f s (launch to script start); whole Blender process %.1f s\n" \
        "$soak_startup" "$blender_startup" "$blender_total"
    echo "- load average before / after: $load_before / $load_after (machine shared with other jobs)"
} | "$PY" "$HERE/render_convergence.py" "$W/runs.tsv" "$TARGET" ${MD:+"$MD"}
