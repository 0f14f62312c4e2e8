#!/usr/bin/env bash
# Installs the Debian bookworm packages Soak needs, only those missing, for
# one tier of work (each tier includes the ones above it):
#   build    compile the C core and the soak tool (make build)
#   package  + what CPack's .deb needs (make package)
#   demo     + the renderers of the main job: POV-Ray, Blender (make demo)
#   test     + every tool of the test suite (make test; the default)
# Usage: scripts/install-deps.sh [build|package|demo|test]
# Idempotent: a second run does nothing and prints one line.
set -euo pipefail

tier=${1:-test}
build=(
  build-essential cmake pkg-config
  libopenimageio-dev libembree-dev libassimp-dev libcjson-dev libopenvdb-dev libboost-dev
)
package=(dpkg-dev file)
demo=(povray blender blender-data xvfb python3 openimageio-tools)  # blender-data: the world HDRIs of the gallery
test=(
  git python3-numpy python3-jsonschema python3-matplotlib valgrind debootstrap hyperfine
  slurm-wlm munge nodejs man-db clang-format flake8 povray-examples
  assimp-testmodels  # the mesh corpus of test_mesh_corpus (issue 47)
)
case "$tier" in
  build) packages=("${build[@]}") ;;
  package) packages=("${build[@]}" "${package[@]}") ;;
  demo) packages=("${build[@]}" "${demo[@]}") ;;
  test) packages=("${build[@]}" "${package[@]}" "${demo[@]}" "${test[@]}") ;;
  *) echo "install-deps: unknown tier '$tier' (expected build, package, demo or test)" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} Debian packages of the $tier tier present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null; then sudo="sudo"; else
    echo "install-deps: missing packages (${missing[*]}) and not root; run as root or install them" >&2
    exit 1
  fi
fi
echo "install-deps ($tier): installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
