"""Blender helper of bench_render_vs_cycles.sh: builds the Cycles equivalent of a
soak scene JSON (camera, sun, constant sky, wet plane, wet scattering spheres) and
renders it at a list of sample counts, timing each bpy.ops.render.render call.

  blender -b --factory-startup --python-exit-code 1 --python cycles_render_scene.py -- \
      SCENE.json OUTDIR THREADS SUN_SCALE REF_SPP:SEED SPP:SEED ...
  blender ... --python cycles_render_scene.py -- --calibrate SCENE.json OUT.exr THREADS
  blender ... --python cycles_render_scene.py -- --export-sphere OUT.obj

--export-sphere writes the UV sphere this script renders (unit radius, at the origin,
smooth vertex normals) as OBJ, so that soak traces the very same triangles.
A job "SPP:0" (seed 0) is a warm-up render, neither written nor reported: it takes
Cycles' one-time initialisation out of the timed renders of a session.

Writes OUTDIR/cycles_<spp>_<seed>.exr (linear RGBA float) and prints
"CYCLES_SCRIPT_START <epoch s>" then one "CYCLES_RENDER <spp> <seed> <wall s> <CPU s>"
per render (render call only: scene sync, BVH build and path tracing; file writing
excluded; CPU = user + system of all the process's threads, time.process_time()).

--calibrate renders a white Lambert plane lit by the scene's sun alone, seen from
straight above (radiance E cos(theta)/pi if Cycles' sun strength is an irradiance in
W/m^2); the shell compares it with soak's render of the same setup.

Only the subset of the scene format used by the benchmark scenes (scenes/bench_wet_sphere.json,
bench_wet_paper.json, bench_wet_puddles.json) is translated: sun lights, a constant
environment, `plane`, `quad`, `box` and `sphere` objects, constant wetness 1 or a wetness
`map` (an Image Texture over the object's UVs mixing the dry base and the wet material:
soak shades the dry/wet mixture with the map's value as weight, render_mix.c, as Cycles
mixes the closures), `lambert` materials and `wet` materials with a lambert or homogeneous
medium base (two HG lobes become one with the same mean cosine). Anything else is an
error (the benchmark must not silently compare different scenes).

Material equivalences (Cycles has no layered film; "equivalent" = same look to first
order and a comparable sampling cost):
- wet over Lambert -> Mix(Fresnel(n_film)) of a Diffuse BSDF and a sharp Glossy BSDF.
  The diffuse colour is Lekner & Dorf's film-darkened albedo
  A (1 - r_i) / (1 - A r_i) divided by (1 - r_e), where r_i / r_e are the
  cosine-weighted hemispherical Fresnel reflectances of the film seen from inside /
  outside (the (1 - F) mix weight already removes the view-side Fresnel loss; the
  light-side one is not modelled).
- wet over a medium -> Principled BSDF, subsurface weight 1, "Random Walk (Fixed
  Radius)", specular F0 of the film (Specular = F0 / 0.08), roughness 0. Cycles
  derives sigma_t = 1 / (d (1 - g)) with d = radius * 0.25/pi for that method, and
  the single-scattering albedo from the colour through a fit (Chiang et al. 2016 /
  Wrenninge et al., intern/cycles/kernel/integrator/subsurface_random_walk.h); we
  invert both so that Cycles walks with the scene's sigma_t, sigma_s/sigma_t and g.
  (Written for Blender 3.4; the 4.x input names are handled, but 4.x's radius
  scaling has not been checked here.) Differences that remain: Cycles enters the medium with a cosine-distributed
  direction (no refraction at n = 1.5), exits through a diffuse lobe, and turns the
  walk into a plain diffuse bounce after a diffuse bounce.
"""
import json
import math
import os
import sys
import time

import bpy
from mathutils import Matrix, Vector

print("CYCLES_SCRIPT_START %.6f" % time.time(), flush=True)


def fail(msg):
    raise SystemExit("cycles_render_scene.py: " + msg)


def rgb(v):
    return [float(v)] * 3 if isinstance(v, (int, float)) else [float(x) for x in v]


def set_input(node, names, value):
    """Principled inputs were renamed in Blender 4.0: try each name."""
    for n in names:
        if n in node.inputs:
            node.inputs[n].default_value = value
            return
    fail("Principled BSDF has none of the inputs %s" % (names,))


def fresnel_dielectric(cos_i, eta):
    """Unpolarised Fresnel reflectance for relative index eta = n_t / n_i."""
    s2 = (1 - cos_i * cos_i) / (eta * eta)
    if s2 >= 1:
        return 1.0
    cos_t = math.sqrt(1 - s2)
    rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t)
    rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t)
    return 0.5 * (rs * rs + rp * rp)


def hemispherical_fresnel(eta, n=4000):
    """Cosine-weighted hemispherical reflectance 2 int F(mu) mu dmu (midpoint rule)."""
    return sum(2 * fresnel_dielectric((i + 0.5) / n, eta) * (i + 0.5) / n / n for i in range(n))


def cycles_alpha(A, g):
    """Cycles' single-scattering albedo from the subsurface colour A (the fit of
    subsurface_random_walk_remap, Blender 3.x)."""
    g2, g3, g4, g5, g6, g7 = g**2, g**3, g**4, g**5, g**6, g**7
    a = (1.8260523782 - 1.28451056436 * g - 1.79904629312 * g2 + 9.19393289202 * g3
         - 22.8215585862 * g4 + 32.0234874259 * g5 - 23.6264803333 * g6 + 7.21067002658 * g7)
    b = 4.98511194385 + 0.127355959438 * math.exp(
        31.1491581433 * g - 201.847017512 * g2 + 841.576016723 * g3 - 2018.09288505 * g4
        + 2731.71560286 * g5 - 1935.41424244 * g6 + 559.009054474 * g7)
    c = (1.09686102424 - 0.394704063468 * g + 1.05258115941 * g2 - 8.83963712726 * g3
         + 28.8643230661 * g4 - 46.8802913581 * g5 + 38.5402837518 * g6 - 12.7181042538 * g7)
    d = (0.496310210422 + 0.360146581622 * g - 2.15139309747 * g2 + 17.8896899217 * g3
         - 55.2984010333 * g4 + 82.065982243 * g5 - 58.5106008578 * g6 + 15.8478295021 * g7)
    e = 4.23190299701 + 0.00310603949088 * math.exp(
        76.7316253952 * g - 594.356773233 * g2 + 2448.8834203 * g3 - 5576.68528998 * g4
        + 7116.60171912 * g5 - 4763.54467887 * g6 + 1303.5318055 * g7)
    f = (2.40602999408 - 2.51814844609 * g + 9.18494908356 * g2 - 79.2191708682 * g3
         + 259.082868209 * g4 - 403.613804597 * g5 + 302.85712436 * g6 - 87.4370473567 * g7)
    blend = A ** 0.25
    return (1 - blend) * a * math.atan(b * A) ** c + blend * d * math.atan(e * A) ** f


def colour_for_alpha(alpha, g):
    lo, hi = 0.0, 1.0  # the fit increases with A: bisection
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if cycles_alpha(mid, g) < alpha:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def setup_render(scene, sc, threads, width=None, height=None):
    r = sc.get("render", {})
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.use_denoising = False
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.sample_clamp_direct = 0.0  # no clamping: soak does not clamp
    scene.cycles.sample_clamp_indirect = 0.0
    scene.cycles.blur_glossy = 0.0
    depth = int(r.get("max_depth", 256))
    for attr in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces"):
        setattr(scene.cycles, attr, depth)
    scene.cycles.volume_bounces = 0
    if hasattr(scene.cycles, "pixel_filter_type"):
        scene.cycles.pixel_filter_type = "BOX"  # soak: box filter, one pixel
    scene.cycles.filter_width = 1.0
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads
    scene.render.resolution_x = int(width or r.get("width", 256))
    scene.render.resolution_y = int(height or r.get("height", 192))
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    st = scene.render.image_settings
    st.file_format = "OPEN_EXR"
    st.color_depth = "32"
    st.color_mode = "RGBA"


def add_camera(scene, position, look_at, up, fov_deg):
    pos, tgt, up = Vector(position), Vector(look_at), Vector(up)
    fwd = (tgt - pos).normalized()
    right = fwd.cross(up)
    if right.length < 1e-9:
        fail("camera.up is parallel to the view direction")
    right.normalize()
    cup = right.cross(fwd)
    cam = bpy.data.cameras.new("cam")
    cam.sensor_fit = "VERTICAL"  # soak's fov is vertical
    cam.angle_y = math.radians(fov_deg)
    cam.clip_start, cam.clip_end = 1e-3, 1e5
    obj = bpy.data.objects.new("cam", cam)
    # Blender cameras look down -Z with +Y up.
    m = Matrix((right, cup, -fwd)).transposed()
    obj.matrix_world = Matrix.Translation(pos) @ m.to_4x4()
    scene.collection.objects.link(obj)
    scene.camera = obj


def add_sun(scene, direction, irradiance, scale):
    e = [x * scale for x in rgb(irradiance)]
    strength = max(e)
    sun = bpy.data.lights.new("sun", "SUN")
    sun.energy = strength
    sun.color = [x / strength for x in e] if strength > 0 else [1, 1, 1]
    sun.angle = 0.0  # delta light like soak's sun (Blender's default is 0.53 degrees)
    obj = bpy.data.objects.new("sun", sun)
    # A sun shines along its local -Z: local +Z must point towards the sun.
    obj.rotation_euler = Vector((0, 0, 1)).rotation_difference(Vector(direction).normalized()).to_euler()
    scene.collection.objects.link(obj)


def set_world(scene, env):
    world = bpy.data.worlds.new("world")
    scene.world = world
    world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    if env is None:
        bg.inputs["Strength"].default_value = 0.0
        return
    if env.get("type") != "constant":
        fail("environment type '%s' is not translated" % env.get("type"))
    bg.inputs["Color"].default_value = rgb(env["radiance"]) + [1.0]
    bg.inputs["Strength"].default_value = 1.0


def new_material(name):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nt = mat.node_tree
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    return mat, nt, out


def lambert_material(name, albedo):
    mat, nt, out = new_material(name)
    d = nt.nodes.new("ShaderNodeBsdfDiffuse")
    d.inputs["Color"].default_value = rgb(albedo) + [1.0]
    nt.links.new(d.outputs[0], out.inputs["Surface"])
    return mat


def wet_lambert_nodes(nt, albedo, n_film):
    """The wet-over-Lambert closure in node tree nt; returns its output socket."""
    r_e = hemispherical_fresnel(n_film)
    r_i = hemispherical_fresnel(1.0 / n_film)
    colour = [a * (1 - r_i) / (1 - a * r_i) / (1 - r_e) for a in rgb(albedo)]
    fres = nt.nodes.new("ShaderNodeFresnel")
    fres.inputs["IOR"].default_value = n_film
    diff = nt.nodes.new("ShaderNodeBsdfDiffuse")
    diff.inputs["Color"].default_value = colour + [1.0]
    gloss = nt.nodes.new("ShaderNodeBsdfGlossy")
    gloss.inputs["Roughness"].default_value = 0.0
    gloss.inputs["Color"].default_value = [1, 1, 1, 1]
    mix = nt.nodes.new("ShaderNodeMixShader")
    nt.links.new(fres.outputs[0], mix.inputs[0])
    nt.links.new(diff.outputs[0], mix.inputs[1])
    nt.links.new(gloss.outputs[0], mix.inputs[2])
    print("wet lambert: diffuse colour %s (r_i %.4f, r_e %.4f)" % (colour, r_i, r_e))
    return mix.outputs[0]


def wet_lambert_material(name, albedo, n_film):
    mat, nt, out = new_material(name)
    nt.links.new(wet_lambert_nodes(nt, albedo, n_film), out.inputs["Surface"])
    return mat


def wet_medium_material(name, base, n_film):
    for k in base:
        if k not in ("type", "sigma_s", "sigma_a", "g1", "g2", "w", "ior"):
            fail("materials.%s.base.%s is not translated" % (name, k))
    w = float(base.get("w", 1.0))
    g1 = float(base.get("g1", 0.0))
    g2 = float(base.get("g2", g1))
    g = w * g1 + (1 - w) * g2  # Cycles has one HG lobe: keep the mean cosine
    ss, sa = rgb(base["sigma_s"]), rgb(base["sigma_a"])
    st = [s + a for s, a in zip(ss, sa)]
    colour = [colour_for_alpha(s / t, g) for s, t in zip(ss, st)]
    radius = [4 * math.pi / (t * (1 - g)) for t in st]  # d = radius/(4 pi) = 1/(sigma_t (1-g))
    mat, nt, out = new_material(name)
    p = nt.nodes.new("ShaderNodeBsdfPrincipled")
    # 3.x "Random Walk (Fixed Radius)" is called "Random Walk" from 4.0 on.
    methods = p.bl_rna.properties["subsurface_method"].enum_items.keys()
    p.subsurface_method = "RANDOM_WALK_FIXED_RADIUS" if "RANDOM_WALK_FIXED_RADIUS" in methods else "RANDOM_WALK"
    if "Subsurface Scale" in p.inputs:  # 4.x: multiplies the radius (default 0.05)
        p.inputs["Subsurface Scale"].default_value = 1.0
    set_input(p, ("Base Color",), colour + [1.0])
    if "Subsurface Color" in p.inputs:  # Blender < 4.0; 4.x uses the base colour
        p.inputs["Subsurface Color"].default_value = colour + [1.0]
    set_input(p, ("Subsurface", "Subsurface Weight"), 1.0)
    set_input(p, ("Subsurface Radius",), radius)
    set_input(p, ("Subsurface Anisotropy",), g)
    if "Specular" in p.inputs:  # 3.x: F0 = 0.08 Specular
        p.inputs["Specular"].default_value = ((n_film - 1) / (n_film + 1)) ** 2 / 0.08
    else:  # 4.x: F0 from the IOR input, level 0.5 = unchanged
        set_input(p, ("IOR",), n_film)
        set_input(p, ("Specular IOR Level",), 0.5)
    set_input(p, ("Roughness",), 0.0)
    nt.links.new(p.outputs[0], out.inputs["Surface"])
    print("material %s: subsurface colour %s, radius %s, g %.3f" % (name, colour, radius, g))
    return mat


def wet_map_material(name, m, image_path):
    """Mix(dry base, wet material) by the wetness map (soak: wet with probability = map)."""
    if m["base"]["type"] != "lambert":
        fail("materials.%s: a wetness map is translated over a lambert base only" % name)
    mat, nt, out = new_material(name + "_map")
    tex = nt.nodes.new("ShaderNodeTexImage")
    tex.image = bpy.data.images.load(image_path)
    tex.image.colorspace_settings.name = "Non-Color"
    tex.interpolation = "Closest"  # soak reads the nearest pixel
    dry = nt.nodes.new("ShaderNodeBsdfDiffuse")
    dry.inputs["Color"].default_value = rgb(m["base"]["albedo"]) + [1.0]
    wet = wet_lambert_nodes(nt, m["base"]["albedo"], float(m.get("film", {}).get("ior", 1.33)))
    mix = nt.nodes.new("ShaderNodeMixShader")
    nt.links.new(tex.outputs["Color"], mix.inputs[0])
    nt.links.new(dry.outputs[0], mix.inputs[1])
    nt.links.new(wet, mix.inputs[2])
    nt.links.new(mix.outputs[0], out.inputs["Surface"])
    print("material %s: wetness map %s mixing dry lambert and the wet one" % (mat.name, image_path))
    return mat


def make_material(name, m):
    t = m.get("type")
    if t == "lambert":
        return lambert_material(name, m["albedo"])
    if t != "wet":
        fail("material type '%s' is not translated" % t)
    film = m.get("film", {})
    n_film = float(film.get("ior", 1.33))
    base = m["base"]
    if base["type"] == "lambert":
        return wet_lambert_material(name, base["albedo"], n_film)
    if base["type"] == "medium":
        return wet_medium_material(name, base, n_film)
    fail("wet base type '%s' is not translated" % base["type"])


def add_quad(origin, eu, ev):
    o, u, v = Vector(origin), Vector(eu), Vector(ev)
    me = bpy.data.meshes.new("quad")
    me.from_pydata([o, o + u, o + u + v, o + v], [], [(0, 1, 2, 3)])
    uv = me.uv_layers.new(name="UVMap")
    for loop, co in zip(me.loops, ((0, 0), (1, 0), (1, 1), (0, 1))):
        uv.data[loop.index].uv = co
    obj = bpy.data.objects.new("quad", me)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def object_material(o, mats, sc_dir, i, materials):
    wet = o.get("wetness", 1)
    if isinstance(wet, (int, float)) and wet == 1:
        return mats[o["material"]]
    if isinstance(wet, dict) and wet.get("type") == "map":
        path = os.path.join(sc_dir, wet["file"])
        return wet_map_material(o["material"], materials[o["material"]], path)
    fail("objects[%d].wetness: only a constant 1 or a map is translated" % i)


def add_object(scene, o, mats, i, sc_dir=".", materials=None):
    for k in o:
        if k not in ("type", "material", "wetness", "center", "radius", "normal", "size", "min", "max", "origin",
                     "edge_u", "edge_v"):
            fail("objects[%d].%s is not translated" % (i, k))
    mat = object_material(o, mats, sc_dir, i, materials or {})
    if o["type"] == "quad":
        obj = add_quad(o["origin"], o["edge_u"], o["edge_v"])
    elif o["type"] == "box":
        lo, hi = Vector(o["min"]), Vector(o["max"])
        bpy.ops.mesh.primitive_cube_add(size=1.0, location=(lo + hi) / 2)
        obj = bpy.context.active_object
        obj.scale = hi - lo
        bpy.ops.object.transform_apply(scale=True)  # the walk sees true distances
    elif o["type"] == "sphere":
        bpy.ops.mesh.primitive_uv_sphere_add(segments=SPHERE_SEGMENTS, ring_count=SPHERE_RINGS, radius=float(o["radius"]),
                                             location=o["center"])
        obj = bpy.context.active_object
        bpy.ops.object.shade_smooth()
    elif o["type"] == "plane":
        w, d = (float(x) for x in o["size"])
        bpy.ops.mesh.primitive_plane_add(size=1.0, location=o["center"])
        obj = bpy.context.active_object
        obj.scale = (w, d, 1)
        obj.rotation_euler = Vector((0, 0, 1)).rotation_difference(Vector(o["normal"]).normalized()).to_euler()
    else:
        fail("object type '%s' is not translated" % o["type"])
    obj.data.materials.append(mat)


SPHERE_SEGMENTS, SPHERE_RINGS = 192, 96


def export_sphere(path):
    bpy.ops.mesh.primitive_uv_sphere_add(segments=SPHERE_SEGMENTS, ring_count=SPHERE_RINGS, radius=1.0)
    obj = bpy.context.active_object
    bpy.ops.object.shade_smooth()
    me = obj.data
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("# Blender %s UV sphere, %d segments x %d rings, radius 1, smooth normals\n"
                % (bpy.app.version_string, SPHERE_SEGMENTS, SPHERE_RINGS))
        for v in me.vertices:
            f.write("v %.9f %.9f %.9f\n" % tuple(v.co))
        for v in me.vertices:
            f.write("vn %.9f %.9f %.9f\n" % tuple(v.normal))
        for p in me.polygons:
            f.write("f " + " ".join("%d//%d" % (i + 1, i + 1) for i in p.vertices) + "\n")
    os.replace(tmp, path)
    print("CYCLES_SPHERE %d vertices %d faces" % (len(me.vertices), len(me.polygons)))


def render_to(scene, path):
    """Renders and saves; returns the render call's (wall, CPU) seconds. CPU is the
    process's CPU clock (user + system of every thread: Cycles' workers, sync, BVH),
    which other jobs on a shared machine do not inflate as they do the wall time."""
    t0, c0 = time.perf_counter(), time.process_time()
    bpy.ops.render.render(write_still=False)
    t1, c1 = time.perf_counter(), time.process_time()
    bpy.data.images["Render Result"].save_render(path, scene=scene)
    return t1 - t0, c1 - c0


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    if args[0] == "--export-sphere":
        export_sphere(args[1])
        return
    if args[0] == "--calibrate":
        scene_path, out_path, threads = args[1], args[2], int(args[3])
        sc = json.load(open(scene_path))
        setup_render(scene, sc, threads, 32, 24)
        scene.cycles.samples = 16
        sun = sc["lights"][0]
        add_camera(scene, [0, 0, 10], [0, 0, 0], [0, 1, 0], 5)
        d = sun["direction"]  # a sun from below is mirrored above (units only), as the shell does
        add_sun(scene, [d[0], d[1], abs(d[2])], sun["irradiance"], 1.0)
        set_world(scene, None)
        bpy.ops.mesh.primitive_plane_add(size=100.0)
        bpy.context.active_object.data.materials.append(lambert_material("white", 1.0))
        print("CYCLES_CALIBRATE %.3f" % render_to(scene, out_path)[0])
        return
    scene_path, outdir, threads, sun_scale = args[0], args[1], int(args[2]), float(args[3])
    sc = json.load(open(scene_path))
    setup_render(scene, sc, threads)
    cam = sc["camera"]
    if float(cam.get("aperture", 0)) != 0:
        fail("camera.aperture: thin lens is not translated")
    add_camera(scene, cam["position"], cam["look_at"], cam.get("up", [0, 0, 1]), float(cam.get("fov", 40)))
    for light in sc.get("lights", []):
        if light["type"] not in ("sun", "directional"):
            fail("light type '%s' is not translated" % light["type"])
        add_sun(scene, light["direction"], light["irradiance"], sun_scale)
    set_world(scene, sc.get("environment"))
    mats = {name: make_material(name, m) for name, m in sc["materials"].items()}
    for i, o in enumerate(sc["objects"]):
        add_object(scene, o, mats, i, os.path.dirname(os.path.abspath(scene_path)), sc["materials"])
    for job in args[4:]:
        spp, seed = (int(x) for x in job.split(":"))
        scene.cycles.samples = spp
        scene.cycles.seed = seed
        if seed == 0:  # warm-up
            bpy.ops.render.render(write_still=False)
            continue
        wall, cpu = render_to(scene, "%s/cycles_%d_%d.exr" % (outdir, spp, seed))
        print("CYCLES_RENDER %d %d %.4f %.4f" % (spp, seed, wall, cpu), flush=True)


main()
