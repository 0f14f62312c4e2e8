#!/usr/bin/env python3
"""Fits gallery pictures under a size: each PNG given that is larger than
--max-kb (default 400) is rewritten as a dithered palette PNG of 256 colours,
or 192 or 128 when Monte Carlo noise will not fit in 256. Pictures already
small enough are left as they are; a picture is replaced only through a
temporary file renamed over it, and only when the result fits.

usage: png_palette.py [--max-kb 400] FILE.png [FILE.png ...]
Needs Pillow (python3-pil); without it prints SKIPPED and exits 77."""
import io
import os
import sys


def fit(path, max_kb, Image):
    size = os.path.getsize(path)
    if size <= max_kb * 1024:
        return f"{path}: {size // 1024} KB, kept"
    img = Image.open(path).convert("RGB")
    for n in (256, 192, 128):
        buf = io.BytesIO()
        img.quantize(n, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.FLOYDSTEINBERG).save(
            buf, "PNG", optimize=True)
        if buf.tell() <= max_kb * 1024:
            tmp = path + ".part"
            with open(tmp, "wb") as f:
                f.write(buf.getvalue())
            os.replace(tmp, path)
            return f"{path}: {size // 1024} -> {buf.tell() // 1024} KB ({n} colours)"
    raise SystemExit(f"png_palette: {path} does not fit in {max_kb} KB even at 128 colours")


def main(argv):
    max_kb = 400.0
    if argv[:1] == ["--max-kb"]:
        if len(argv) < 2:
            raise SystemExit("png_palette: --max-kb needs a number")
        max_kb = float(argv[1])
        argv = argv[2:]
    if not argv or not max_kb > 0 or any(not a.endswith(".png") for a in argv):
        raise SystemExit(__doc__)
    try:
        from PIL import Image
    except ImportError:
        print("SKIPPED: Pillow (python3-pil) is not installed")
        return 77
    for path in argv:
        if not os.path.isfile(path):
            raise SystemExit(f"png_palette: no file {path}")
        print(fit(path, max_kb, Image))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
