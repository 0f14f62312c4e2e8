#!/usr/bin/env bash
# test.sh MAKE BUILD: what `make test` runs after the set-up (README.md,
# .ci/run). The two Debian roots of Blender 4.3 and 5.2 (`make blender43
# blender52`: downloads and unpacking, little CPU, about 5 minutes when new)
# are made in the background while the release and sanitizer trees build and
# the sanitizer pass runs (it needs no Blender); the release pass starts when
# both roots are ready. Both passes run whatever the other's result; the exit
# status is non-zero when a pass or a root failed. The roots' output is kept
# in BUILD/blender43.setup.log and BUILD/blender52.setup.log.
set -uo pipefail
MAKE_CMD=${1:-make}
BUILD=${2:-build}
mk() { $MAKE_CMD --no-print-directory "$@"; }
mkdir -p "$BUILD"
status=0

pids=()
for v in 43 52; do
  mk "blender$v" > "$BUILD/blender$v.setup.log" 2>&1 &
  pids+=($!)
done
echo "make test: Blender 4.3 and 5.2 roots being made in the background ($BUILD/blender43.setup.log, $BUILD/blender52.setup.log)"

release_built=0
if mk build; then
  release_built=1
  if mk build-asan; then
    mk ctest-asan || status=1
  else
    echo "make test: the sanitizer build failed"; status=1
  fi
else
  echo "make test: the release build failed"; status=1
fi

roots_ok=1
for i in 0 1; do
  v=$([ $i = 0 ] && echo 43 || echo 52)
  if ! wait "${pids[$i]}"; then
    roots_ok=0
    echo "make test: making the Blender ${v:0:1}.${v:1} root failed; the end of $BUILD/blender$v.setup.log:"
    tail -20 "$BUILD/blender$v.setup.log" | sed 's/^/    /'
  else
    tail -1 "$BUILD/blender$v.setup.log"
  fi
done
[ $roots_ok = 1 ] || status=1

if [ $release_built = 1 ]; then
  # without a root the release pass still runs: its Blender tests fail, naming the missing root
  mk ctest-release || status=1
fi
exit $status
