"""Builds the installable add-on zip: soak/ with bl_info (Blender 3.x-4.1)
and blender_manifest.toml (4.2+ extensions). Fixed timestamps: same files,
same bytes.  Usage: python3 build_zip.py OUT.zip [--version X.Y.Z]

--version rewrites the manifest's version (and bl_info's) in the zip: the
extension repository's test publishes a newer build to update to."""
import os
import re
import sys
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
KEEP = (".py", ".json", ".toml")


def _versioned(rel, text, version):
    """The file's bytes with `version` in place of the manifest's version line
    or bl_info's version tuple; unchanged without a version."""
    if version is None:
        return text
    if rel.endswith("blender_manifest.toml"):
        new, n = re.subn(rb'(?m)^version = "[^"]*"', b'version = "' + version.encode() + b'"', text)
    elif rel == os.path.join("soak", "__init__.py"):
        tup = "(" + ", ".join(version.split(".")) + ")"
        new, n = re.subn(rb'"version": \([0-9, ]+\)', b'"version": ' + tup.encode(), text)
    else:
        return text
    if n != 1:
        raise SystemExit(f"build_zip.py: no version to replace in {rel}")
    return new


def main(out, version=None):
    if version is not None and not re.fullmatch(r"[0-9]+\.[0-9]+\.[0-9]+", version):
        raise SystemExit(f"build_zip.py: --version {version!r}: expected X.Y.Z")
    tmp = out + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        for root, dirs, files in os.walk(os.path.join(HERE, "soak")):
            dirs[:] = sorted(d for d in dirs if d != "__pycache__")
            for f in sorted(files):
                if f.endswith(KEEP):
                    full = os.path.join(root, f)
                    info = zipfile.ZipInfo(os.path.relpath(full, HERE), date_time=(2024, 1, 1, 0, 0, 0))
                    info.external_attr = 0o644 << 16
                    with open(full, "rb") as fh:
                        z.writestr(info, _versioned(info.filename, fh.read(), version), zipfile.ZIP_DEFLATED)
        # the generated OSL shaders, shipped beside the add-on (one copy in osl/)
        for f in ("soak_wet_surface.osl", "soak_wet_surface_legacy.osl", "soak_wet_sheet.osl", "soak_wetmap.osl"):
            full = os.path.join(HERE, "..", "osl", f)
            info = zipfile.ZipInfo("soak/osl/" + f, date_time=(2024, 1, 1, 0, 0, 0))
            info.external_attr = 0o644 << 16
            with open(full, "rb") as fh:
                z.writestr(info, fh.read(), zipfile.ZIP_DEFLATED)
    os.replace(tmp, out)


if __name__ == "__main__":
    args = sys.argv[1:]
    ver = None
    if "--version" in args:
        i = args.index("--version")
        if i + 1 >= len(args):
            raise SystemExit("build_zip.py: --version needs X.Y.Z")
        ver = args[i + 1]
        del args[i:i + 2]
    if len(args) != 1:
        raise SystemExit("usage: python3 build_zip.py OUT.zip [--version X.Y.Z]")
    main(args[0], ver)
