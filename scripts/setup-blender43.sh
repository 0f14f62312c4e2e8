#!/usr/bin/env bash
# setup-blender43.sh ROOT: a Debian 13 ("trixie") root file system holding
# Debian's Blender 4.3 and Xvfb, so that the add-on is tested in the Blender
# artists use beside Debian 12's 3.4. Made once per build folder and reused
# (a stamp file records it); run as root, as CI does. Blender runs there
# through tests/blender/run_blender.sh (SOAK_BLENDER=4.3).
#
# Measured here: debootstrap about 2.5 min, Blender and Xvfb about 2 min,
# 1.8 GB on disk (inside the build folder, ignored by git).
set -euo pipefail

root=${1:?usage: setup-blender43.sh ROOT}
stamp="$root/.soak-blender43-ready"
packages="blender xvfb xauth"

if [ -f "$stamp" ]; then
  echo "setup-blender43: $root ready ($(cat "$stamp"))"
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "setup-blender43: making the Debian 13 root for Blender 4.3 needs root (chroot, mount)" >&2
  exit 1
fi
if ! command -v debootstrap >/dev/null; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap
fi

# The mirror this machine already uses (deb822 or one-line sources).
mirror=$(sed -n 's/^URIs: //p' /etc/apt/sources.list.d/debian.sources 2>/dev/null | head -1 || true)
if [ -z "$mirror" ]; then
  mirror=$(awk '$1 == "deb" {print $2; exit}' /etc/apt/sources.list 2>/dev/null || true)
fi
mirror=${mirror:-http://deb.debian.org/debian}

# Built beside its final name and renamed at the end: an interrupted set-up
# leaves no half root that a later run would take for a finished one.
work="$root.partial"
rm -rf "$work"
mkdir -p "$(dirname "$root")"
echo "setup-blender43: debootstrap trixie from $mirror into $work (a few minutes)"
debootstrap --variant=minbase trixie "$work" "$mirror" > "$work.log" 2>&1 || {
  tail -20 "$work.log" >&2; echo "setup-blender43: debootstrap failed (log: $work.log)" >&2; exit 1; }

echo "setup-blender43: installing $packages in the trixie root"
unshare --mount --propagation private bash -euc '
  w=$1; shift
  mount -t proc proc "$w/proc"
  cp /etc/resolv.conf "$w/etc/resolv.conf" 2>/dev/null || true
  chroot "$w" bash -c "apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $*"
' _ "$work" $packages >> "$work.log" 2>&1 || {
  tail -20 "$work.log" >&2; echo "setup-blender43: apt-get in the root failed (log: $work.log)" >&2; exit 1; }
chroot "$work" apt-get clean
mkdir -p "$work/host/usr"

version=$(unshare --mount --propagation private bash -c \
  'mount -t proc proc "$1/proc" && chroot "$1" blender --version 2>/dev/null | head -1' _ "$work")
case "$version" in
  "Blender 4."*) ;;
  *) echo "setup-blender43: the root's blender printed '$version', expected Blender 4.x" >&2; exit 1 ;;
esac
echo "$version" > "$work/.soak-blender43-ready"
rm -rf "$root"
mv "$work" "$root"
mv "$work.log" "$root.log"
echo "setup-blender43: $root ready ($version)"
