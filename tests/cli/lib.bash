# Shared helpers for tests/cli/*.sh (sourced, not a test itself).
# Each check prints ok/FAIL; finish prints the plain "N passed, N failed" line.
: "${SOAK:?SOAK must point at the soak binary}"
: "${SOAK_TMP:=$(mktemp -d)}"
mkdir -p "$SOAK_TMP"
pass=0
fail=0
ok() { pass=$((pass + 1)); echo "ok   $*"; }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }
# expect_exit CODE DESCRIPTION -- command...   (stderr kept in $SOAK_TMP/last.err)
expect_exit() {
  local want=$1 what=$2; shift 3
  "$@" > "$SOAK_TMP/last.out" 2> "$SOAK_TMP/last.err"
  local got=$?
  if [ "$got" = "$want" ]; then ok "$what (exit $got)"; else bad "$what: exit $got, want $want; stderr: $(head -c 300 "$SOAK_TMP/last.err")"; fi
}
# expect_stderr PATTERN DESCRIPTION: the last command's stderr matches
expect_stderr() {
  if grep -qE -- "$1" "$SOAK_TMP/last.err"; then ok "$2"; else bad "$2: stderr lacks /$1/: $(head -c 300 "$SOAK_TMP/last.err")"; fi
}
# close A B TOL DESCRIPTION: |A - B| <= TOL
close() {
  if awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; then
    ok "$4: $1 vs $2 (tol $3)"
  else bad "$4: $1 vs $2 (tol $3)"; fi
}
finish() {
  echo "$pass passed, $fail failed"
  [ "$fail" -eq 0 ]
}
