# Shared helpers for tests/cli/*.sh (sourced, not a test itself).
# Each check prints ok/FAIL/SKIPPED; finish prints "N passed, N failed, N skipped"
# and exits 1 on a failure or when no check ran, 77 (ctest's SKIP_RETURN_CODE)
# when every check was skipped.
: "${SOAK:?SOAK must point at the soak binary}"
: "${SOAK_TMP:=$(mktemp -d)}"
mkdir -p "$SOAK_TMP"
pass=0
fail=0
skipped=0
ok() { pass=$((pass + 1)); echo "ok   $*"; }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }
# skip REASON [WHAT]: a missing tool reads "<tool> not on PATH"
skip() { skipped=$((skipped + 1)); echo "SKIPPED: $1${2:+ ($2)}"; }
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
  if ! number "$1" || ! number "$2"; then bad "$4: not numbers: '$1' vs '$2'"; return; fi
  if awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; then
    ok "$4: $1 vs $2 (tol $3)"
  else bad "$4: $1 vs $2 (tol $3)"; fi
}
# number STRING: STRING is a finite decimal number (an empty or crashed
# command's output is not)
number() { [[ $1 =~ ^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$ ]]; }
finish() {
  echo "$pass passed, $fail failed, $skipped skipped"
  [ "$fail" -eq 0 ] || exit 1
  if [ "$pass" -eq 0 ]; then
    [ "$skipped" -gt 0 ] && exit 77
    echo "FAIL no check ran"; exit 1
  fi
  exit 0
}

# wall_obj FILE: a 1 x 1 m wall in the x-z plane facing -y (z up), UVs across it.
wall_obj() {
  printf 'v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' >"$1"
}

# A unit plane (y = 0) with UVs, as OBJ, in $1 and, when $2 is given, the
# same plane without UVs in $2 (the bakes' fixture).
uv_plane_obj() {
  printf 'v -0.5 0 -0.5\nv 0.5 0 -0.5\nv 0.5 0 0.5\nv -0.5 0 0.5\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 4/4 3/3\nf 1/1 3/3 2/2\n' >"$1"
  [ -z "${2:-}" ] || grep -v '^vt' "$1" | sed 's#/[0-9]*##g' >"$2"
}
