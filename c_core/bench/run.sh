#!/usr/bin/env bash
# Runs every benchmark once and collects the tables in out/bench/.
# Usage: c_core/bench/run.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
mkdir -p out/bench
echo "== models: speed vs error (one core)"
"$build/bench/bench_models" out/bench/models.md
for b in "$build"/bench/bench_*; do
  case "$(basename "$b")" in bench_models) continue ;; esac
  [ -x "$b" ] || continue
  echo "== $(basename "$b")"
  "$b" | tee "out/bench/$(basename "$b").txt"
done
for s in c_core/bench/*.sh; do
  case "$(basename "$s")" in run.sh) continue ;; esac
  echo "== $(basename "$s")"
  bash "$s" "$build" | tee "out/bench/$(basename "$s" .sh).txt"
done
