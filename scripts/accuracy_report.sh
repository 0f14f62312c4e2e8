#!/usr/bin/env bash
# Regenerates docs/ACCURACY.md, docs/accuracy/report.json and the Pareto plots:
#   scripts/accuracy_report.sh [path/to/soak]     (run from anywhere)
# 1. instructions per evaluation of each model: scripts/accuracy_callgrind.c
#    (built here against the build's libsoak_models.a and libsoak_core.a)
#    under valgrind --tool=callgrind, run with 0 and N evaluations (the
#    difference over N leaves set-up and start-up out). `soak report
#    --cost-only` does the same through the scene path, but the soak binary
#    loads OpenImageIO, whose libhwy start-up valgrind 3.19 cannot run;
# 2. `soak report` with those counts beside its timings;
# 3. scripts/plot_accuracy.py draws the plots.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
soak=${1:-$root/build/bin/soak}
[ -x "$soak" ] || { echo "accuracy_report: no soak binary at $soak (pass its path)" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "accuracy_report: valgrind not on PATH" >&2; exit 2; }
[ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import matplotlib' 2>/dev/null ||
  { echo "accuracy_report: /usr/bin/python3 with matplotlib missing (scripts/install-deps.sh)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
n=20000
lib=$(cd "$(dirname "$soak")/../c_core" && pwd)
cc -std=c11 -O2 -I"$root/c_core/models/include" -I"$root/c_core/core/include" "$root/scripts/accuracy_callgrind.c" \
  "$lib/libsoak_models.a" "$lib/libsoak_core.a" -lm -o "$tmp/accuracy_callgrind"
ir_of() { # model evals -> total instructions
  valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" "$tmp/accuracy_callgrind" "$1" "$2" \
    > /dev/null 2> "$tmp/cg.err" || { echo "  $1: $(grep -v '^==' "$tmp/cg.err" | head -c 300)" >&2; return 1; }
  awk '/^summary:|^totals:/ { print $2; exit }' "$tmp/cg.out"
}
: > "$tmp/callgrind.tsv"
for model in full $("$soak" eval --list | awk 'NF && $1 !~ /^#/ { print $1 }'); do
  a=$(ir_of "$model" 0) || continue
  b=$(ir_of "$model" "$n") || continue
  ir=$(awk -v a="$a" -v b="$b" -v n="$n" 'BEGIN { printf "%.0f", (b - a) / n }')
  echo "  $model: $ir instructions per eval"
  printf '%s\t%s\n' "$model" "$ir" >> "$tmp/callgrind.tsv"
done
mkdir -p "$root/docs/accuracy"
cp "$tmp/callgrind.tsv" "$root/docs/accuracy/callgrind.tsv.tmp" && mv "$root/docs/accuracy/callgrind.tsv.tmp" "$root/docs/accuracy/callgrind.tsv"
(cd "$root" && "$soak" report --callgrind docs/accuracy/callgrind.tsv)
/usr/bin/python3 "$root/scripts/plot_accuracy.py" "$root/docs/accuracy/report.json" "$root/docs/accuracy"
echo "accuracy_report: docs/ACCURACY.md, docs/accuracy/{report.json,callgrind.tsv,pareto*.png}"
