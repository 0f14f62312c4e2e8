"""EEVEE's first render of a wet material against the dry one: what an
artist waits for before the first picture (shader compilation). One Blender
process per run, in this order: a warm-up render of a plain material (the
engine's own shaders), the first render of the close-up textured plane dry
(blender_bench_plane.py: its material compiles), then Make Wet at --quality
and the first render again (the wet material compiles). 64x64, 1 sample.
Prints wall and CPU time (all of Blender's threads and the X server's:
llvmpipe compiles on the CPU) of each first render and the group's node
count. Not a test.

blender -b --factory-startup --python bench_eevee_compile.py -- --addon ZIP --quality BALANCED
(c_core/bench/bench_eevee_compile.sh runs it in Blender 4.3 and 5.2)"""
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_bench_plane  # noqa: E402

opts = blender_bench_plane.options()
quality = opts.get("--quality", "BALANCED")
mat, tree, bsdf = blender_bench_plane.textured_plane(opts["--addon"], False)
sc = bpy.context.scene
engines = [e.identifier for e in bpy.types.RenderSettings.bl_rna.properties["engine"].enum_items]
sc.render.engine = next(e for e in engines if e.startswith("BLENDER_EEVEE"))
sc.eevee.taa_render_samples = 1
sc.render.resolution_x = sc.render.resolution_y = 64
plane = bpy.context.object


def x_server_cpu():
    """CPU seconds of the X server this Blender draws on (Xvfb: with indirect
    GLX llvmpipe may run there, not in Blender), 0 when it cannot be found."""
    display = os.environ.get("DISPLAY", "")
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                cmd = f.read().split(b"\0")
            if cmd and cmd[0].endswith(b"Xvfb") and display.encode() in cmd:
                with open(f"/proc/{pid}/stat") as f:
                    fields = f.read().rsplit(")", 1)[1].split()
                return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
        except OSError:
            continue
    return 0.0


def first_render():
    t0, c0, x0 = time.perf_counter(), time.process_time(), x_server_cpu()
    bpy.ops.render.render()
    return time.perf_counter() - t0, time.process_time() - c0 + x_server_cpu() - x0


warm = bpy.data.materials.new("warm-up")
plane.data.materials[0] = warm
first_render()
plane.data.materials[0] = mat
dry = first_render()
mat.soak.quality = quality
bpy.ops.soak.make_wet()
gn = next(n for n in tree.nodes if n.type == "GROUP")
count = sum(1 for n in gn.node_tree.nodes if n.type not in ("FRAME", "GROUP_INPUT", "GROUP_OUTPUT"))
wet = first_render()
print(f"Blender {bpy.app.version_string} {quality}: dry first render {dry[0]:.2f} s wall {dry[1]:.2f} s CPU; "
      f"wet {wet[0]:.2f} s wall {wet[1]:.2f} s CPU; group {count} nodes; load {os.getloadavg()[0]:.1f}")
