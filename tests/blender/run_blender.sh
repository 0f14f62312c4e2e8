#!/bin/bash
# run_blender.sh SCRIPT ARGS...: the script in headless Blender; fails (never
# skips) when blender is missing: the README's set-up installs it.
set -u
if ! command -v blender >/dev/null; then
  echo "FAIL: blender not found on PATH (make deps installs it)"
  exit 1
fi
script=$1; shift
exec blender -b --factory-startup --python-exit-code 1 --python "$script" -- "$@"
