"""The add-on zip with the gallery's extra presets: soak_data.json re-exported
by the core with `soak export --target blender --variant ...` (one variant a
line of VARIANTS, e.g. scenes/gallery/variants.txt: clay at the porosities of
[Hnat06] Fig. 5, concrete and copper under [Lag13]'s film depths), every other
file of the add-on as built. Python copies bytes; the core computes the data.

usage: /usr/bin/python3 variant_addon.py SOAK ADDON.zip VARIANTS OUT.zip"""
import os
import subprocess
import sys
import tempfile
import zipfile


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    soak, addon, variants, out = sys.argv[1:]
    lines = [l.strip() for l in open(variants, encoding="utf-8") if l.strip() and not l.startswith("#")]
    with tempfile.TemporaryDirectory() as tmp:
        data = os.path.join(tmp, "soak_data.json")
        args = [soak, "export", "--target", "blender", "-o", data] + [f"--variant={v}" for v in lines]
        r = subprocess.run(args, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"variant_addon.py: {' '.join(args[:4])} failed: {r.stderr.strip()}")
        staged = out + ".tmp"
        replaced = 0
        with zipfile.ZipFile(addon) as src, zipfile.ZipFile(staged, "w", zipfile.ZIP_DEFLATED) as dst:
            for item in src.infolist():
                if item.filename.endswith("/soak_data.json"):
                    dst.write(data, item.filename)
                    replaced += 1
                else:
                    dst.writestr(item, src.read(item.filename))
        if replaced != 1:
            os.remove(staged)
            sys.exit(f"variant_addon.py: {addon} holds {replaced} soak_data.json, expected 1")
        os.replace(staged, out)
    print(f"wrote {out}: {addon} with {len(lines)} preset variants")


if __name__ == "__main__":
    main()
