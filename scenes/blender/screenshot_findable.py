"""Where an artist finds Soak, as Blender starts (issue 46 item 5): the
default layout and render engine, the default cube selected, the Properties
editor on the Material tab (the Soak panel must show without scrolling),
and the 3D Viewport turned into a Shader Editor with its sidebar open (the
Soak tab, active where the Blender lets a script choose it). Blender with a window under Xvfb; the picture is read from the X
server's frame buffer (4.x and 5.x draw a black front buffer there):

SOAK_BLENDER_UI=1 SOAK_XVFB_FBDIR=/tmp/fb [SOAK_BLENDER=4.3] bash tests/blender/run_blender.sh \
    scenes/blender/screenshot_findable.py --addon build/soak_blender.zip --xwd /tmp/fb/Xvfb_screen0 \
    --out blender_addon/images/findable_3.4.png

Prints where the Soak panel's header is in the Properties editor (its top
in pixels below the editor's top, and the editor's height)."""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import xwd  # noqa: E402  (scenes/blender/xwd.py)

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
out = os.path.abspath(opts["--out"])
bpy.context.preferences.view.show_splash = False     # read before the splash opens: set at start-up


def setup():
    win = bpy.context.window_manager.windows[0]
    ob = bpy.data.objects["Cube"]
    bpy.context.view_layer.objects.active = ob
    ob.select_set(True)
    props = next(a for a in win.screen.areas if a.type == "PROPERTIES")
    props.spaces[0].context = "MATERIAL"
    timeline = next(a for a in win.screen.areas if a.type == "VIEW_3D")
    timeline.type = "NODE_EDITOR"
    timeline.ui_type = "ShaderNodeTree"
    sp = timeline.spaces[0]
    sp.show_region_ui = True
    return win, props, timeline


def open_sidebar_tab():
    win, props, shader = setup.state
    region = next(r for r in shader.regions if r.type == "UI")
    with bpy.context.temp_override(window=win, area=shader, region=region):
        try:
            bpy.ops.wm.context_set_string(data_path="space_data.region_ui.active_panel_category", value="Soak")
        except (TypeError, RuntimeError, AttributeError):
            pass
    # the sidebar's active tab (3.4: no RNA for it; the Soak tab is picked by its category when clicked)
    for r in shader.regions:
        if r.type == "UI" and hasattr(r, "active_panel_category"):
            try:
                r.active_panel_category = "Soak"
            except (TypeError, AttributeError):
                pass
    bpy.app.timers.register(shoot, first_interval=1.5)


def shoot():
    win, props, shader = setup.state
    with bpy.context.temp_override(window=win, area=props):
        bpy.ops.wm.redraw_timer(type="DRAW_WIN_SWAP", iterations=2)
    w, h = xwd.save_rect(opts["--xwd"], 0, 0, win.width, win.height, out)
    print(f"wrote {out} ({w}x{h}); Properties editor {props.width}x{props.height} at ({props.x}, {props.y}); "
          f"engine {bpy.context.scene.render.engine}; Blender {bpy.app.version_string}")
    bpy.ops.wm.quit_blender()


def later():
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon",
                                    "tools"))
    import soak_install  # noqa: E402
    soak_install.install(opts["--addon"])
    bpy.context.preferences.view.show_splash = False
    bpy.context.preferences.view.show_tooltips = False
    setup.state = setup()
    bpy.app.timers.register(open_sidebar_tab, first_interval=1.0)


bpy.app.timers.register(later, first_interval=1.0)
