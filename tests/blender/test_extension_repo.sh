#!/bin/bash
# The extension repository (issue 46 item 7), in Blender 4.3 or 5.2
# (SOAK_BLENDER): a studio hosts Soak, an artist installs and updates it.
#  1. build_zip.py makes the add-on zip at 1.0.0 and at 1.0.1;
#     scripts/extension-repo.sh publishes 1.0.0 (`blender --command extension
#     server-generate`): index.json lists soak 1.0.0 whose archive_hash and
#     archive_size are the zip's own sha256 and size (computed here by
#     hashlib, not by Blender);
#  2. `extension repo-add` with the file:// URL of that index.json, then
#     `extension install -s -e soak`: installed from the repository (the
#     archive's bytes on disk under the repository's folder) and enabled
#     (check_extension.py: bl_ext.<repo>.soak in the preferences' add-ons,
#     its module imported, Make Wet registered);
#  3. the repository publishes 1.0.1; `extension update -s`: the installed
#     manifest says 1.0.1 and the add-on is still enabled.
# Usage: test_extension_repo.sh TMP (SOAK_BLENDER=4.3|5.2, BLENDER_USER_* set)
set -u
here=$(cd "$(dirname "$0")" && pwd)
repo_root=$(cd "$here/../.." && pwd)
tmp=$1
run() { SOAK_BLENDER_RAW=1 bash "$here/run_blender.sh" "$@"; }
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$tmp/repo" "$tmp/zips" "$BLENDER_USER_EXTENSIONS" "$BLENDER_USER_CONFIG"
mkdir -p "$tmp/repo" "$tmp/zips"
/usr/bin/python3 "$repo_root/blender_addon/build_zip.py" "$tmp/zips/soak-1.0.0.zip" --version 1.0.0 || fail "build_zip 1.0.0"
/usr/bin/python3 "$repo_root/blender_addon/build_zip.py" "$tmp/zips/soak-1.0.1.zip" --version 1.0.1 || fail "build_zip 1.0.1"

publish() { # version: the repository holds that zip alone, index.json regenerated
  rm -f "$tmp/repo"/*.zip
  cp "$tmp/zips/soak-$1.zip" "$tmp/repo/"
  bash "$repo_root/scripts/extension-repo.sh" "$tmp/repo" || fail "server-generate for $1"
  /usr/bin/python3 - "$tmp/repo" "$1" <<'PY' || fail "index.json for $1"
import hashlib, json, os, sys
repo, version = sys.argv[1], sys.argv[2]
index = json.load(open(os.path.join(repo, "index.json")))
pkgs = [p for p in index["data"] if p["id"] == "soak"]
assert len(pkgs) == 1, f"index.json lists {len(pkgs)} soak packages"
p = pkgs[0]
zip_path = os.path.join(repo, f"soak-{version}.zip")
data = open(zip_path, "rb").read()
want = "sha256:" + hashlib.sha256(data).hexdigest()
assert p["version"] == version, f"index.json version {p['version']}, published {version}"
assert p["archive_hash"] == want, f"archive_hash {p['archive_hash']} != {want}"
assert p["archive_size"] == len(data), f"archive_size {p['archive_size']} != {len(data)}"
print(f"ok: index.json lists soak {version}, hash and size of the zip ({len(data)} bytes)")
PY
}

installed_version() {
  sed -n 's/^version = "\(.*\)"/\1/p' "$BLENDER_USER_EXTENSIONS/soak_studio/soak/blender_manifest.toml" 2>/dev/null
}

publish 1.0.0
run --command extension repo-remove blender_org >/dev/null 2>&1    # no network here: only the studio's repository
run --command extension repo-add --name "Soak studio" --url "file://$tmp/repo/index.json" soak_studio \
  || fail "repo-add"
run --online-mode --command extension install -s -e soak || fail "install from the repository"
v=$(installed_version)
[ "$v" = 1.0.0 ] || fail "installed version '$v', the repository has 1.0.0"
echo "ok: installed soak 1.0.0 from file://$tmp/repo/index.json"
run -b --python-exit-code 1 --python "$here/check_extension.py" -- soak_studio 1.0.0 || fail "not enabled after install"

publish 1.0.1
run --online-mode --command extension update -s || fail "update"
v=$(installed_version)
[ "$v" = 1.0.1 ] || fail "after update the installed version is '$v', the repository has 1.0.1"
echo "ok: updated to soak 1.0.1"
run -b --python-exit-code 1 --python "$here/check_extension.py" -- soak_studio 1.0.1 || fail "not enabled after update"
echo "test_extension_repo: passed (Blender $SOAK_BLENDER)"
