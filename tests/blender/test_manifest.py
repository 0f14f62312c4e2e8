"""The add-on zip as a Blender extension (4.2+) and as a 3.x add-on.

Every version: blender_manifest.toml in the zip parses, holds the fields
4.2's extension system requires, and keeps the limits extensions.blender.org
applies in strict validation (Blender's bl_pkg/cli/blender_ext.py,
TERSE_DESCRIPTION_MAX_LENGTH = 64: the tagline and each permission reason
at most 64 characters, ending in a letter, digit or closing bracket); the
zip installs and enables as each version's users install it
(common.install_addon: Install Add-on in 3.x, Install from Disk as an
extension in 4.2+); the manifest names no website (the project has none).
Blender 4.2+: `blender --command extension validate` accepts the zip, and
`blender --command extension build` builds an extension zip from its
contents that holds the same add-on files."""
import os
import shutil
import subprocess
import sys
import tomllib
import zipfile

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
ZIP, TMP = A["addon"], A["tmp"]
LIMIT = 64  # blender_ext.py TERSE_DESCRIPTION_MAX_LENGTH
REQUIRED = ("schema_version", "id", "version", "name", "tagline", "maintainer", "type", "blender_version_min",
            "license")
failures = []


def terse(label, text):
    if not isinstance(text, str) or not text.strip():
        failures.append(f"{label}: empty")
    elif len(text) > LIMIT:
        failures.append(f"{label}: {len(text)} characters (at most {LIMIT}): '{text}'")
    elif not (text[-1].isalnum() or text[-1] in ")]}"):
        failures.append(f"{label}: ends with punctuation: '{text}'")


with zipfile.ZipFile(ZIP) as z:
    names = z.namelist()
    manifest = tomllib.loads(z.read("soak/blender_manifest.toml").decode("utf-8"))
for key in REQUIRED:
    if key not in manifest:
        failures.append(f"manifest: no '{key}'")
terse("tagline", manifest.get("tagline"))
for key, reason in manifest.get("permissions", {}).items():
    terse(f"permissions.{key}", reason)
if tuple(int(x) for x in manifest.get("blender_version_min", "0.0.0").split(".")) < (4, 2, 0):
    failures.append("blender_version_min below 4.2.0 (extensions start there)")
# the project has no web page of its own: a website would be a made-up address
if "website" in manifest:
    failures.append(f"manifest website '{manifest['website']}': the project has no page; leave it out")
if manifest.get("type") != "add-on" or manifest.get("id") != "soak":
    failures.append(f"type/id: {manifest.get('type')}/{manifest.get('id')}")
print(f"tagline {len(manifest['tagline'])} characters, permission reasons "
      f"{[len(v) for v in manifest.get('permissions', {}).values()]}")

mod = common.install_addon(ZIP)
if bpy.app.version < (4, 2, 0) and mod.bl_info.get("blender", (9,)) > tuple(bpy.app.version):
    failures.append(f"bl_info blender {mod.bl_info['blender']} is above the running {bpy.app.version}")

if bpy.app.version >= (4, 2, 0):
    os.makedirs(TMP, exist_ok=True)
    blender = bpy.app.binary_path

    def command(*args):
        r = subprocess.run([blender, "--factory-startup", "--command", "extension", *args],
                           capture_output=True, text=True, timeout=120)
        print(f"blender --command extension {' '.join(args)}: exit {r.returncode}")
        return r

    r = command("validate", ZIP)
    if r.returncode != 0:
        failures.append(f"extension validate {ZIP}: exit {r.returncode}: {(r.stdout + r.stderr).strip()[-600:]}")
    src = os.path.join(TMP, "source")
    out = os.path.join(TMP, "built")
    for d in (src, out):
        shutil.rmtree(d, ignore_errors=True)
    os.makedirs(out)
    with zipfile.ZipFile(ZIP) as z:
        z.extractall(src)
    r = command("build", "--source-dir", os.path.join(src, "soak"), "--output-dir", out)
    built = [f for f in os.listdir(out) if f.endswith(".zip")]
    if r.returncode != 0 or len(built) != 1:
        failures.append(f"extension build: exit {r.returncode}, zips {built}: {(r.stdout + r.stderr).strip()[-600:]}")
    else:
        with zipfile.ZipFile(os.path.join(out, built[0])) as z:
            got = set(z.namelist())
        want = {n[len("soak/"):] for n in names if n.startswith("soak/") and not n.endswith("/")}
        if want - got:
            failures.append(f"built extension lacks {sorted(want - got)[:5]}")
        print(f"built {built[0]}: {len(got)} files")
        r = command("validate", os.path.join(out, built[0]))
        if r.returncode != 0:
            failures.append(f"extension validate (built zip): {(r.stdout + r.stderr).strip()[-600:]}")

if failures:
    common.fail("; ".join(failures))
print("PASS")
