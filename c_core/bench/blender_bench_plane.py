"""The scene both Blender add-on benchmarks render (bench_blender_overhead.py,
bench_blender_ablation.py): the add-on installed from --addon, Cycles CPU
with one render thread, 128x128, 64 samples, no denoiser, a 4 m plane filling
the view with a checker-textured Principled BSDF, sand at wetness 0.6."""
import os
import sys

import bpy


def options():
    """The script's `-- --key value` arguments."""
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    return dict(zip(argv[::2], argv[1::2]))


def textured_plane(addon, exact):
    """Sets the scene up; returns (material, its node tree, its Principled BSDF)."""
    bpy.ops.preferences.addon_install(filepath=os.path.abspath(addon), overwrite=True)
    bpy.ops.preferences.addon_enable(module="soak")
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.samples = 64
    sc.cycles.use_denoising = False
    sc.render.threads_mode = "FIXED"   # (sc.cycles.threads_mode, an alias, is gone in 5.x)
    sc.render.threads = 1
    sc.render.resolution_x = sc.render.resolution_y = 128
    for o in list(bpy.data.objects):
        if o.type == "MESH":
            bpy.data.objects.remove(o)
    bpy.ops.mesh.primitive_plane_add(size=4)
    mat = bpy.data.materials.new("M")
    mat.use_nodes = True
    bpy.context.object.data.materials.append(mat)
    tree = mat.node_tree
    bsdf = next(n for n in tree.nodes if n.type == "BSDF_PRINCIPLED")
    tree.links.new(tree.nodes.new("ShaderNodeTexChecker").outputs["Color"], bsdf.inputs["Base Color"])
    sc.camera.location = (0, 0, 5)
    sc.camera.rotation_euler = (0, 0, 0)
    mat.soak.preset, mat.soak.wetness = "sand", 0.6
    mat.soak.exact_lookups = exact
    return mat, tree, bsdf
