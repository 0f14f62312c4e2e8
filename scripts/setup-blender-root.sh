#!/usr/bin/env bash
# setup-blender-root.sh VERSION ROOT: a Debian root file system holding
# Debian's Blender VERSION and Xvfb, so that the add-on is tested in the
# Blenders artists use beside the host's Debian 12 Blender 3.4:
#
#   4.3  Debian 13 "trixie": blender xvfb xauth python3-numpy (the glTF importer
#        needs it: cli_bake_per_vertex imports a baked .glb)
#   5.2  Debian sid:         the same (numpy also for the gallery scripts) and
#        python3-cattr python3-requests (5.2's bundled extensions add-on
#        imports them at every start; Debian's blender does not depend on them)
#
# Made once per build folder and reused: the stamp file ROOT/.soak-blenderXY-ready
# (XY: VERSION without the dot) records it, and tests/blender/run_blender.sh
# refuses a root without it. Run as root, as CI does (debootstrap, chroot).
#
# Measured here: trixie debootstrap about 2.5 min + 2 min of packages, 1.8 GB;
# sid about 1 min + 1 min on a quiet machine, 1.3 GB (this script, run on the
# shared machine under load: 67 s user + 14 s system CPU, 17 min wall). The
# mirror's sid Release file is past its Valid-Until date on this machine's
# clock, hence Check-Valid-Until=false.
set -euo pipefail

version=${1:?usage: setup-blender-root.sh 4.3|5.2 ROOT}
root=${2:?usage: setup-blender-root.sh 4.3|5.2 ROOT}
me="setup-blender-root $version"
packages="blender xvfb xauth"
apt_opts=""
case "$version" in
  4.3) suite=trixie
       packages="$packages python3-numpy" ;;
  5.2) suite=sid
       packages="$packages python3-numpy python3-cattr python3-requests"
       apt_opts="-o Acquire::Check-Valid-Until=false" ;;
  *) echo "$me: no Debian suite known for Blender $version (4.3: trixie, 5.2: sid)" >&2; exit 2 ;;
esac
stamp="$root/.soak-blender${version/./}-ready"

if [ -f "$stamp" ]; then
  echo "$me: $root ready ($(cat "$stamp"))"
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "$me: making the Debian $suite root for Blender $version needs root (chroot, mount)" >&2
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
echo "$me: debootstrap $suite from $mirror into $work (a few minutes)"
debootstrap --variant=minbase "$suite" "$work" "$mirror" > "$work.log" 2>&1 || {
  tail -20 "$work.log" >&2; echo "$me: debootstrap failed (log: $work.log)" >&2; exit 1; }

echo "$me: installing $packages in the $suite root"
unshare --mount --propagation private bash -euc '
  w=$1; opts=$2; shift 2
  mount -t proc proc "$w/proc"
  cp /etc/resolv.conf "$w/etc/resolv.conf" 2>/dev/null || true
  chroot "$w" bash -c "apt-get $opts update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $*"
' _ "$work" "$apt_opts" $packages >> "$work.log" 2>&1 || {
  tail -20 "$work.log" >&2; echo "$me: apt-get in the root failed (log: $work.log)" >&2; exit 1; }
chroot "$work" apt-get clean
mkdir -p "$work/host/usr"

got=$(unshare --mount --propagation private bash -c \
  'mount -t proc proc "$1/proc" && chroot "$1" blender --version 2>/dev/null | head -1' _ "$work")
case "$got" in
  "Blender $version"*) ;;
  *) echo "$me: the root's blender printed '$got', expected Blender $version" >&2; exit 1 ;;
esac
echo "$got" > "$work/$(basename "$stamp")"
rm -rf "$root"
mv "$work" "$root"
mv "$work.log" "$root.log"
echo "$me: $root ready ($got)"
