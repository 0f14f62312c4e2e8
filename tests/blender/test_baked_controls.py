"""A saved wet material's controls in a Blender without the add-on (issue 46
item 2): every input the Soak Wet node shows does what it shows.

Phase 1 (the add-on installed) makes two materials wet and saves the file:
  constant  sand in water, Quality Draft, Wetness 0.6, Base Color a value:
            the group is specialised to that one liquid amount
            (wet_constant: the liquid's inputs are folded into numbers);
  varying   sand in water, Quality Balanced, a Noise wetness source, Wetness
            0.6: the group is built for the liquid's inputs that only their
            values set (wet_bounds: folded), the Wet Map read live.
Phase 2 opens the saved file in a second Blender started with
--factory-startup (no add-on: a colleague, a render farm), checks that the
add-on is absent, and for each group node:
  - every input it shows (unlinked, not hidden, with a value) is changed and
    the group's outputs, rendered through an Emission shader by Cycles,
    change as the core says:
      Base Color  the wet colour of the new dry colour at the baked liquid
                  amount, against `soak albedo --material sand --wetness L
                  --base-colour R,G,B` (the core's chain): tolerance the
                  tables' 0.005 (SOAK_EXPORT_BASE_TOL) + 2e-4 float32
                  coordinates + Blender's curve sampling 2e-4
                  (test_specialise.py bounds it), Blender 4.x's coat
                  compensation taken out (1 / (1 - coat F0), as
                  test_group_values.py); Balanced and Exact times the view
                  factor at the camera's cosine 1 (the json export's knots);
      Roughness, Specular  scaled by the core's factors, which do not depend
                  on them: output(new) / output(old) = new / old (1e-4);
      Spill Edge  the bump at the wet map's edges: the Normal output moves;
      any other   some output changes (a shown control that does nothing fails);
  - every input it hides is one the group does not read, and the node's
    label names the folded liquid inputs with their values (the group shows
    itself as baked), e.g. "Soak Wet (baked: Wetness 0.6, ...)".
Phase 1 also checks that every computing node of both groups carries a
role label (what it computes) and that the stages sit in labelled frames.
Before the fix the node showed Wetness, Puddle Level, Schedule, ... and a
changed Wetness left the render unchanged (0.11408 -> 0.11408 in 5.2)."""
import json
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
PHASE = A.get("phase", "save")
N = 8
LIQUID_INPUTS = ("Wetness", "Wet Map", "Puddle Level", "Schedule", "Drying", "Time", "Start Time", "Fill Time")
COLOUR_TOL = 0.005 + 2e-4 + 2e-4
RATIO_TOL = 1e-4
DRY = (0.5, 0.35, 0.2)
NEW_DRY = (0.2, 0.45, 0.7)


def scene():
    return common.box_filtered_scene(N, N, 2.0)


def make(name, quality, source):
    bpy.ops.mesh.primitive_plane_add(size=2, location=(0, 0, 0))
    plane = bpy.context.object
    plane.name = name
    mat = bpy.data.materials.new(name)
    tree = common.use_nodes(mat)
    plane.data.materials.append(mat)
    bsdf = next(n for n in tree.nodes if n.type == "BSDF_PRINCIPLED")
    bsdf.inputs["Base Color"].default_value = DRY + (1.0,)
    s = mat.soak
    s.preset, s.liquid, s.quality, s.wetness, s.wetness_source = "sand", "water", quality, 0.6, source
    s.noise_scale = 3.0
    bpy.context.view_layer.objects.active = plane
    if bpy.ops.soak.make_wet() != {"FINISHED"}:
        common.fail(f"make_wet {name}")
    return mat


def save():
    common.install_addon(A["addon"])
    scene()
    made = {"constant": make("constant", "DRAFT", "CONSTANT"), "varying": make("varying", "BALANCED", "NOISE")}
    info = {}
    for key, mat in made.items():
        gn = mat.node_tree.nodes["Soak Wet"]
        tag = json.loads(gn.node_tree["soak_group"])
        info[key] = tag
        unlabelled = [n.name for n in gn.node_tree.nodes
                      if n.type not in ("FRAME", "GROUP_INPUT", "GROUP_OUTPUT") and not n.label]
        frames = [n.label for n in gn.node_tree.nodes if n.type == "FRAME"]
        print(key, len(gn.node_tree.nodes), "nodes; frames", frames, "; unlabelled", unlabelled)
        if unlabelled or not frames:
            common.fail(f"{key}: the group's computing nodes without a role label: {unlabelled}, frames {frames}")
        print(key, "group built for", tag.get("constant"), tag.get("varying"), "label", repr(gn.label))
    if info["constant"].get("constant") is None or info["varying"].get("varying") is None:
        common.fail(f"the materials are not specialised as the test needs: {info}")
    for o in bpy.data.objects:
        o.hide_render = True
    path = os.path.join(A["tmp"], "baked.blend")
    bpy.ops.wm.save_as_mainfile(filepath=path)
    out = subprocess.run([bpy.app.binary_path, "-b", "--factory-startup", path, "--python-exit-code", "1",
                          "--python", os.path.abspath(__file__), "--", "--phase", "check", "--soak", A["soak"],
                          "--tmp", A["tmp"]], capture_output=True, text=True, timeout=600)
    print("\n".join(x for x in out.stdout.splitlines() if not x.startswith(("Fra:", "Saved:", " Time:")) and x))
    print(out.stderr[-3000:])
    if out.returncode != 0 or "BAKED CONTROLS OK" not in out.stdout:
        common.fail(f"the saved file's controls without the add-on: exit {out.returncode}")


# ---- phase 2: no add-on ------------------------------------------------------

def render(sc, mat, gn, output):
    """The group's output through an Emission shader: the mean of the
    plane's pixels (constant) or all of them."""
    tree = mat.node_tree
    em = tree.nodes.get("test emission") or tree.nodes.new("ShaderNodeEmission")
    em.name = "test emission"
    tree.links.new(em.outputs[0], tree.nodes["Material Output"].inputs["Surface"])
    src = gn.outputs[output]
    if output in ("Roughness", "Specular", "Coat Weight", "Liquid"):
        comb = tree.nodes.get("test comb") or tree.nodes.new("ShaderNodeCombineXYZ")
        comb.name = "test comb"
        tree.links.new(src, comb.inputs[0])
        src = comb.outputs[0]
    tree.links.new(src, em.inputs["Color"])
    path = os.path.join(A["tmp"], "out.exr")
    sc.render.filepath = path
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(path, check_existing=False)
    px = list(img.pixels)
    bpy.data.images.remove(img)
    return [px[i:i + 3] for i in range(0, len(px), 4)]


def core_wet(liquid, rgb):
    out = subprocess.run([A["soak"], "albedo", "--material", "sand", "--liquid", "water", "--wetness", f"{liquid:.9g}",
                          "--base-colour", ",".join(f"{c:.9g}" for c in rgb)], capture_output=True, text=True)
    if out.returncode != 0:
        common.fail(f"soak albedo: {out.stderr}")
    line = next(x for x in out.stdout.splitlines() if x.startswith("wet albedo "))
    return [float(v) for v in line.split()[2:5]]


def view_factor(liquid):
    """Balanced and Exact: the wet colour times the view factor at the
    camera's cosine 1 (head-on), from `soak export --target json` (its knots'
    view_factor rows, last column: cos 1), linear between the knots."""
    path = os.path.join(A["tmp"], "export.json")
    out = subprocess.run([A["soak"], "export", "--target", "json", "-o", path], capture_output=True, text=True)
    if out.returncode != 0:
        common.fail(f"soak export --target json: {out.stderr}")
    ref = json.load(open(path))
    kn = next(m for m in ref["materials"] if m["name"] == "sand")["liquids"]["water"]["knots"]
    ws = kn["wetness"]
    for i in range(len(ws) - 1):
        if ws[i] <= liquid <= ws[i + 1]:
            f = (liquid - ws[i]) / (ws[i + 1] - ws[i]) if ws[i + 1] > ws[i] else 0.0
            a, b = kn["view_factor"][i][-1], kn["view_factor"][i + 1][-1]
            return [x + (y - x) * f for x, y in zip(a, b)]
    common.fail(f"liquid {liquid} outside the export's knots")


def coat_factor(sc, mat, gn, i):
    """Blender 4.x: the group divides Base Color by (1 - coat F0) so that
    the engine's own coat dimming is undone (compat.coat_base_compensation)."""
    if bpy.app.version < (4, 0, 0):
        return 1.0
    coat = render(sc, mat, gn, "Coat Weight")[i][0]
    f0 = ((1.333 - 1.0) / (1.333 + 1.0)) ** 2
    return 1.0 / (1.0 - coat * f0)


def differs(a, b, eps=1e-4):
    return any(abs(x - y) > eps for p, q in zip(a, b) for x, y in zip(p, q))


def outputs(sc, mat, gn):
    return {o: render(sc, mat, gn, o) for o in ("Base Color", "Roughness", "Specular", "Coat Weight", "Liquid",
                                                "Normal")}


def check_shown(sc, mat, gn, name, failures):
    sock = gn.inputs[name]
    before = outputs(sc, mat, gn)
    if name == "Base Color":
        tag = json.loads(gn.node_tree["soak_group"])
        from_tag = tag.get("constant")
        i = max(range(len(before["Liquid"])), key=lambda j: before["Liquid"][j][0])   # the wettest pixel
        liquid = before["Liquid"][i][0]
        sock.default_value = NEW_DRY + (1.0,)
        got = render(sc, mat, gn, "Base Color")[i]
        k = coat_factor(sc, mat, gn, i)
        vf = view_factor(liquid) if json.loads(gn.node_tree["soak_group"])["quality"] != "DRAFT" else [1.0] * 3
        want = [k * f * v for v, f in zip(core_wet(liquid, NEW_DRY), vf)]
        err = max(abs(g - w) for g, w in zip(got, want))
        print(f"  {mat.name} Base Color {NEW_DRY}: group {got}, core x coat factor {want} at liquid {liquid:.4f} "
              f"(baked {from_tag}): err {err:.5f} (tol {COLOUR_TOL})")
        if err > COLOUR_TOL:
            failures.append(f"{mat.name}: Base Color {NEW_DRY} gives {got}, the core {want}")
        return
    if name in ("Roughness", "Specular"):
        old = sock.default_value
        new = 0.25 if abs(old - 0.25) > 0.05 else 0.45
        sock.default_value = new
        got = render(sc, mat, gn, name)
        ratio = got[0][0] / before[name][0][0] if before[name][0][0] else float("nan")
        print(f"  {mat.name} {name} {old:.3f} -> {new:.3f}: output {before[name][0][0]:.5f} -> {got[0][0]:.5f}, "
              f"ratio {ratio:.5f} (want {new / old:.5f})")
        if not abs(ratio - new / old) <= RATIO_TOL * max(1.0, new / old):
            failures.append(f"{mat.name}: {name} {old} -> {new} scales its output by {ratio}, not {new / old}")
        return
    old = sock.default_value
    sock.default_value = 1.0 if name == "Spill Edge" else (old * 0.5 if old else 0.5)
    after = outputs(sc, mat, gn)
    changed = [o for o in after if differs(before[o], after[o])]
    print(f"  {mat.name} {name} {old} -> {sock.default_value}: outputs changed {changed}")
    if name == "Spill Edge" and "Normal" not in changed:
        failures.append(f"{mat.name}: Spill Edge shown but the normal does not move")
    if not changed:
        failures.append(f"{mat.name}: the input '{name}' is shown but changing it changes nothing")
    sock.default_value = old


def check_hidden(mat, gn, hidden, failures):
    tag = json.loads(gn.node_tree["soak_group"])
    folded = tag.get("constant") or (tag.get("varying") or {}).get("fixed") or {}
    print(f"  {mat.name}: hidden {hidden}, label {gn.label!r}")
    for name in hidden:
        if name in LIQUID_INPUTS and name not in folded:
            failures.append(f"{mat.name}: '{name}' is hidden but the group reads it")
    if any(name in LIQUID_INPUTS for name in hidden) and "baked" not in gn.label:
        failures.append(f"{mat.name}: liquid inputs hidden but the node is not labelled as baked: {gn.label!r}")
    wet = folded.get("Wetness")
    if wet is not None and f"Wetness {wet:.3g}" not in gn.label:
        failures.append(f"{mat.name}: the label {gn.label!r} does not give the baked Wetness {wet:.3g}")


def check():
    if hasattr(bpy.types.Material, "soak") or "soak" in sys.modules:
        common.fail("the add-on is loaded in the --factory-startup Blender")
    sc = bpy.context.scene
    failures = []
    for name in ("constant", "varying"):
        mat = bpy.data.materials[name]
        for o in bpy.data.objects:
            o.hide_render = o.name != name
        gn = mat.node_tree.nodes["Soak Wet"]
        shown = [s.name for s in gn.inputs if not s.hide and not s.is_linked and not s.hide_value]
        hidden = [s.name for s in gn.inputs if s.hide]
        print(f"{name}: shown {shown}")
        check_hidden(mat, gn, hidden, failures)
        for inp in shown:
            check_shown(sc, mat, gn, inp, failures)
    for f in failures:
        print("FAIL:", f)
    if failures:
        sys.exit(1)
    print("BAKED CONTROLS OK")


if PHASE == "save":
    os.makedirs(A["tmp"], exist_ok=True)
    save()
else:
    check()
