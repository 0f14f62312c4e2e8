"""Renders the Blender seed scenes (seeds.py) with the add-on installed from its zip.

blender -b --factory-startup --python-exit-code 1 --python render_all.py -- \\
    --addon build/soak_blender.zip --out out/demo/blender [--soak build/bin/soak] \\
    [--size 320x180] [--samples 16] [--prefix NAME_] [--only NAME[,NAME...]] [--max-kb 400]

A scene with several frames (bricks drying) is rendered at half size per
frame and tiled 2 x 2 into one picture of the full size, white between the
frames. Prints the render time of every picture. --soak sets the add-on's
path to the soak executable (Bake Wet Map, the bakes of the bricks and
bas-relief scenes); without it the add-on looks on PATH. A scene that sets
the scene property soak_inset (a wet map's path) gets that map pasted into
its lower right corner (white = wet). --max-kb: a picture whose PNG is
larger (Monte Carlo noise does not compress) is smoothed with a 3 x 3
binomial filter, up to three times, until it fits (Debian's Blender has no denoiser)."""
import os
import sys
import time

import bpy

try:
    import numpy as np
except ImportError:   # Debian 13's blender package: no tiling or smoothing, no numpy scenes
    np = None

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
out = os.path.abspath(opts.get("--out", "out/demo/blender"))
w, h = (int(x) for x in opts.get("--size", "320x180").split("x"))
samples = int(opts.get("--samples", "16"))
prefix = opts.get("--prefix", "")
max_kb = float(opts.get("--max-kb", "0"))
only = set(opts["--only"].split(",")) if "--only" in opts else None
os.makedirs(out, exist_ok=True)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon", "tools"))
import soak_install  # noqa: E402  (blender_addon/tools/: as users of this Blender install it)

soak_install.install(opts["--addon"])
if "--soak" in opts:
    soak_install.preferences().soak_path = os.path.abspath(opts["--soak"])

import seeds  # noqa: E402

# per-scene sample factors: back light through a sheet and the glass are noisier
FACTOR = {"wet_paper_back": 2.0, "cognac_table": 1.5}


def _render(sc, path, frame):
    sc.frame_set(frame)
    sc.render.filepath = path
    t0 = time.time()
    bpy.ops.render.render(write_still=True)
    return time.time() - t0


def _load(path):
    im = bpy.data.images.load(path)
    a = np.array(im.pixels[:], dtype=np.float32).reshape(im.size[1], im.size[0], 4)
    bpy.data.images.remove(im)
    return a


def _save(a, target):
    img = bpy.data.images.new("out", a.shape[1], a.shape[0])
    img.pixels.foreach_set(a.ravel())
    img.filepath_raw = target
    img.file_format = "PNG"
    img.save()
    bpy.data.images.remove(img)


def _tile(paths, target, w, h, pad):
    """2 x 2 tiling of four equal renders (first at the top left), `pad`
    pixels of white between them and round them, on a w x h picture."""
    imgs = [_load(p) for p in paths]
    fh, fw = imgs[0].shape[:2]
    out = np.ones((h, w, 4), dtype=np.float32)
    x0, y0 = (w - 2 * fw - pad) // 2, (h - 2 * fh - pad) // 2
    for k, im in enumerate(imgs[:4]):               # pixels rows run bottom to top
        x = x0 + (k % 2) * (fw + pad)
        y = y0 + (1 - k // 2) * (fh + pad)
        out[y:y + fh, x:x + fw] = im
    _save(out, target)


def _inset(target, map_path):
    """The scene's wet map (white = wet) pasted into the lower right corner,
    a quarter of the picture's width, in a pale 2-pixel frame 16 pixels
    from the edges, as the POV-Ray and soak columns show it."""
    a = _load(target)
    h, w = a.shape[:2]
    im = bpy.data.images.load(map_path, check_existing=False)
    im.colorspace_settings.name = "Non-Color"
    m = np.array(im.pixels[:], dtype=np.float32).reshape(im.size[1], im.size[0], 4)[..., 0]
    bpy.data.images.remove(im)
    iw, ih = w // 4, w // 8
    r0 = (np.arange(ih) * m.shape[0]) // ih       # each inset pixel: the mean of its block
    c0 = (np.arange(iw) * m.shape[1]) // iw
    counts = np.outer(np.diff(np.append(r0, m.shape[0])), np.diff(np.append(c0, m.shape[1])))
    m = np.add.reduceat(np.add.reduceat(m, r0, axis=0), c0, axis=1) / counts
    pad, edge = max(2, w // 60), 2
    x, y = w - pad - iw - edge, pad                 # rows run bottom to top
    a[y:y + ih + 2 * edge, x:x + iw + 2 * edge, :3] = 0.92
    a[y + edge:y + edge + ih, x + edge:x + edge + iw, :3] = m[..., None]
    _save(a, target)


def _fit(target, kb):
    """Smooths the picture until its PNG is at most kb kilobytes (3 tries)."""
    for _ in range(3):
        if os.path.getsize(target) <= kb * 1024:
            return
        a = _load(target)
        b = a.copy()
        for axis in (0, 1):
            p = np.pad(b, [(1, 1) if i == axis else (0, 0) for i in range(3)], mode="edge")
            n = b.shape[axis]
            b = 0.25 * np.take(p, range(0, n), axis) + 0.5 * np.take(p, range(1, n + 1), axis) \
                + 0.25 * np.take(p, range(2, n + 2), axis)
        _save(b, target)
        print(f"smoothed {target}: {os.path.getsize(target) // 1024} KB", flush=True)


total = 0.0
for name, build in seeds.SCENES.items():
    if only is not None and name not in only:
        continue
    if np is None and name in seeds.NUMPY_SCENES:
        print(f"skipped {name}: its wet map is made with numpy, which this Blender's Python lacks", flush=True)
        continue
    t_build = time.time()
    renders = build()
    t_build = time.time() - t_build
    sc = bpy.context.scene
    sc.cycles.samples = max(1, int(samples * FACTOR.get(name, 1.0)))
    for fname, frames in renders:
        target = os.path.join(out, prefix + fname + ".png")
        if len(frames) == 1:
            sc.render.resolution_x, sc.render.resolution_y = w, h
            secs = _render(sc, target, frames[0])
            if sc.get("soak_inset") and np is not None:
                _inset(target, sc["soak_inset"])
        else:
            pad = max(2, w // 120)                 # 8 px of white between the frames at 960
            sc.render.resolution_x, sc.render.resolution_y = (w - 3 * pad) // 2, (h - 3 * pad) // 2
            parts = [os.path.join(out, f"{prefix}{fname}_{f:02d}.png") for f in frames]
            secs = sum(_render(sc, p, f) for p, f in zip(parts, frames))
            if np is None:
                print(f"no numpy: {fname}'s frames left as {len(parts)} pictures, not tiled")
                total += secs
                continue
            _tile(parts, target, w, h, pad)
            for p in parts:
                os.remove(p)
        if max_kb > 0 and np is not None:
            _fit(target, max_kb)
        total += secs
        print(f"wrote {target}: {w}x{h}, {sc.cycles.samples} samples, render {secs:.1f} s "
              f"(build {t_build:.1f} s)", flush=True)
print(f"total render time {total:.1f} s", flush=True)
