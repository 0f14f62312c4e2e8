#!/bin/bash
# extension-repo.sh DIR: the extension repository listing of the add-on zips
# in DIR (index.json beside them), by `blender --command extension
# server-generate` in Blender 5.2 (Debian sid root; SOAK_BLENDER=4.3 for the
# Debian 13 one). A studio serves DIR over http(s) or file:// and artists add
# its index.json as a remote repository in Get Extensions (README,
# "Extension repository").
set -eu
here=$(cd "$(dirname "$0")" && pwd)
dir=$(readlink -f "$1")
ls "$dir"/*.zip >/dev/null 2>&1 || { echo "extension-repo.sh: no add-on zip in $dir"; exit 1; }
export SOAK_BLENDER=${SOAK_BLENDER:-5.2}
out=$(SOAK_BLENDER_RAW=1 bash "$here/../tests/blender/run_blender.sh" --command extension server-generate \
  --repo-dir "$dir" 2>&1) || { echo "$out"; echo "extension-repo.sh: server-generate failed"; exit 1; }
[ -s "$dir/index.json" ] || { echo "$out"; echo "extension-repo.sh: no index.json written in $dir"; exit 1; }
echo "extension repository: $dir/index.json ($(echo "$out" | grep -o 'found [0-9]* packages'))"
