"""Cycles CPU time of a close-up plane with a textured Principled material,
in three states, runs interleaved (same scene, samples, resolution, one
render thread):

  dry      the user's material as it is;
  coat     the same material with the coat the wet state switches on
           (weight = the group's Coat Weight output, read back from a
           render of it), no group: what any wet look costs in Cycles;
  wet      after Make Wet (default or --exact 1 lookups), once per
           quality of --qualities (the panel's Quality; default BALANCED);
  coat noise  (--varying 1) the coat state with the wetness source's Noise
           texture evaluated too (its Fac x 1e-6 added to the coat weight,
           which Cycles cannot fold): what a texture-driven wet look costs
           before any of the group's work;
  wet DRAFT fold  (--fold 1) an experiment, not an add-on setting: Draft
           with the coat lobe dropped and the liquid's mirror folded into the
           base's own specular lobe (Coat Weight unlinked, Specular + coat
           weight x F0(liquid) / 0.08: the Principled's specular amount whose
           F0 is the liquid's, 3.x Specular and 4.x+ Specular IOR Level at
           IOR 1.5 alike), at the base's wet roughness instead of a mirror.

wet/dry is what an artist pays; wet/coat is the group's own cost (its
lookups and math). Prints each run, then min and median per state, and
the group's node count per quality. Not a test: nothing here asserts a time.

--varying 1: the wetness varies (the panel's Noise wetness source, a Noise
texture into the group's Wet Map: issue 46/50's "varying wetness"), so the
group reads its tables at every shading point.

blender -b --factory-startup --python bench_blender_overhead.py -- --addon ZIP [--repeat 3] [--exact 0|1]
    [--qualities DRAFT,BALANCED,EXACT] [--fold 0|1] [--varying 0|1]
(c_core/bench/bench_blender_overhead.sh runs it in Blender 3.4, 4.3 and 5.2)"""
import os
import statistics
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_bench_plane  # noqa: E402

opts = blender_bench_plane.options()
repeat = int(opts.get("--repeat", "3"))
exact = bool(int(opts.get("--exact", "0")))
qualities = opts.get("--qualities", "BALANCED").split(",")
fold = bool(int(opts.get("--fold", "0")))
varying = bool(int(opts.get("--varying", "0")))
COAT = ("Clearcoat", "Coat Weight")[bpy.app.version >= (4, 0, 0)]
mat, tree, bsdf = blender_bench_plane.textured_plane(opts["--addon"], exact)
if varying:
    mat.soak.wetness_source = "NOISE"


def coat_weight_of_wet_state():
    """The constant Coat Weight the group feeds the Principled (wetness is
    uniform here), read from the group's output by Blender itself."""
    bpy.ops.soak.make_wet()
    link = bsdf.inputs[COAT].links[0] if bsdf.inputs[COAT].is_linked else None
    gn = link.from_node if link is not None else None
    bpy.ops.soak.make_dry()
    if gn is None:
        return 0.0
    # the group's coverage at the material's wetness: the params table of the
    # export, looked up as the group does (soak_data.json through the add-on)
    data = sys.modules["soak"].data
    t = data.table(mat.soak.preset, mat.soak.liquid)
    rows = t["rows_below"] + t["rows_above"] + 1
    # wetness 0.6 sits above saturation for sand: linear rows there
    ws = t["saturation"]
    r = t["rows_below"] + (mat.soak.wetness - ws) / (1 - ws) * t["rows_above"] if mat.soak.wetness > ws else None
    if r is None:
        return float(t["params"][t["rows_below"]][10])
    r0 = min(int(r), rows - 2)
    f = r - r0
    return (1 - f) * float(t["params"][r0][10]) + f * float(t["params"][r0 + 1][10])


def render_cpu():
    t0 = time.process_time()
    bpy.ops.render.render()
    return time.process_time() - t0


def group_nodes():
    """Nodes of the Soak Wet group that compute (frames and group inputs
    and outputs left out)."""
    gn = next(n for n in tree.nodes if n.type == "GROUP")
    return sum(1 for n in gn.node_tree.nodes if n.type not in ("FRAME", "GROUP_INPUT", "GROUP_OUTPUT"))


def fold_coat_into_specular():
    """The experiment above, on the wet material Make Wet left."""
    gn = next(n for n in tree.nodes if n.type == "GROUP")
    spec_in = bsdf.inputs[("Specular", "Specular IOR Level")[bpy.app.version >= (4, 0, 0)]]
    for ln in list(bsdf.inputs[COAT].links) + list(spec_in.links):
        tree.links.remove(ln)
    bsdf.inputs[COAT].default_value = 0.0
    n = sys.modules["soak"].data.liquid(mat.soak.liquid)["ior"]
    f0 = ((n - 1) / (n + 1)) ** 2
    m = tree.nodes.new("ShaderNodeMath")
    m.operation = "MULTIPLY_ADD"
    m.name = "bench fold"
    tree.links.new(gn.outputs["Coat Weight"], m.inputs[0])
    m.inputs[1].default_value = f0 / 0.08
    tree.links.new(gn.outputs["Specular"], m.inputs[2])
    tree.links.new(m.outputs[0], spec_in)


def add_noise(coat):
    """The coat state plus the Noise source's evaluation (see above)."""
    noise = tree.nodes.new("ShaderNodeTexNoise")
    noise.name = "bench noise"
    noise.inputs["Scale"].default_value = mat.soak.noise_scale
    m = tree.nodes.new("ShaderNodeMath")
    m.operation = "MULTIPLY_ADD"
    m.name = "bench noise add"
    tree.links.new(noise.outputs["Fac"], m.inputs[0])
    m.inputs[1].default_value = 1e-6
    m.inputs[2].default_value = coat
    tree.links.new(m.outputs[0], bsdf.inputs[COAT])


def undo_noise():
    for name in ("bench noise", "bench noise add"):
        if tree.nodes.get(name) is not None:
            tree.nodes.remove(tree.nodes[name])


def undo_fold():
    m = tree.nodes.get("bench fold")
    if m is not None:
        tree.nodes.remove(m)


coat = coat_weight_of_wet_state()
states = (["dry", "coat"] + (["coat noise"] if varying else []) + [f"wet {q}" for q in qualities]
          + (["wet DRAFT fold"] if fold else []))
times = {s: [] for s in states}
count = {}
for r in range(repeat):
    for state in states:
        if state == "coat":
            bsdf.inputs[COAT].default_value = coat
        if state == "coat noise":
            add_noise(coat)
        if state.startswith("wet"):
            bsdf.inputs[COAT].default_value = 0.0
            mat.soak.quality = state.split()[1]
            bpy.ops.soak.make_wet()
            count[state] = group_nodes()
            if state.endswith("fold"):
                fold_coat_into_specular()
        times[state].append(render_cpu())
        undo_noise()
        if state.startswith("wet"):
            undo_fold()
            bpy.ops.soak.make_dry()
        print(f"run {r} {state}: {times[state][-1]:.3f} s CPU")
        sys.stdout.flush()
bsdf.inputs[COAT].default_value = 0.0
mins = {k: min(v) for k, v in times.items()}
meds = {k: statistics.median(v) for k, v in times.items()}
print(f"Blender {bpy.app.version_string}, exact lookups {int(exact)}, varying {int(varying)}, coat weight {coat:.3f}, "
      f"load average {os.getloadavg()[0]:.1f}")
for k in states:
    print(f"{k}: min {mins[k]:.3f} s, median {meds[k]:.3f} s CPU")
for k in [s for s in states if s.startswith("wet")]:
    print(f"ratio {k}/dry: min {mins[k] / mins['dry']:.3f}, median {meds[k] / meds['dry']:.3f}; "
          f"{k}/coat (the group's own cost): min {mins[k] / mins['coat']:.3f}, "
          f"median {meds[k] / meds['coat']:.3f}; {count[k]} nodes")
