"""Makes the blend file an artist would submit to the Soak Drying Animation
job: a 2 x 2 plane seen from above by an orthographic camera that covers it
exactly (SIZE x SIZE pixels, one pixel per wet-map texel), lit by a sun with
a zero angle and a black world (direct light only: no Monte Carlo noise from
the light), a grey Principled material made wet by the add-on's Make Wet with
the Image wetness source (a placeholder map, all wet: the farm job points the
source at the baked sequence). Cycles, few samples, no denoiser, a pixel
filter narrower than a pixel, the wet map read with Closest interpolation,
PNG 16-bit, Standard view transform.

blender -b --factory-startup --python make_blend.py -- --addon ZIP --out FILE.blend --size N
"""
import os
import sys

import bpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "blender"))
import common  # noqa: E402  (tests/blender/common.py: install_addon, args)


def main():
    a = common.args()
    size = int(a["size"])
    common.install_addon(a["addon"])
    for ob in list(bpy.data.objects):
        bpy.data.objects.remove(ob)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.device = "CPU"
    sc.cycles.samples = 4
    sc.cycles.use_denoising = False
    sc.cycles.use_adaptive_sampling = False
    sc.cycles.filter_width = 0.01
    sc.cycles.seed = 1
    sc.render.resolution_x = sc.render.resolution_y = size
    sc.render.resolution_percentage = 100
    sc.render.image_settings.file_format = "PNG"
    sc.render.image_settings.color_depth = "16"
    sc.render.image_settings.color_mode = "RGB"
    sc.view_settings.view_transform = "Standard"
    sc.frame_start, sc.frame_end = 1, 4
    world = bpy.data.worlds.new("Black")
    common.use_nodes(world)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    sc.world = world

    bpy.ops.mesh.primitive_plane_add(size=2.0)
    plane = bpy.context.active_object
    mat = bpy.data.materials.new("Ground")
    common.use_nodes(mat)
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (0.5, 0.5, 0.5, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.6
    plane.data.materials.append(mat)
    plane.active_material_index = 0

    placeholder = bpy.data.images.new("wet_placeholder", size, size, float_buffer=True)
    placeholder.pixels[:] = [1.0] * (4 * size * size)
    placeholder.pack()
    mat.soak.wetness_source = "IMAGE"
    mat.soak.wet_map = placeholder
    if bpy.ops.soak.make_wet() != {"FINISHED"}:
        common.fail("Make Wet did not finish")
    sources = [n for n in mat.node_tree.nodes if n.bl_idname == "ShaderNodeTexImage" and n.get("soak_role") == "source"]
    if len(sources) != 1:
        common.fail(f"expected one tagged image source after Make Wet, found {len(sources)}")
    # one texel per pixel, read without blending in its neighbours
    sources[0].interpolation = "Closest"

    cam_data = bpy.data.cameras.new("Cam")
    cam_data.type = "ORTHO"
    cam_data.ortho_scale = 2.0
    cam = bpy.data.objects.new("Cam", cam_data)
    cam.location = (0.0, 0.0, 3.0)
    sc.collection.objects.link(cam)
    sc.camera = cam
    sun_data = bpy.data.lights.new("Sun", "SUN")
    sun_data.energy = 3.0
    sun_data.angle = 0.0
    sun = bpy.data.objects.new("Sun", sun_data)
    sun.rotation_euler = (0.5, 0.0, 0.3)
    sc.collection.objects.link(sun)
    bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(a["out"]))
    print("saved", a["out"])


main()
