"""Shared helpers of the Blender tests (run inside Blender)."""
import json
import os
import sys

import bpy


def args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    out = {}
    i = 0
    while i < len(argv):
        out[argv[i].lstrip("-")] = argv[i + 1]
        i += 2
    return out


def install_addon(zip_path):
    """Installs and enables the add-on from the built zip (like a user)."""
    if not os.path.isfile(zip_path):
        raise SystemExit(f"add-on zip not found: {zip_path} (make addon)")
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="soak")
    import soak  # noqa: F401
    assert hasattr(bpy.types.Material, "soak"), "add-on registered no Material.soak"
    return sys.modules["soak"]


def tree_state(tree):
    """A canonical description of a node tree: nodes, input values, links."""
    nodes = {}
    for n in tree.nodes:
        vals = {}
        for s in n.inputs:
            v = getattr(s, "default_value", None)
            if v is None:
                continue
            try:
                v = [round(float(x), 7) for x in v]
            except TypeError:
                v = round(float(v), 7) if isinstance(v, (int, float)) else str(v)
            vals[s.identifier] = v
        nodes[n.name] = {"type": n.bl_idname, "inputs": vals}
    links = sorted((l.from_node.name, l.from_socket.identifier, l.to_node.name, l.to_socket.identifier)
                   for l in tree.links)
    return json.dumps({"nodes": nodes, "links": links}, sort_keys=True)


def fail(msg):
    print("FAIL:", msg)
    raise SystemExit(1)


def plane_case_scene(cases, width, height):
    """The plane of plane_cases.json on an empty scene: black world, the
    camera along the normal, Cycles CPU with the cases' samples, no
    denoiser, seed 1, 32-bit EXR output in the Standard view transform.
    Returns (scene, plane, its node material)."""
    import math
    for coll in (bpy.data.objects, bpy.data.meshes, bpy.data.materials, bpy.data.lights, bpy.data.cameras,
                 bpy.data.worlds, bpy.data.node_groups, bpy.data.images):
        for item in list(coll):
            coll.remove(item)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.device = "CPU"
    sc.cycles.samples = cases["render"]["cycles_samples"]
    sc.cycles.use_denoising = False
    sc.cycles.seed = 1
    sc.render.resolution_x, sc.render.resolution_y = width, height
    sc.render.resolution_percentage = 100
    sc.render.image_settings.file_format = "OPEN_EXR"
    sc.render.image_settings.color_depth = "32"
    sc.view_settings.view_transform = "Standard"
    world = bpy.data.worlds.new("W")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    sc.world = world
    cd = bpy.data.cameras.new("C")
    cd.sensor_fit = "VERTICAL"
    cd.angle_y = math.radians(cases["camera"]["fov"])
    co = bpy.data.objects.new("C", cd)
    sc.collection.objects.link(co)
    co.location = cases["camera"]["position"]
    co.rotation_euler = (0, 0, 0)  # looking down -z, up +y
    sc.camera = co
    bpy.ops.mesh.primitive_plane_add(size=2)
    plane = bpy.context.object
    mat = bpy.data.materials.new("M")
    mat.use_nodes = True
    plane.data.materials.append(mat)
    return sc, plane, mat


def add_case_sun(sc, cases, back_lit=False):
    """The cases' sun (irradiance in W/m^2, a delta light); back_lit mirrors
    it below the plane."""
    import mathutils
    d = mathutils.Vector(cases["sun"]["direction"])
    if back_lit:
        d.z = -d.z
    ld = bpy.data.lights.new("S", "SUN")
    ld.energy = cases["sun"]["irradiance"]
    ld.angle = 0.0
    lo = bpy.data.objects.new("S", ld)
    sc.collection.objects.link(lo)
    # a sun shines along its local -z: rotate -z onto -d
    lo.rotation_euler = d.to_track_quat("Z", "Y").to_euler()
