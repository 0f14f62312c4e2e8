"""Screenshot of Bake Rain running: the progress bar Soak draws in the status
bar (UILayout.progress in 4.0+, a text bar in 3.x), Blender with a window
under Xvfb, the picture read from the X frame buffer:

SOAK_BLENDER_UI=1 SOAK_XVFB_FBDIR=/tmp/fb [SOAK_BLENDER=5.2] bash tests/blender/run_blender.sh \
    scenes/blender/screenshot_bake_progress.py --addon build/soak_blender.zip --soak build/bin/soak \
    --xwd /tmp/fb/Xvfb_screen0 --out blender_addon/images/bake_progress_5.2.png

Waits for the bake to end before quitting (no orphaned soak process)."""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import xwd  # noqa: E402  (scenes/blender/xwd.py)

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
out = os.path.abspath(opts["--out"])
bpy.context.preferences.view.show_splash = False


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
    xwd.save_rect(opts["--xwd"], 0, win.height - 64, win.width, 64, out)   # the status bar
    print("wrote", out)
    bpy.app.timers.register(wait_end, first_interval=2.0)


def wait_end():
    if any(i.get("soak_rain_for") for i in bpy.data.images):
        print("bake finished")
        bpy.ops.wm.quit_blender()
        return None
    return 2.0


bpy.app.timers.register(start, first_interval=1.0)
