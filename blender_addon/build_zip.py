"""Builds the installable add-on zip: soak/ with bl_info (Blender 3.x-4.1)
and blender_manifest.toml (4.2+ extensions). Fixed timestamps: same files,
same bytes.  Usage: python3 build_zip.py OUT.zip"""
import os
import sys
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
KEEP = (".py", ".json", ".toml")


def main(out):
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
                        z.writestr(info, fh.read(), zipfile.ZIP_DEFLATED)
        # the generated OSL shaders, shipped beside the add-on (one copy in osl/)
        for f in ("soak_wet_surface.osl", "soak_wet_surface_legacy.osl", "soak_wet_sheet.osl", "soak_wetmap.osl"):
            full = os.path.join(HERE, "..", "osl", f)
            info = zipfile.ZipInfo("soak/osl/" + f, date_time=(2024, 1, 1, 0, 0, 0))
            info.external_attr = 0o644 << 16
            with open(full, "rb") as fh:
                z.writestr(info, fh.read(), zipfile.ZIP_DEFLATED)
    os.replace(tmp, out)


if __name__ == "__main__":
    main(sys.argv[1])
