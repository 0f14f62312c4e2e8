#!/bin/bash
# libFuzzer runs of the targets in tests/fuzz.
#   run.sh BUILD_DIR SECONDS_PER_TARGET [targets...]
#     long runs (make fuzz): every target for SECONDS each, starting from the
#     checked-in corpus; new inputs go to BUILD/fuzz/corpus/<target>,
#     crashes/hangs to BUILD/fuzz/artifacts/<target>. Summary lines
#     (executions, coverage, findings) are printed at the end and kept in
#     BUILD/fuzz/summary.txt.
#   run.sh --short BUILD_DIR SECONDS TARGET
#     one time-boxed run for ctest (fuzz_run_<target>): a fresh copy of the
#     corpus and reproducers in BUILD/fuzz-short/<target>; exit 1 on a finding
#     (the input is printed in hex; copy it into reproducers/<target>/ once
#     fixed), 0 otherwise, with the same summary line.
set -u
short=0
[ "${1:-}" = --short ] && { short=1; shift; }
B=${1:?build dir}
SECS=${2:-900}
shift 2 || true
TARGETS=${*:-scene preset image mesh volume export}
HERE=$(cd "$(dirname "$0")" && pwd)
# A unit (one input) slower than this is reported as a hang. 60 s, not 10: at
# nice 10 on a loaded machine a starved fuzzer has stalled 46-66 s on inputs
# that take 0.5 s alone (tests/fuzz/README.md, runs of 2026-11-27).
# libFuzzer also saves a "slow unit" artifact past 10 s by default; the same
# limit applies (a 1-byte image input was saved at load 10, 2026-11-29).
UNIT_TIMEOUT=${SOAK_FUZZ_UNIT_TIMEOUT:-60}
OUT="$B/fuzz"
[ $short = 1 ] && OUT="$B/fuzz-short"
mkdir -p "$OUT"
[ $short = 1 ] || : >"$OUT/summary.txt"
status=0
for t in $TARGETS; do
    exe="$B/tests/fuzz/fuzz_$t"
    [ -x "$exe" ] || { echo "run.sh: $exe missing (configure with CC=clang CXX=clang++ -DSOAK_FUZZ=ON)"; exit 1; }
    [ $short = 1 ] && rm -rf "$OUT/corpus/$t" "$OUT/artifacts/$t"
    mkdir -p "$OUT/corpus/$t" "$OUT/artifacts/$t"
    cp -n "$HERE/corpus/$t/"* "$OUT/corpus/$t/" 2>/dev/null
    [ $short = 1 ] && [ -d "$HERE/reproducers/$t" ] && cp -n "$HERE/reproducers/$t/"* "$OUT/corpus/$t/" 2>/dev/null
    extra=()
    [ -f "$HERE/$t.dict" ] && extra+=(-dict="$HERE/$t.dict")
    # Assimp's own crashes and hangs are known and contained at run time
    # (mesh_contain.c): keep fuzzing past them and count the artifacts.
    [ "$t" = mesh ] && extra+=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
    ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 \
        LSAN_OPTIONS=suppressions=$HERE/../lsan.supp:fast_unwind_on_malloc=0 \
        nice -n 10 "$exe" "$OUT/corpus/$t" -max_total_time="$SECS" -timeout="$UNIT_TIMEOUT" -report_slow_units="$UNIT_TIMEOUT" -rss_limit_mb=3072 \
        -artifact_prefix="$OUT/artifacts/$t/" -print_final_stats=1 "${extra[@]}" >"$OUT/$t.log" 2>&1
    rc=$?
    execs=$(grep -E "stat::number_of_executed_units" "$OUT/$t.log" | tail -1 | awk '{ print $2 }')
    [ -z "$execs" ] && execs=$(grep -oE "^#[0-9]+" "$OUT/$t.log" | tail -1 | tr -d '#')
    cov=$(grep -oE "cov: [0-9]+ ft: [0-9]+" "$OUT/$t.log" | tail -1)
    n_art=$(ls "$OUT/artifacts/$t" | wc -l)
    line="$t: exit $rc, ${SECS} s, ${execs:-?} executions, ${cov:-cov: ? ft: ?}, corpus $(ls "$OUT/corpus/$t" | wc -l), artifacts $n_art"
    echo "$line"
    [ $short = 1 ] || echo "$line" >>"$OUT/summary.txt"
    if [ $short = 1 ] && { [ $rc -ne 0 ] || { [ "$t" != mesh ] && [ "$n_art" -gt 0 ]; }; }; then
        status=1
        grep -E "ERROR|SUMMARY|abort|fuzz:" "$OUT/$t.log" | head -20
        for a in "$OUT/artifacts/$t"/*; do
            [ -f "$a" ] || continue
            echo "finding $a ($(stat -c %s "$a") bytes):"
            od -An -tx1 "$a" | head -20
        done
    fi
done
exit $status
