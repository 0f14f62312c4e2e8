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


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon", "tools"))
import soak_install  # noqa: E402  (blender_addon/tools/soak_install.py; not on the path of soak/)


def install_addon(zip_path):
    """Installs and enables the add-on from the built zip as a user of the
    running Blender does (an add-on in 3.x, an extension in 4.2+); the
    module is `soak` (sys.modules) in every version."""
    return soak_install.install(zip_path)[0]


def preferences():
    """The installed add-on's preferences (after install_addon)."""
    return soak_install.preferences()


def fcurves(id_data):
    """The F-curves animating id_data, read the way each Blender stores
    them (independently of the add-on's compat.py): the action's list up to
    4.x, the assigned slot's channel bag in 5.x (Blender's own
    bpy_extras.anim_utils)."""
    ad = id_data.animation_data
    if ad is None or ad.action is None:
        return []
    if bpy.app.version < (5, 0, 0):
        return list(ad.action.fcurves)
    from bpy_extras import anim_utils
    bag = anim_utils.action_get_channelbag_for_slot(ad.action, ad.action_slot)
    return list(bag.fcurves) if bag is not None else []


def find_fcurve(id_data, path):
    return next((fc for fc in fcurves(id_data) if fc.data_path == path and fc.array_index == 0), None)


def use_nodes(idblock):
    """Gives a material or world its node tree: Use Nodes before 5.0; 5.x
    data always use nodes (setting use_nodes is deprecated there)."""
    if bpy.app.version < (5, 0, 0) or idblock.node_tree is None:
        idblock.use_nodes = True
    return idblock.node_tree


def eevee_engine():
    """EEVEE's engine id as each Blender names it (release notes: EEVEE Next
    in 4.2, renamed back in 5.0)."""
    return "BLENDER_EEVEE_NEXT" if (4, 2, 0) <= bpy.app.version < (5, 0, 0) else "BLENDER_EEVEE"


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


def load_pixels(path):
    """An image file's pixels as Blender gives them (RGBA rows, bottom row first)."""
    img = bpy.data.images.load(path, check_existing=False)
    px = list(img.pixels)
    bpy.data.images.remove(img)
    return px


def render_lum(sc, path):
    """Renders scene sc to path (EXR) and returns the image's mean Rec. 709 luminance."""
    sc.render.filepath = path
    bpy.ops.render.render(write_still=True)
    px = load_pixels(path)
    n = len(px) // 4
    return sum(0.2126 * px[4 * i] + 0.7152 * px[4 * i + 1] + 0.0722 * px[4 * i + 2] for i in range(n)) / n


def fail(msg):
    print("FAIL:", msg)
    raise SystemExit(1)


def make_check(quiet=False):
    """(check, checks): check(cond, msg) fails the test with msg unless cond,
    and otherwise records msg in the list checks (and prints it unless quiet)."""
    checks = []

    def check(cond, msg):
        if not cond:
            fail(msg)
        checks.append(msg)
        if not quiet:
            print("ok:", msg)
    return check, checks


def ortho_exr_camera(sc, width, height, ortho_scale, z=3.0):
    """sc renders width x height 32-bit EXR in the Standard view through an
    orthographic camera at (0, 0, z) looking down, ortho_scale wide."""
    sc.render.resolution_x, sc.render.resolution_y = width, height
    sc.render.resolution_percentage = 100
    sc.render.image_settings.file_format = "OPEN_EXR"
    sc.render.image_settings.color_depth = "32"
    sc.view_settings.view_transform = "Standard"
    cd = bpy.data.cameras.new("C")
    cd.type = "ORTHO"
    cd.ortho_scale = ortho_scale
    co = bpy.data.objects.new("C", cd)
    sc.collection.objects.link(co)
    co.location = (0, 0, z)
    sc.camera = co


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
    use_nodes(world)
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
    use_nodes(mat)
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


def box_filtered_scene(width, height, ortho_scale):
    """The current scene emptied of objects, materials and meshes, set to one
    Cycles sample, no denoising and a box filter narrower than a pixel (each
    pixel sees its own centre), rendered through ortho_exr_camera."""
    for coll in (bpy.data.objects, bpy.data.materials, bpy.data.meshes):
        for item in list(coll):
            coll.remove(item)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.samples = 1
    sc.cycles.use_denoising = False
    sc.cycles.pixel_filter_type = "BOX"
    sc.cycles.filter_width = 0.01
    ortho_exr_camera(sc, width, height, ortho_scale)
    return sc
