"""Screenshot of the Wetness panel (Blender with a window, under Xvfb):
xvfb-run -a -s "-screen 0 1280x1024x24" blender --factory-startup --python screenshot_panel.py -- \
    --addon build/soak_blender.zip --out blender_addon/images/panel.png"""
import os
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
bpy.ops.preferences.addon_install(filepath=os.path.abspath(opts["--addon"]), overwrite=True)
bpy.ops.preferences.addon_enable(module="soak")
out = os.path.abspath(opts["--out"])
bpy.context.preferences.view.show_splash = False


def setup():
    ob = bpy.data.objects["Cube"]
    bpy.context.view_layer.objects.active = ob
    mat = ob.active_material
    mat.soak.preset = "brick"
    with bpy.context.temp_override(object=ob):
        bpy.ops.soak.make_wet()
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
        bpy.ops.screen.screenshot_area(filepath=out)
    print("wrote", out)
    bpy.ops.wm.quit_blender()


def later():
    setup.area = setup()
    bpy.app.timers.register(tab, first_interval=1.0)


bpy.app.timers.register(later, first_interval=1.0)
