"""Renders a wet plane in Cycles (add-on installed from the zip) and with
`soak render` from one description (plane_cases.json) and compares the
mean radiance of the view (the plane fills it) and the wet/dry ratio.

Tolerances (derivation in blender_addon/README.md, "Error against the
reference"):
  ratio wet/dry:  |r_blender / r_soak - 1| <= RATIO_TOL
  absolute:       |L_blender / L_soak - 1| <= ABS_TOL
The Principled BSDF is a Lambertian diffuse lobe under a GGX specular lobe;
soak render traces the preset's scattering medium under its film. The two
differ by the angular distribution of light leaving the medium (a diffusion
profile is not Lambertian) and by the 3.4 clearcoat (fixed IOR 1.5, 1/4
weight) standing in for the liquid film's specular."""
import json
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
SOAK, ZIP, TMP = A["soak"], A["addon"], A["tmp"]
CASES = json.load(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "plane_cases.json")))
RATIO_TOL = float(A.get("ratio_tol", 0.10))
ABS_TOL = float(A.get("abs_tol", 0.20))
os.makedirs(TMP, exist_ok=True)


def mean_exr(path):
    img = bpy.data.images.load(path, check_existing=False)
    px = list(img.pixels)
    w, h = img.size
    bpy.data.images.remove(img)
    s = [0.0, 0.0, 0.0]
    for i in range(w * h):
        for c in range(3):
            s[c] += px[4 * i + c]
    return [x / (w * h) for x in s]


def soak_render(name, material, back_lit=False):
    sun = dict(CASES["sun"])
    if back_lit:
        sun["direction"] = [sun["direction"][0], sun["direction"][1], -sun["direction"][2]]
    t = CASES["slab_thickness_m"] if material.get("name") not in ("paper",) else 0.0008
    scene = {
        "render": {"width": CASES["render"]["width"], "height": CASES["render"]["height"],
                   "spp": CASES["render"]["soak_spp"], "max_depth": 256},
        "camera": CASES["camera"],
        "lights": [{"type": "sun", "direction": sun["direction"], "irradiance": sun["irradiance"]}],
        "materials": {"m": material},
        "objects": [{"type": "box", "min": [-1, -1, -t], "max": [1, 1, 0], "material": "m"}],
    }
    js = os.path.join(TMP, name + ".json")
    exr = os.path.join(TMP, name + "_soak.exr")
    with open(js, "w") as f:
        json.dump(scene, f)
    r = subprocess.run([SOAK, "render", js, "-o", exr, "--threads", "2"], capture_output=True, text=True)
    if r.returncode != 0:
        common.fail(f"soak render {js}: {r.stderr.strip()}")
    return mean_exr(exr)


def setup_scene():
    for coll in (bpy.data.objects, bpy.data.meshes, bpy.data.materials, bpy.data.lights, bpy.data.cameras,
                 bpy.data.worlds, bpy.data.node_groups, bpy.data.images):
        for item in list(coll):
            coll.remove(item)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.device = "CPU"
    sc.cycles.samples = CASES["render"]["cycles_samples"]
    sc.cycles.use_denoising = False
    sc.render.resolution_x = CASES["render"]["width"]
    sc.render.resolution_y = CASES["render"]["height"]
    sc.render.resolution_percentage = 100
    sc.render.image_settings.file_format = "OPEN_EXR"
    sc.render.image_settings.color_depth = "32"
    sc.view_settings.view_transform = "Standard"
    sc.cycles.seed = 1
    world = bpy.data.worlds.new("W")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    sc.world = world
    cam = CASES["camera"]
    cd = bpy.data.cameras.new("C")
    cd.sensor_fit = "VERTICAL"
    import math
    cd.angle_y = math.radians(cam["fov"])
    co = bpy.data.objects.new("C", cd)
    sc.collection.objects.link(co)
    co.location = cam["position"]
    co.rotation_euler = (0, 0, 0)  # looking down -z, up +y
    sc.camera = co
    bpy.ops.mesh.primitive_plane_add(size=2)
    plane = bpy.context.object
    mat = bpy.data.materials.new("M")
    mat.use_nodes = True
    plane.data.materials.append(mat)
    return sc, plane, mat


def add_sun(sc, back_lit=False):
    import mathutils
    d = mathutils.Vector(CASES["sun"]["direction"])
    if back_lit:
        d.z = -d.z
    ld = bpy.data.lights.new("S", "SUN")
    ld.energy = CASES["sun"]["irradiance"]
    ld.angle = 0.0
    lo = bpy.data.objects.new("S", ld)
    sc.collection.objects.link(lo)
    # a sun shines along its local -z: rotate -z onto -d
    lo.rotation_euler = d.to_track_quat("Z", "Y").to_euler()


def blender_render(sc, name):
    path = os.path.join(TMP, name + "_blender.exr")
    sc.render.filepath = path
    bpy.ops.render.render(write_still=True)
    return mean_exr(path)


def lum(c):
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]


def main():
    common.install_addon(ZIP)
    rows, failures = [], []

    def case(name, preset, wetness, liquid="water", back_lit=False, metallic=0.0):
        sc, plane, mat = setup_scene()
        add_sun(sc, back_lit)
        bsdf = mat.node_tree.nodes["Principled BSDF"]
        bsdf.inputs["Metallic"].default_value = metallic
        mat.soak.preset = preset
        mat.soak.liquid = liquid
        mat.soak.colour_source = "PRESET"
        mat.soak.wetness = wetness
        bpy.context.view_layer.objects.active = plane
        assert bpy.ops.soak.make_wet() == {"FINISHED"}
        lb = blender_render(sc, name)
        ls = soak_render(name, {"type": "preset", "name": preset, "wetness": wetness, "liquid": liquid,
                                "unit_mm": 1000}, back_lit)
        return lb, ls

    def check(label, got, want, tol):
        rel = got / want - 1.0 if want > 0 else float("inf")
        ok = abs(rel) <= tol
        if not ok:
            failures.append(f"{label}: blender {got:.5f} vs soak {want:.5f} ({rel:+.1%}, tol {tol:.0%})")
        return rel

    for p in CASES["presets"] + [CASES["metal"]]:
        metallic = 1.0 if p == CASES["metal"] else 0.0
        lb0, ls0 = case(f"{p}_dry", p, 0.0, metallic=metallic)
        rows.append((p, 0.0, lum(lb0), lum(ls0), check(f"{p} dry", lum(lb0), lum(ls0), ABS_TOL), 0.0))
        for w in CASES["wetness_levels"]:
            lb, ls = case(f"{p}_{w}", p, w, metallic=metallic)
            ra = check(f"{p} w={w} absolute", lum(lb), lum(ls), ABS_TOL)
            rr = check(f"{p} w={w} wet/dry", lum(lb) / lum(lb0), lum(ls) / lum(ls0), RATIO_TOL)
            rows.append((p, w, lum(lb), lum(ls), ra, rr))
    ts = CASES["thin_sheet"]
    for w in ts["wetness"]:
        lb, ls = case(f"paper_back_{w}", ts["preset"], w, back_lit=True)
        rows.append((ts["preset"] + " back-lit", w, lum(lb), lum(ls), check(f"paper back-lit w={w}", lum(lb), lum(ls), ABS_TOL), 0.0))
    print("\n| preset | wetness | Cycles | soak render | absolute | wet/dry ratio |")
    print("|---|---|---|---|---|---|")
    for p, w, lb, ls, ra, rr in rows:
        print(f"| {p} | {w} | {lb:.4f} | {ls:.4f} | {ra:+.1%} | {rr:+.1%} |")
    if failures:
        common.fail("; ".join(failures))
    print("PASS")


main()
