"""Screenshot of the Wetness panel's Rain sub-panel after Bake Rain on the
default cube (Blender with a window, under Xvfb; Blender 3.4, whose
screenshot_area works there):
SOAK_BLENDER_UI=1 bash tests/blender/run_blender.sh scenes/blender/screenshot_rain_panel.py \
    --addon build/soak_blender.zip --soak build/bin/soak --out blender_addon/images/rain_panel_3.4.png"""
import os
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon", "tools"))
import soak_install  # noqa: E402

soak_install.install(opts["--addon"])
soak_install.preferences().soak_path = os.path.abspath(opts["--soak"])
out = os.path.abspath(opts["--out"])
bpy.context.preferences.view.show_splash = False
bpy.context.preferences.view.show_tooltips = False   # the pointer rests mid-screen


def setup():
    ob = bpy.data.objects["Cube"]
    bpy.context.view_layer.objects.active = ob
    mat = ob.active_material
    mat.soak.preset = "concrete"
    sc = bpy.context.scene
    s = sc.soak_rain
    s.rate, s.start_frame, s.end_frame, s.size, s.shelter = 20.0, 1, 48, 64, False
    sc.frame_end = 72
    with bpy.context.temp_override(object=ob):
        bpy.ops.soak.make_wet()
        bpy.ops.soak.bake_rain()
    mat.soak.puddle_level = 0.8
    sc.render.engine = "BLENDER_WORKBENCH"      # a short material tab
    win = bpy.context.window_manager.windows[0]
    area = max(win.screen.areas, key=lambda a: a.width * a.height)
    area.type = "PROPERTIES"
    return area


def tab():
    setup.area.spaces[0].context = "MATERIAL"
    bpy.app.timers.register(scroll, first_interval=1.0)


def scroll():
    area = setup.area
    win = bpy.context.window_manager.windows[0]
    with bpy.context.temp_override(window=win, area=area, region=area.regions[-1]):
        for _ in range(12):
            bpy.ops.view2d.scroll_down()
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
