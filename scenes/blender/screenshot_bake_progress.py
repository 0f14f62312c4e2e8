"""Screenshot of Bake Rain running: the progress bar Soak draws in the status
bar (UILayout.progress in 4.0+, a text bar in 3.x), Blender with a window
under Xvfb, the picture read from the X frame buffer:

SOAK_BLENDER_UI=1 SOAK_XVFB_FBDIR=/tmp/fb [SOAK_BLENDER=5.2] bash tests/blender/run_blender.sh \
    scenes/blender/screenshot_bake_progress.py --addon build/soak_blender.zip --soak build/bin/soak \
    --xwd /tmp/fb/Xvfb_screen0 --out blender_addon/images/bake_progress_5.2.png

Waits for the bake to end before quitting (no orphaned soak process)."""
import os
import struct
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
out = os.path.abspath(opts["--out"])
bpy.context.preferences.view.show_splash = False


def read_xwd(path):
    """(width, height, rows of (r, g, b) bytes top first) of an Xvfb -fbdir
    frame buffer file (XWD, 24-bit TrueColor, 32 bits per pixel)."""
    with open(path, "rb") as f:
        raw = f.read()
    h = struct.unpack(">25I", raw[:100])
    size, width, height, byte_order, bpp, stride, ncolors = h[0], h[4], h[5], h[7], h[11], h[12], h[19]
    if bpp != 32:
        raise SystemExit(f"{path}: {bpp} bits per pixel, expected 32 (Xvfb -screen 0 WxHx24)")
    start = size + 12 * ncolors
    rows = []
    for y in range(height):
        line = raw[start + y * stride:start + y * stride + 4 * width]
        if byte_order == 0:      # LSBFirst: B G R X
            rgb = bytes(b for i in range(0, len(line), 4) for b in (line[i + 2], line[i + 1], line[i]))
        else:
            rgb = bytes(b for i in range(0, len(line), 4) for b in (line[i + 1], line[i + 2], line[i + 3]))
        rows.append(rgb)
    return width, height, rows


def save_window(win, path, y0=0, rows=None):
    width, height, fb = read_xwd(opts["--xwd"])
    w, h = min(width, win.width), min(height, win.height)
    rows = rows or h
    img = bpy.data.images.new("shot", w, rows)
    px = []
    for y in range(h - 1, h - 1 - rows, -1):
        line = fb[y]
        for x in range(w):
            px += [line[3 * x] / 255.0, line[3 * x + 1] / 255.0, line[3 * x + 2] / 255.0, 1.0]
    img.pixels[:] = px
    img.filepath_raw = path
    img.file_format = "PNG"
    img.save()


def start():
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon",
                                    "tools"))
    import soak_install  # noqa: E402
    soak_install.install(opts["--addon"])
    soak_install.preferences().soak_path = os.path.abspath(opts["--soak"])
    bpy.context.preferences.view.show_tooltips = False
    win = bpy.context.window_manager.windows[0]
    ob = bpy.data.objects["Cube"]
    bpy.context.view_layer.objects.active = ob
    area = next(a for a in win.screen.areas if a.type == "VIEW_3D")
    with bpy.context.temp_override(window=win, area=area, object=ob):
        assert bpy.ops.soak.make_wet() == {"FINISHED"}
        r = bpy.ops.soak.bake_rain("INVOKE_DEFAULT")
    print("bake_rain invoked:", r)
    start.win = win
    bpy.app.timers.register(shoot, first_interval=4.0)


def shoot():
    win = start.win
    with bpy.context.temp_override(window=win):
        bpy.ops.wm.redraw_timer(type="DRAW_WIN_SWAP", iterations=2)
    save_window(win, out, rows=64)          # the bottom of the window: the status bar
    print("wrote", out)
    bpy.app.timers.register(wait_end, first_interval=2.0)


def wait_end():
    if any(i.get("soak_rain_for") for i in bpy.data.images):
        print("bake finished")
        bpy.ops.wm.quit_blender()
        return None
    return 2.0


bpy.app.timers.register(start, first_interval=1.0)
