#!/usr/bin/env bash
# Compiles the shipped shaders with oslc where OSL is installed. OSL is not
# packaged by Debian: without oslc this test is SKIPPED (exit 77), never a
# pass; the shaders' arithmetic is checked against the core by test_osl_math
# in every build.
. "$(dirname "$0")/lib.bash"
ROOT=${SOAK_ROOT:?}
if ! command -v oslc > /dev/null; then
  echo "SKIPPED: oslc not on PATH (OSL has no Debian package); test_osl_math checks the shaders' math"
  exit 77
fi
for f in soak_wet_surface.osl soak_wetmap.osl; do
  expect_exit 0 "oslc $f" -- oslc -o "$SOAK_TMP/${f%.osl}.oso" "$ROOT/osl/$f"
done
finish
