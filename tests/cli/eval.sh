#!/usr/bin/env bash
# soak eval: values against analytic identities, CSV shape, argument errors.
. "$(dirname "$0")/lib.bash"

expect_exit 0 "eval --help" -- "$SOAK" eval --help
grep -q "example" "$SOAK_TMP/last.out" && ok "help has an example" || bad "help has no example"

# Lambert: f = A / pi at any angles.
v=$("$SOAK" eval --model lambert --albedo 0.5 --theta-i 10 --theta-o 70 --phi 33 | tail -n 1)
close "$v" "$(awk 'BEGIN { printf "%.10f", 0.5 / atan2(0, -1) }')" 1e-9 "lambert = A/pi"

# A film of index 1 is no interface: the film model equals Lambert exactly.
for angles in "0 0" "30 60" "80 10"; do
  set -- $angles
  v=$("$SOAK" eval --model film --film-ior 1 --absorption 0 --albedo 0.7 --theta-i "$1" --theta-o "$2" | tail -n 1)
  close "$v" "$(awk 'BEGIN { printf "%.10f", 0.7 / atan2(0, -1) }')" 1e-9 "film n=1 equals Lambert at $1/$2"
done

# Reciprocity through the CLI: swap the angles.
a=$("$SOAK" eval --model ww --theta-i 20 --theta-o 65 --phi 150 | tail -n 1)
b=$("$SOAK" eval --model ww --theta-i 65 --theta-o 20 --phi 150 | tail -n 1)
close "$a" "$b" 1e-9 "ww reciprocal through the CLI"

lines=$("$SOAK" eval --model porous --csv --step 5 | wc -l)
[ "$lines" = 325 ] && ok "csv has 18x18 rows + header" || bad "csv has $lines lines, want 325"

expect_exit 2 "unknown model" -- "$SOAK" eval --model nosuch --theta-i 0 --theta-o 0
expect_stderr "unknown model 'nosuch'" "message names the model"
expect_exit 2 "NaN angle" -- "$SOAK" eval --model ww --theta-i nan --theta-o 0
expect_stderr "--theta-i" "message names --theta-i"
expect_exit 2 "angle out of range" -- "$SOAK" eval --model ww --theta-i 0 --theta-o 91
expect_stderr "--theta-o" "message names --theta-o"
expect_exit 2 "missing value" -- "$SOAK" eval --model ww --theta-i
expect_stderr "needs a value" "message says the value is missing"
expect_exit 2 "albedo > 1" -- "$SOAK" eval --model film --albedo 1.5 --theta-i 0 --theta-o 0
expect_stderr "--albedo" "message names --albedo"
expect_exit 2 "missing --model" -- "$SOAK" eval --theta-i 0 --theta-o 0
finish
