#!/usr/bin/env bash
# Start-up cost of `soak` before and after the I/O modules (soak/plugin.h):
# whole-process wall time (hyperfine, min and median), CPU time, peak RSS and
# the number of shared objects, for two commands that touch no image (eval,
# albedo) and one that writes a PNG (bake turbulence, 64x64, 1 octave).
#
# Usage: c_core/bench/bench_startup.sh [BUILD_DIR] [BEFORE_COMMIT]
#   BUILD_DIR      the build to measure ("after"; default build)
#   BEFORE_COMMIT  the "before" version (default 83b1b68, the last commit that
#                  linked OpenImageIO, OpenVDB and Assimp into soak); built
#                  once from `git archive` into BUILD_DIR/startup-before/.
#   SOAK_BEFORE=path/to/soak uses that binary instead of building one.
#   ROUNDS (default 5) x RUNS (default 10): the two versions alternate
#   round by round (one hyperfine call per command and round, both versions
#   in it), so load on the shared machine falls on both.
# Prints a Markdown report on stdout. Needs hyperfine (scripts/install-deps.sh).
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-build}" && pwd)
before_commit=${2:-83b1b68}
rounds=${ROUNDS:-5}
runs=${RUNS:-10}
after="$build/bin/soak"
command -v hyperfine > /dev/null || { echo "bench_startup: hyperfine not on PATH (scripts/install-deps.sh installs it)" >&2; exit 1; }
[ -x "$after" ] || { echo "bench_startup: no $after (build it first)" >&2; exit 1; }

before=${SOAK_BEFORE:-}
if [ -z "$before" ]; then
  full=$(git -C "$repo" rev-parse --verify "$before_commit^{commit}")
  dir="$build/startup-before/${full:0:12}"
  before="$dir/build/bin/soak"
  if [ ! -x "$before" ]; then
    echo "bench_startup: building $before_commit in $dir (once)" >&2
    rm -rf "$dir" && mkdir -p "$dir/src"
    git -C "$repo" archive "$full" | tar -x -C "$dir/src"
    cmake -S "$dir/src" -B "$dir/build" -DCMAKE_BUILD_TYPE=Release > "$dir/configure.log"
    cmake --build "$dir/build" -j2 --target soak_cli > "$dir/build.log"
  fi
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
names=(eval albedo image)
args_eval=(eval --model ww --theta-i 20 --theta-o 65 --phi 150)
args_albedo=(albedo --material sand --wetness 1)
args_image=(bake turbulence --width 64 --height 64 --octaves 1 -o "$tmp/t.png")

args_of() { local v="args_$1[@]"; printf '%q ' "${!v}"; }

# Wall times: hyperfine rounds, before and after alternating.
for r in $(seq "$rounds"); do
  for n in "${names[@]}"; do
    hyperfine -N --style none --warmup 2 --runs "$runs" --export-json "$tmp/$n.$r.json" \
      -n before "$before $(args_of "$n")" -n after "$after $(args_of "$n")" > /dev/null
  done
done

# Peak RSS (/usr/bin/time), objects the loader initialised (LD_DEBUG=libs,
# dlopen'ed modules included) and what ldd lists for the binary.
probe() { # probe VERSION NAME -> "rss_kb objects"
  local bin=$1 n=$2 v="args_$2[@]"
  /usr/bin/time -f %M -o "$tmp/rss" "$bin" "${!v}" > /dev/null 2>&1
  LD_DEBUG=libs LD_DEBUG_OUTPUT="$tmp/ld" "$bin" "${!v}" > /dev/null 2>&1
  echo "$(cat "$tmp/rss") $(cat "$tmp/ld".* | grep -c 'calling init:')"
  rm -f "$tmp/ld".*
}
for n in "${names[@]}"; do
  echo "$n before $(probe "$before" "$n")" >> "$tmp/probe"
  echo "$n after $(probe "$after" "$n")" >> "$tmp/probe"
done

/usr/bin/python3 - "$tmp" "$rounds" "$before" "$after" "$(ldd "$before" | wc -l)" "$(ldd "$after" | wc -l)" \
  "$before_commit" "${names[@]}" <<'EOF'
import json, statistics, sys
tmp, rounds, before, after, ldd_b, ldd_a, commit = sys.argv[1:8]
names = sys.argv[8:]
probe = {}
for line in open(f"{tmp}/probe"):
    n, v, rss, objs = line.split()
    probe[(n, v)] = (int(rss), int(objs))
print(f"before: `{before}` ({commit}); after: `{after}`")
print(f"ldd lists {ldd_b} shared objects for before, {ldd_a} for after.\n")
print("| command | version | runs | wall min ms | wall median ms | CPU (user+sys) mean ms | peak RSS MB | shared objects loaded |")
print("|---|---|---|---|---|---|---|---|")
for n in names:
    for v in ("before", "after"):
        times, cpu = [], []
        for r in range(1, int(rounds) + 1):
            for res in json.load(open(f"{tmp}/{n}.{r}.json"))["results"]:
                if res["command"] == v:
                    times += res["times"]
                    cpu.append(res["user"] + res["system"])
        rss, objs = probe[(n, v)]
        print(f"| {n} | {v} | {len(times)} | {1e3 * min(times):.1f} | {1e3 * statistics.median(times):.1f} | "
              f"{1e3 * statistics.mean(cpu):.1f} | {rss / 1024:.1f} | {objs} |")
EOF
