"""Cycles CPU time of the ripples (issue 37): the benchmark plane
(blender_bench_plane.py: sand at wetness 0.6, 128x128, 64 samples, one
thread) after Make Wet and the add-on's Rain wiring (soak.rain.wire) of a
wet map that floods the whole plane (0.8, Puddle Level 0.6) and the ripple
flipbooks (sharp and --far, blended by view distance), in four states run
interleaved:

  wet      the wiring with the ripple normal unlinked from the group (the
           wet map still drives the wetness; Cycles compiles no unlinked node);
  sharp    the ripples without the far flipbook (the sharp one straight into
           the Normal Map node: no far lookup, no distance blend);
  ripples  the whole wiring: flipbooks, distance blend, normal map, flood mix;
  near     the wiring Bake Rain makes for an object all nearer than the far
           ripples' start (rain.RippleView reach NEAR): the sharp flipbook
           alone, no far lookup, no blend (re-wired each round, outside the
           timed render).

Prints each run, min and median per state, the ratio ripples/wet, and the
rain nodes. Not a test: nothing here asserts a time.

blender -b --factory-startup --python bench_blender_ripples.py -- --addon ZIP --frames DIR [--repeat 5]
(c_core/bench/bench_blender_ripples.sh bakes DIR and runs it in Blender 3.4, 4.3 and 5.2)"""
import os
import statistics
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_bench_plane  # noqa: E402

opts = blender_bench_plane.options()
repeat = int(opts.get("--repeat", "5"))
frames = os.path.abspath(opts["--frames"])
mat, tree, bsdf = blender_bench_plane.textured_plane(opts["--addon"], False)
rain = sys.modules[next(m for m in sys.modules if m.endswith("soak.rain"))]


def sequence(name):
    img = bpy.data.images.load(os.path.join(frames, name), check_existing=False)
    img.source = "SEQUENCE"
    img.colorspace_settings.name = "Non-Color"
    return img


bpy.ops.soak.make_wet()
gn = next(n for n in tree.nodes if n.type == "GROUP")
gn.inputs["Puddle Level"].default_value = 0.6
ob = bpy.context.object
images = [sequence(n) for n in ("wet.0001.exr", "ripples.0000.exr", "ripples_far.0000.exr")]


def wire(reach):
    """The add-on's wiring for a reach (rain.ripple_reach's choice, forced
    here): BAND both flipbooks and the blend, NEAR the sharp one alone."""
    near, far = rain.far_distances(bpy.context.scene)
    rain.wire(mat, images[0], 1, 1, images[1], 64, 1, 8.0, ob.data.uv_layers[0].name, images[2],
              rain.RippleView(near, far, reach))
    rain.sync_level(mat)


wire(rain.BAND)
source = gn.inputs["Normal"].links[0].from_socket
nm = next(n for n in rain.rain_nodes(tree) if n.type == "NORMAL_MAP")
sharp_tex = next(n for n in rain.rain_nodes(tree) if n.type == "TEX_IMAGE" and "far" not in n.label)
blend = nm.inputs["Color"].links[0].from_socket
band_kinds = sorted(n.bl_idname for n in rain.rain_nodes(tree))


def render_cpu():
    t0 = time.process_time()
    bpy.ops.render.render()
    return time.process_time() - t0


states = ("wet", "sharp", "ripples", "near")
times = {s: [] for s in states}
for r in range(repeat):
    for state in states:
        if state == "wet":
            for link in list(gn.inputs["Normal"].links):
                tree.links.remove(link)
        elif state == "near":
            wire(rain.NEAR)
        else:
            tree.links.new(source, gn.inputs["Normal"])
            tree.links.new(sharp_tex.outputs["Color"] if state == "sharp" else blend, nm.inputs["Color"])
        times[state].append(render_cpu())
        print(f"run {r} {state}: {times[state][-1]:.3f} s CPU", flush=True)
    near_kinds = sorted(n.bl_idname for n in rain.rain_nodes(tree))
    wire(rain.BAND)
    source = gn.inputs["Normal"].links[0].from_socket
    nm = next(n for n in rain.rain_nodes(tree) if n.type == "NORMAL_MAP")
    sharp_tex = next(n for n in rain.rain_nodes(tree) if n.type == "TEX_IMAGE" and "far" not in n.label)
    blend = nm.inputs["Color"].links[0].from_socket
mins = {k: min(v) for k, v in times.items()}
meds = {k: statistics.median(v) for k, v in times.items()}
print(f"Blender {bpy.app.version_string}, load average {os.getloadavg()[0]:.1f}, "
      f"{len(band_kinds)} rain nodes (blend): {', '.join(band_kinds)}; "
      f"{len(near_kinds)} (near only): {', '.join(near_kinds)}")
for k in states:
    print(f"{k}: min {mins[k]:.3f} s, median {meds[k]:.3f} s CPU")
for k in ("sharp", "ripples", "near"):
    print(f"ratio {k}/wet: min {mins[k] / mins['wet']:.3f}, median {meds[k] / meds['wet']:.3f}")
