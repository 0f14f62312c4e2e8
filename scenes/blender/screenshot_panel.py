"""Screenshot of the Wetness panel (Blender with a window, under Xvfb), after
Make Wet and Key Drying:
SOAK_BLENDER_UI=1 [SOAK_BLENDER=4.3] bash tests/blender/run_blender.sh scenes/blender/screenshot_panel.py \
    --addon build/soak_blender.zip --out blender_addon/images/panel_3.4.png
(or xvfb-run -a -s "-screen 0 1280x1024x24" blender --factory-startup --python screenshot_panel.py -- ...)
Blender 4.x under Xvfb reads a black front buffer (screenshot_area gives
black or 1x1 images): start Xvfb with `-fbdir DIR` and pass
`--xwd DIR/Xvfb_screen0`: the area is cropped from the X server's frame
buffer file."""
import os
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon", "tools"))
import soak_install  # noqa: E402  (blender_addon/tools/: as users of this Blender install it)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import xwd  # noqa: E402  (scenes/blender/xwd.py)

soak_install.install(opts["--addon"])
out = os.path.abspath(opts["--out"])
bpy.context.preferences.view.show_splash = False


def setup():
    ob = bpy.data.objects["Cube"]
    bpy.context.view_layer.objects.active = ob
    mat = ob.active_material
    mat.soak.preset = "brick"
    mat.soak.wetness_source = "NOISE"
    with bpy.context.temp_override(object=ob):
        bpy.ops.soak.make_wet()
        bpy.ops.soak.key_drying()
    # Workbench keeps the material tab short (no Surface node list above the panel)
    bpy.context.scene.render.engine = "BLENDER_WORKBENCH"
    win = bpy.context.window_manager.windows[0]
    area = max(win.screen.areas, key=lambda a: a.width * a.height)
    area.type = "PROPERTIES"
    return area


def tab():
    setup.area.spaces[0].context = "MATERIAL"
    bpy.app.timers.register(shoot, first_interval=1.0)


def shoot():
    area = setup.area
    win = bpy.context.window_manager.windows[0]
    with bpy.context.temp_override(window=win, area=area, region=area.regions[-1]):
        if "--xwd" in opts:
            bpy.ops.wm.redraw_timer(type="DRAW_WIN_SWAP", iterations=2)   # the X frame buffer up to date
            xwd.save_rect(opts["--xwd"], area.x, win.height - (area.y + area.height), area.width, area.height, out)
        else:
            bpy.ops.screen.screenshot_area(filepath=out)
    print("wrote", out)
    bpy.ops.wm.quit_blender()


def later():
    setup.area = setup()
    bpy.app.timers.register(tab, first_interval=1.0)


bpy.app.timers.register(later, first_interval=1.0)
