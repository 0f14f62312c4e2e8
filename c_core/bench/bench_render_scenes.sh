#!/bin/bash
# Benchmark (not a test): the three-scene comparison of issue 38. Runs
# bench_render_vs_cycles.sh on scenes/bench_wet_sphere.json (a wet subsurface sphere),
# bench_wet_paper.json (a wet subsurface sheet lit from behind) and bench_wet_puddles.json
# (a wet plane with a puddle map under sun and sky), then render_scaling.py on each
# (CPU-time cost of 4x the pixels, paths per CPU second at 1 and 2 threads). Prints one
# Markdown report with the commit measured and the load average before and after. The
# ratios compare CPU time (user + system of every thread of the render call, both sides),
# which a shared machine inflates far less than wall time; the wall-time ratios are
# printed beside them.
#
# usage: bench_render_scenes.sh [BUILD_DIR] [REF_SPP] [SPP_LIST] [THREADS] [TARGET]
#   as bench_render_vs_cycles.sh (BENCH_REPEAT, BENCH_KEEP apply to each scene);
#   BENCH_SCENES="bench_wet_paper ..." runs a subset.
set -eu -o pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD="${1:-build}"
echo "# soak render vs Cycles on three scenes"
echo
echo "Commit $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo unknown)$(git -C "$ROOT" diff --quiet 2>/dev/null || echo ' (with local changes)'), $(date -u '+%Y-%m-%d %H:%M UTC'), load average before: $(cut -d' ' -f1-3 /proc/loadavg)."
for scene in ${BENCH_SCENES:-bench_wet_sphere bench_wet_paper bench_wet_puddles}; do
    echo
    echo "## $scene"
    echo
    BENCH_SCENE="$ROOT/scenes/$scene.json" bash "$HERE/bench_render_vs_cycles.sh" "$@" | sed 's/^# /### /'
    echo
    /usr/bin/python3 "$HERE/render_scaling.py" "$BUILD/bin/soak" "$ROOT/scenes/$scene.json" 32
done
echo
echo "Load average after: $(cut -d' ' -f1-3 /proc/loadavg)."
