"""Benchmark (not a test): Blender's Bake Rain over a 250-frame shot at the
default resolution (256 px maps), on the scene of tests/blender/test_bakes_show.py
(a 2 x 2 m yard under a 0.6 m bench, 24 fps, frames 1-250), one add-on zip
per run. Prints one line: label, wall seconds, CPU seconds of the soak
processes (RUSAGE_CHILDREN), whether the ripple flipbook came from the cache.

  bench_blender_bake_rain.sh runs it for two zips, interleaved and repeated.

--same-inputs 1: the old add-on's inputs on both sides (rain frames 1-120,
real time: 1/24 s a frame, Dry Time 20 s); otherwise each zip's defaults."""
import os
import resource
import shutil
import sys
import tempfile
import time

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon", "tools"))
import soak_install  # noqa: E402

soak_install.install(opts["--addon"])
soak_install.preferences().soak_path = os.path.abspath(opts["--soak"])
cache = os.path.join(tempfile.gettempdir(), "soak_rain")     # TMPDIR: the .sh gives each run its own
if opts.get("--cold", "1") == "1":
    shutil.rmtree(os.path.join(cache, ".ripple-cache"), ignore_errors=True)   # no flipbook from an earlier run
for ob in list(bpy.data.objects):
    bpy.data.objects.remove(ob)
sc = bpy.context.scene
sc.frame_start, sc.frame_end = 1, 250
sc.render.fps, sc.render.fps_base = 24, 1.0
bpy.ops.mesh.primitive_plane_add(size=0.6, location=(-0.5, 0.0, 0.3))
bpy.ops.mesh.primitive_plane_add(size=2.0)
yard = bpy.context.object
mat = bpy.data.materials.new("Yard")
mat.use_nodes = True
yard.data.materials.append(mat)
mat.soak.preset = "concrete"
assert bpy.ops.soak.make_wet() == {"FINISHED"}
s = sc.soak_rain
if opts.get("--same-inputs") == "1":
    s.start_frame, s.end_frame, s.dry_time = 1, 120, 20.0
    if hasattr(s, "seconds_per_frame"):
        s.seconds_per_frame = 1.0 / 24.0
cached = os.path.isdir(os.path.join(cache, ".ripple-cache"))
c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
t0 = time.time()
assert bpy.ops.soak.bake_rain() == {"FINISHED"}
wall = time.time() - t0
c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = (c1.ru_utime + c1.ru_stime) - (c0.ru_utime + c0.ru_stime)
print(f"BENCH {opts.get('--label', 'run')} wall {wall:.2f} cpu {cpu:.2f} ripples_cached {int(cached)}")
