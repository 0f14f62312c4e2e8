#!/usr/bin/env bash
# Installs the Debian bookworm packages Soak needs, only those missing.
# Idempotent: a second run does nothing and prints one line.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libopenimageio-dev openimageio-tools
  libembree-dev libassimp-dev libcjson-dev libopenvdb-dev libboost-dev
  povray blender xvfb python3 python3-numpy python3-jsonschema
  python3-matplotlib valgrind debootstrap hyperfine
  slurm-wlm munge nodejs
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} Debian packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null; then sudo="sudo"; else
    echo "install-deps: missing packages (${missing[*]}) and not root; run as root or install them" >&2
    exit 1
  fi
fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
