"""The Soak asset library (issue 46 item 6): one .blend holding a wet
material per preset of the core's export (soak_data.json, through the
add-on's Make Wet, Colours: Preset) and three combinations, each marked as
a material asset with a rendered preview (Cycles, a sphere on a ground
plane, PREVIEW px), tagged "Soak". Artists add the folder as an asset
library (Preferences > File Paths > Asset Libraries) and drag a material
onto an object; the materials carry their Soak Wet node group, so they
render without the add-on.

  SOAK_BLENDER=5.2 bash tests/blender/run_blender.sh scenes/blender/asset_library.py \
      --addon build/soak_blender.zip --out build/asset_library/soak_materials.blend [--preview 96]

(`make asset-library`.) Combinations (made by the panel's own settings):
- Wet asphalt with puddles: asphalt, Noise wetness source (scale 2), Puddle
  Level 0.55: the wetter patches stand as water;
- Wet brick in rain: brick, Noise source (scale 8), Wetness 0.8: patchy
  wetting of a wall in passing rain;
- Wet sand at a shoreline: sand, Noise source (scale 1.5), Puddle Level 0.7:
  broad wet and dry bands with standing water in the wettest."""
import math
import os
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon", "tools"))
import soak_install  # noqa: E402

PREVIEW = int(opts.get("--preview", 96))
COMBOS = (
    ("Wet asphalt with puddles", "asphalt", {"wetness_source": "NOISE", "noise_scale": 2.0}, {"puddle_level": 0.55}),
    ("Wet brick in rain", "brick", {"wetness_source": "NOISE", "noise_scale": 8.0}, {"group_wetness": 0.8}),
    ("Wet sand at a shoreline", "sand", {"wetness_source": "NOISE", "noise_scale": 1.5}, {"puddle_level": 0.7}),
)


def use_nodes(idblock):
    if bpy.app.version < (5, 0, 0) or idblock.node_tree is None:
        idblock.use_nodes = True
    return idblock.node_tree


def stage():
    """A sphere on a ground plane under a sun and a grey sky, framed
    close: the preview's scene."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.samples = 24
    sc.cycles.use_denoising = False
    sc.render.resolution_x = sc.render.resolution_y = PREVIEW
    sc.render.resolution_percentage = 100
    sc.render.film_transparent = False
    sc.render.image_settings.file_format = "PNG"
    world = bpy.data.worlds.new("Preview sky")
    bg = use_nodes(world).nodes["Background"]
    bg.inputs["Color"].default_value = (0.6, 0.65, 0.75, 1.0)
    bg.inputs["Strength"].default_value = 0.8
    sc.world = world
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (math.radians(40), 0, math.radians(30))
    sc.collection.objects.link(sun)
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    cam.location = (0, -3.2, 1.6)
    cam.rotation_euler = (math.radians(68), 0, 0)
    cam.data.lens = 50
    sc.collection.objects.link(cam)
    sc.camera = cam
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.7, location=(0, 0, 0.7), segments=48, ring_count=24)
    bpy.ops.object.shade_smooth()
    sphere = bpy.context.object
    sphere.name = "Preview sphere"
    bpy.ops.mesh.primitive_plane_add(size=6)
    ground = bpy.context.object
    ground.name = "Preview ground"
    return sc, sphere, ground


def make(sc, sphere, ground, name, preset, settings, controls):
    mat = bpy.data.materials.new(name)
    use_nodes(mat)
    for ob in (sphere, ground):
        ob.data.materials.clear()
        ob.data.materials.append(mat)
    bpy.context.view_layer.objects.active = sphere
    s = mat.soak
    s.preset = preset
    s.colour_source = "PRESET"
    for k, v in settings.items():
        setattr(s, k, v)
    if bpy.ops.soak.make_wet() != {"FINISHED"}:
        raise SystemExit(f"Make Wet failed on {name}: {s.status}")
    for k, v in controls.items():
        setattr(s, k, v)
    return mat


def render_preview(sc, mat):
    path = os.path.join(bpy.app.tempdir, "soak_preview.png")
    sc.render.filepath = path
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(path, check_existing=False)
    px = [0.0] * (4 * PREVIEW * PREVIEW)
    img.pixels.foreach_get(px)
    bpy.data.images.remove(img)
    mat.preview_ensure()
    mat.preview.image_size = (PREVIEW, PREVIEW)
    mat.preview.image_pixels_float.foreach_set(px)


def main():
    out = os.path.abspath(opts["--out"])
    os.makedirs(os.path.dirname(out), exist_ok=True)
    sc, sphere, ground = stage()              # factory settings first: they would drop the add-on
    soak_install.install(opts["--addon"])
    soak = sys.modules["soak"]
    entries = [(f"Wet {display}", preset, {}, {}) for preset, display, _kind in soak.data.preset_items()]
    mats = []
    for name, preset, settings, controls in list(entries) + list(COMBOS):
        mat = make(sc, sphere, ground, name, preset, settings, controls)
        render_preview(sc, mat)
        mat.asset_mark()
        mat.asset_data.description = (f"Soak: {preset} wetted by the core's model ({name}); "
                                      "renders without the add-on (the Soak Wet group is inside)")
        for tag in ("Soak", "wet", preset):
            mat.asset_data.tags.new(tag, skip_if_exists=True)
        mat.use_fake_user = True
        mats.append(mat)
        print(f"asset: {name}")
    for ob in (sphere, ground):
        ob.data.materials.clear()
    # only the materials (and what they use) go into the library
    tmp = out + ".tmp.blend"
    bpy.data.libraries.write(tmp, set(mats), fake_user=True, compress=True)
    os.replace(tmp, out)
    print(f"wrote {out}: {len(mats)} material assets")


main()
