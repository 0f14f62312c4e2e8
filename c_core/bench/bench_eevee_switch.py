"""Benchmark (not a test), issue 46's frozen EEVEE switch: the default cube
after Make Wet (Noise source) and Key Drying, then the engine switched to
EEVEE: how often the add-on's depsgraph handler (handlers.respecialise)
runs and rebuilds the group on the switch and over 40 frame changes, the
time it spends, and the first (shader compile) and second EEVEE renders
(64 px, 1 sample). --dry 1: the same without Make Wet (the baseline).
  SOAK_BLENDER=5.2 bash tests/blender/run_blender.sh c_core/bench/bench_eevee_switch.py \
      --addon build/soak_blender.zip [--dry 1]"""
import os
import sys
import time

import bpy
argv = sys.argv[sys.argv.index("--") + 1:]
opts = dict(zip(argv[::2], argv[1::2]))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon", "tools"))
import soak_install
soak_install.install(opts["--addon"])
soak = sys.modules["soak"]
H = soak.handlers
stats = {"calls": 0, "rebuilds": 0, "t": 0.0}
orig = H.specialise.specialise


def counted(mat):
    n = orig(mat)
    stats["rebuilds"] += n
    return n


H.specialise.specialise = counted
orig_h = H.respecialise


def timed(*a):
    t = time.perf_counter()
    orig_h(*a)
    stats["t"] += time.perf_counter() - t
    stats["calls"] += 1


hs = bpy.app.handlers.depsgraph_update_post
i = [k for k, f in enumerate(hs) if getattr(f, "__name__", "") == "respecialise"]
for k in i:
    hs[k] = timed
ob = bpy.data.objects["Cube"]
bpy.context.view_layer.objects.active = ob
mat = ob.active_material
if opts.get("--dry") != "1":
    mat.soak.wetness_source = "NOISE"
    assert bpy.ops.soak.make_wet() == {"FINISHED"}
    assert bpy.ops.soak.key_drying() == {"FINISHED"}
ng = [g.name for g in bpy.data.node_groups]
print("groups after key drying:", ng, "nodes in group:", len(bpy.data.node_groups[ng[0]].nodes) if ng else 0)
sc = bpy.context.scene
def reset(): stats.update(calls=0, rebuilds=0, t=0.0)


reset()
engines = [e.identifier for e in bpy.types.RenderSettings.bl_rna.properties["engine"].enum_items]
eevee = next(e for e in engines if e.startswith("BLENDER_EEVEE"))
sc.render.engine = eevee
for _ in range(5):
    bpy.context.view_layer.update()
print(
    f"switch to {eevee} + 5 updates: handler calls {stats['calls']}, rebuilds {stats['rebuilds']}, handler time {stats['t']*1000:.1f} ms")
reset()
for f in range(1, 41):
    sc.frame_set(f)
print(
    f"40 frame changes: handler calls {stats['calls']}, rebuilds {stats['rebuilds']}, handler time {stats['t']*1000:.1f} ms")
sc.render.resolution_x = sc.render.resolution_y = 64
if hasattr(sc.eevee, "taa_render_samples"):
    sc.eevee.taa_render_samples = 1
for label in ("first EEVEE render (compiles the group's shader)", "second render (cached)"):
    reset()
    t = time.time()
    bpy.ops.render.render()
    print(f"{label}: {time.time()-t:.1f} s; handler calls {stats['calls']}, rebuilds {stats['rebuilds']}")
