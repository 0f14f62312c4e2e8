"""Where the Soak Wet group's Cycles time goes (issue 19's speed target).

The close-up textured plane of blender_bench_plane.py (Cycles CPU, one
render thread, 128x128, 64 samples, checker-textured Principled BSDF, sand
at wetness 0.6), rendered in these states, interleaved:

  dry              the user's material;
  wet              after Make Wet (the add-on as it is);
  wet_nobump       the group's Normal output unlinked (no Bump node);
  wet_nocoat       the Principled's coat input unlinked and 0;
  wet_nocolour     the group's Base Color output fed the dry colour directly
                   (no column program, no table lookups);
  wet_nospec       Specular and Roughness passed through (no parameter lookup);
  wet_lk3          the colour from three Linear lookups of the group's first
                   table image at one Vector Math coordinate each, summed:
                   the least any per-channel table lookup costs;
  wet_lk1          one such lookup;
  wet_vchain5      the colour through five Vector Math nodes (a closed form
                   of that size in place of the tables).

Not a test: nothing here asserts a time. Prints min and median CPU seconds
per state and their ratio to dry.

blender -b --factory-startup --python bench_blender_ablation.py -- --addon ZIP [--repeat 3] [--exact 0|1]"""
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
COAT = ("Clearcoat", "Coat Weight")[bpy.app.version >= (4, 0, 0)]
STATES = ("dry", "wet", "wet_nobump", "wet_nocoat", "wet_nocolour", "wet_nospec",
          "wet_lk3", "wet_lk1", "wet_vchain5")
mat, tree, bsdf = blender_bench_plane.textured_plane(opts["--addon"], exact)


class _Group:
    def __init__(self):
        gn = next(n for n in tree.nodes if n.type == "GROUP")
        self.g = gn.node_tree
        self.gin = next(n for n in self.g.nodes if n.type == "GROUP_INPUT")
        self.gout = next(n for n in self.g.nodes if n.type == "GROUP_OUTPUT")

    def unlink(self, sock):
        for link in list(sock.links):
            self.g.links.remove(link)

    def feed(self, out_name, socket):
        self.unlink(self.gout.inputs[out_name])
        self.g.links.new(socket, self.gout.inputs[out_name])

    def node(self, kind, **props):
        n = self.g.nodes.new(kind)
        for k, v in props.items():
            setattr(n, k, v)
        return n

    def vec(self, op, a, b):
        n = self.node("ShaderNodeVectorMath", operation=op)
        for i, x in enumerate((a, b)):
            if isinstance(x, tuple):
                n.inputs[i].default_value = x
            else:
                self.g.links.new(x, n.inputs[i])
        return n


def lookups(grp, k):
    image = next(n for n in grp.g.nodes if n.type == "TEX_IMAGE").image
    total = None
    for i in range(k):
        coord = grp.vec("MULTIPLY_ADD", grp.gin.outputs["Base Color"], ((1, 0, 0), (0, 1, 0), (1, 0, 0))[i])
        coord.inputs[2].default_value = (0.1, 0.2, 0.0)
        tex = grp.node("ShaderNodeTexImage", image=image, interpolation="Linear", extension="EXTEND")
        grp.g.links.new(coord.outputs[0], tex.inputs["Vector"])
        total = tex.outputs["Color"] if total is None else grp.vec("ADD", total, tex.outputs["Color"]).outputs[0]
    return total


def vector_chain(grp, k):
    v = grp.gin.outputs["Base Color"]
    for i in range(k - 1):
        n = grp.vec("MULTIPLY_ADD", v, (0.3 + 0.01 * i, 0.3, 0.3))
        n.inputs[2].default_value = (0.1, 0.1, 0.2)
        v = n.outputs[0]
    return grp.vec("DIVIDE", v, grp.gin.outputs["Base Color"]).outputs[0]


def make_state(name):
    bpy.ops.soak.make_wet()
    if name == "wet":
        return
    grp = _Group()
    if name == "wet_nobump":
        grp.unlink(grp.gout.inputs["Normal"])
    elif name == "wet_nocoat":
        for link in list(bsdf.inputs[COAT].links):
            tree.links.remove(link)
        bsdf.inputs[COAT].default_value = 0.0
    elif name == "wet_nocolour":
        grp.feed("Base Color", grp.gin.outputs["Base Color"])
    elif name == "wet_nospec":
        grp.feed("Specular", grp.gin.outputs["Specular"])
        grp.feed("Roughness", grp.gin.outputs["Roughness"])
    elif name in ("wet_lk3", "wet_lk1"):
        grp.feed("Base Color", lookups(grp, int(name[-1])))
    elif name == "wet_vchain5":
        grp.feed("Base Color", vector_chain(grp, 5))


def render_cpu():
    t0 = time.process_time()
    bpy.ops.render.render()
    return time.process_time() - t0


times = {s: [] for s in STATES}
for r in range(repeat):
    for s in STATES:
        if s != "dry":
            make_state(s)
        times[s].append(render_cpu())
        if s != "dry":
            bpy.ops.soak.make_dry()
        print(f"run {r} {s}: {times[s][-1]:.3f} s CPU", flush=True)
dmin, dmed = min(times["dry"]), statistics.median(times["dry"])
print(f"Blender {bpy.app.version_string}, exact lookups {int(exact)}")
for s in STATES:
    lo, med = min(times[s]), statistics.median(times[s])
    print(f"state {s:13s} min {lo:.3f} median {med:.3f} s CPU; /dry min {lo / dmin:.3f} median {med / dmed:.3f}")
