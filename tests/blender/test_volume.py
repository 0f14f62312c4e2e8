"""Import Wet Volume: a `soak bake volume` OpenVDB file becomes a Volume
object with its medium wired; it renders (a lit slab of the sand medium in
front of a black world is visible, finite and coloured like sand: red > blue),
and a file that is not a soak volume is reported."""
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
common.install_addon(A["addon"])
os.makedirs(A["tmp"], exist_ok=True)
prefix = os.path.join(A["tmp"], "sand")
r = subprocess.run([A["soak"], "bake", "volume", "--material", "sand", "--dims", "16,16,8", "--size", "0.1,0.1,0.05",
                    "--format", "vdb", "-o", prefix], capture_output=True, text=True)
if r.returncode != 0:
    common.fail(f"soak bake volume: {r.stderr}")
for o in list(bpy.data.objects):
    if o.type == "MESH":
        bpy.data.objects.remove(o)
if bpy.ops.soak.import_volume(filepath=prefix + ".vdb") != {"FINISHED"}:
    common.fail("import_volume")
ob = next(o for o in bpy.data.objects if o.type == "VOLUME")
sc = bpy.context.scene
sc.render.engine = "CYCLES"
sc.cycles.samples = 16
sc.cycles.use_denoising = False
sc.cycles.volume_bounces = 4
sc.render.resolution_x = sc.render.resolution_y = 16
sc.render.image_settings.file_format = "OPEN_EXR"
sc.view_settings.view_transform = "Standard"
w = bpy.data.worlds.new("black")
sc.world = w
cd = bpy.data.cameras.new("TopCam")
cd.type = "ORTHO"
cd.ortho_scale = 0.06
cam = bpy.data.objects.new("TopCam", cd)
sc.collection.objects.link(cam)
cam.location = (0.05, 0.05, 1.0)
sc.camera = cam
ld = bpy.data.lights.new("Sun", "SUN")
ld.energy = 3.0
sun = bpy.data.objects.new("Sun", ld)
sc.collection.objects.link(sun)
path = os.path.join(A["tmp"], "volume.exr")
sc.render.filepath = path
bpy.ops.render.render(write_still=True)
img = bpy.data.images.load(path)
px = list(img.pixels)
n = len(px) // 4
mean = [sum(px[4 * i + c] for i in range(n)) / n for c in range(3)]
print("volume render mean", mean)
if not all(v == v and abs(v) < 1e6 for v in px):
    common.fail("non-finite pixels")
if not (mean[0] > 0.01 and mean[0] > mean[2]):
    common.fail(f"the sand volume does not render as a lit, reddish medium: {mean}")

bad = os.path.join(A["tmp"], "not_a_volume.vdb")
with open(bad, "w") as f:
    f.write("not vdb")
try:
    bpy.ops.soak.import_volume(filepath=bad)
    common.fail("a broken file was imported")
except RuntimeError as e:
    if "not an OpenVDB file" not in str(e) and "not a soak bake volume" not in str(e):
        common.fail(f"unclear error: {e}")
    print("reported:", str(e).strip())
print("PASS")
