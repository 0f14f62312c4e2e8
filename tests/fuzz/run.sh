#!/bin/bash
# Long fuzzing runs (make fuzz): every target for SECONDS each, starting
# from the checked-in corpus; new inputs go to BUILD/fuzz/corpus/<target>,
# crashes/hangs to BUILD/fuzz/artifacts/<target>. Summary lines (executions,
# coverage, findings) are printed at the end and kept in BUILD/fuzz/summary.txt.
#   usage: run.sh BUILD_DIR SECONDS_PER_TARGET [targets...]
set -u
B=${1:?build dir}
SECS=${2:-900}
shift 2 || true
TARGETS=${*:-scene preset image mesh}
HERE=$(cd "$(dirname "$0")" && pwd)
OUT="$B/fuzz"
mkdir -p "$OUT"
: >"$OUT/summary.txt"
for t in $TARGETS; do
    exe="$B/tests/fuzz/fuzz_$t"
    [ -x "$exe" ] || { echo "run.sh: $exe missing (configure with CC=clang CXX=clang++ -DSOAK_FUZZ=ON)"; exit 1; }
    mkdir -p "$OUT/corpus/$t" "$OUT/artifacts/$t"
    cp -n "$HERE/corpus/$t/"* "$OUT/corpus/$t/" 2>/dev/null
    extra=()
    [ -f "$HERE/$t.dict" ] && extra+=(-dict="$HERE/$t.dict")
    # Assimp's own crashes and hangs are known and contained at run time
    # (mesh_contain.c): keep fuzzing past them and count the artifacts.
    [ "$t" = mesh ] && extra+=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
    ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 \
        LSAN_OPTIONS=suppressions=$HERE/../lsan.supp:fast_unwind_on_malloc=0 \
        nice -n 10 "$exe" "$OUT/corpus/$t" -max_total_time="$SECS" -timeout=10 -rss_limit_mb=3072 \
        -artifact_prefix="$OUT/artifacts/$t/" -print_final_stats=1 "${extra[@]}" >"$OUT/$t.log" 2>&1
    rc=$?
    execs=$(grep -E "stat::number_of_executed_units|#[0-9]+.*DONE" "$OUT/$t.log" | tail -1)
    cov=$(grep -oE "cov: [0-9]+ ft: [0-9]+" "$OUT/$t.log" | tail -1)
    n_art=$(ls "$OUT/artifacts/$t" | wc -l)
    echo "$t: exit $rc, ${execs:-?}, ${cov:-?}, corpus $(ls "$OUT/corpus/$t" | wc -l), artifacts $n_art" | tee -a "$OUT/summary.txt"
done
