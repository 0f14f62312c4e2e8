"""EEVEE against Cycles on one wet plane, in the Blender that runs it (3.4:
EEVEE, 4.2+: EEVEE Next), with the description of plane_cases.json (one
sun 30 degrees off the normal, black world, camera along the normal).

Per state (dry: Wetness 0, wet: Wetness 1; sand preset, Exact lookups, the
path EEVEE needs) and engine: L, the plane, and S, the same with a black base
colour (the specular and coat lobes); the diffuse part D = L - S.
Asserted:
  1. the diffuse part keeps its EEVEE/Cycles ratio when wet:
       |(D_E/D_C)_wet / (D_E/D_C)_dry - 1| <= 0.005/D_wet-albedo + 2 NOISE
     the dry ratio is the baseline (what EEVEE's sun shading differs by on
     this material, measured); a base colour EEVEE cannot read (the 4.2+
     black material) fails it by 100 %;
  2. the wet/dry ratio of the whole image, EEVEE against Cycles:
       |ratio_E / ratio_C - 1| <= sum over dry, wet of |S_E - S_C| / L_C
                                 + 2 NOISE
     the named term: EEVEE's specular for a sun (its LTC fit of GGX; split-
     sum only for world light, black here) is not Cycles' sampled GGX,
     measured from the black-base renders of each state.
NOISE: Cycles' 16 samples of a delta sun on a black world have no variance
in the direct diffuse; EEVEE's 4 anti-aliasing samples of a flat plane
neither; 0.5 % covers the EXR half/float round-off of the means."""
import json
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
ZIP, TMP = A["addon"], A["tmp"]
CASES = json.load(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "plane_cases.json")))
EEVEE = "BLENDER_EEVEE_NEXT" if bpy.app.version >= (4, 2, 0) else "BLENDER_EEVEE"
SIZE = 32
NOISE = 0.005
os.makedirs(TMP, exist_ok=True)


def mean(path):
    img = bpy.data.images.load(path, check_existing=False)
    px = list(img.pixels)
    bpy.data.images.remove(img)
    n = len(px) // 4
    c = [sum(px[k::4]) / n for k in range(3)]
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]


def scene():
    for coll in (bpy.data.objects, bpy.data.meshes, bpy.data.materials, bpy.data.lights, bpy.data.cameras,
                 bpy.data.worlds, bpy.data.node_groups, bpy.data.images):
        for item in list(coll):
            coll.remove(item)
    sc = bpy.context.scene
    sc.render.resolution_x = sc.render.resolution_y = SIZE
    sc.render.resolution_percentage = 100
    sc.render.image_settings.file_format = "OPEN_EXR"
    sc.render.image_settings.color_depth = "32"
    sc.view_settings.view_transform = "Standard"
    sc.cycles.device = "CPU"
    sc.cycles.samples = CASES["render"]["cycles_samples"]
    sc.cycles.use_denoising = False
    sc.cycles.seed = 1
    sc.eevee.taa_render_samples = 4
    world = bpy.data.worlds.new("W")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    sc.world = world
    cd = bpy.data.cameras.new("C")
    cd.sensor_fit = "VERTICAL"
    cd.angle_y = math.radians(CASES["camera"]["fov"])
    co = bpy.data.objects.new("C", cd)
    sc.collection.objects.link(co)
    co.location = CASES["camera"]["position"]
    sc.camera = co
    import mathutils
    d = mathutils.Vector(CASES["sun"]["direction"])
    ld = bpy.data.lights.new("S", "SUN")
    ld.energy = CASES["sun"]["irradiance"]
    ld.angle = 0.0
    lo = bpy.data.objects.new("S", ld)
    sc.collection.objects.link(lo)
    lo.rotation_euler = d.to_track_quat("Z", "Y").to_euler()
    bpy.ops.mesh.primitive_plane_add(size=2)
    plane = bpy.context.object
    mat = bpy.data.materials.new("M")
    mat.use_nodes = True
    plane.data.materials.append(mat)
    return sc, plane, mat


def render(sc, engine, tag):
    sc.render.engine = engine
    path = os.path.join(TMP, f"{tag}_{engine}.exr")
    sc.render.filepath = path
    bpy.ops.render.render(write_still=True)
    return mean(path)


def main():
    common.install_addon(ZIP)
    sc, plane, mat = scene()
    mat.soak.preset, mat.soak.liquid, mat.soak.colour_source = "sand", "water", "PRESET"
    mat.soak.exact_lookups = True
    bpy.context.view_layer.objects.active = plane
    if bpy.ops.soak.make_wet() != {"FINISHED"}:
        common.fail("make_wet")
    gn = mat.node_tree.nodes["Soak Wet"]
    colour = tuple(gn.inputs["Base Color"].default_value)
    res = {}
    for state, w in (("dry", 0.0), ("wet", 1.0)):
        gn.inputs["Wetness"].default_value = w
        for engine in ("CYCLES", EEVEE):
            gn.inputs["Base Color"].default_value = colour
            L = render(sc, engine, f"{state}_L")
            gn.inputs["Base Color"].default_value = (0, 0, 0, 1)
            S = render(sc, engine, f"{state}_S")
            res[state, engine] = (L, S, L - S)
            print(f"{state} {engine}: L {L:.5f}  S {S:.5f}  D {L - S:.5f}")
    failures = []
    base = {s: res[s, EEVEE][2] / res[s, "CYCLES"][2] for s in ("dry", "wet")}
    # the wet albedo of the preset colour: the diffuse part's size against E cos / pi
    d = CASES["sun"]["direction"]
    e_cos = CASES["sun"]["irradiance"] * d[2] / math.sqrt(sum(x * x for x in d)) / math.pi
    albedo_wet = res["wet", "CYCLES"][2] / e_cos
    tol1 = 0.005 / albedo_wet + 2 * NOISE
    rel1 = base["wet"] / base["dry"] - 1
    print(f"diffuse EEVEE/Cycles: dry {base['dry']:.4f} (baseline), wet {base['wet']:.4f}: {rel1:+.2%} "
          f"(tolerance {tol1:.2%})")
    if not abs(rel1) <= tol1:
        failures.append(f"diffuse part: EEVEE/Cycles wet {base['wet']:.4f} vs dry {base['dry']:.4f} "
                        f"({rel1:+.2%}, tolerance {tol1:.2%})")
    ratio = {e: res["wet", e][0] / res["dry", e][0] for e in ("CYCLES", EEVEE)}
    spec_term = sum(abs(res[s, EEVEE][1] - res[s, "CYCLES"][1]) / res[s, "CYCLES"][0] for s in ("dry", "wet"))
    tol2 = spec_term + 2 * NOISE
    rel2 = ratio[EEVEE] / ratio["CYCLES"] - 1
    print(f"wet/dry: Cycles {ratio['CYCLES']:.4f}, {EEVEE} {ratio[EEVEE]:.4f}: {rel2:+.2%} "
          f"(tolerance {tol2:.2%} = specular term {spec_term:.2%} + noise {2 * NOISE:.2%})")
    if not abs(rel2) <= tol2:
        failures.append(f"wet/dry {EEVEE} {ratio[EEVEE]:.4f} vs Cycles {ratio['CYCLES']:.4f} ({rel2:+.2%}, "
                        f"tolerance {tol2:.2%})")
    if failures:
        common.fail("; ".join(failures))
    print("PASS")


main()
