"""The seed scenes of the physics sources as a Blender gallery, built from
scratch (no .blend) with the Soak add-on's operators, as an artist would:
build a dry material, set the Wetness panel, Make Wet. Where the other two
columns of docs/gallery.md (scenes/gallery/*.json, POV-Ray) share geometry or a
baked map (the relief, the pot, the glass, the drying splash, the relief's
rain), the scene takes the same: the same profile, helper (_module) or `soak`
command (_soak), so the three columns show one scene.

  wet_paper_front / wet_paper_back  [JLD99] sec. 4.1, Fig. 5
  beach_rock                        [JLD99] sec. 4.2, Fig. 6 (four states in one picture)
  cognac_table                      [JLD99] sec. 4.3, Fig. 7
  bricks_drying                     [Hnat06] sec. 3.3 / Fig. 6 (drying, four frames)
  bas_relief_rain                   [Hnat06] sec. 3.3.1 / Fig. 7 (rain bake with sky exposure)
  flowerpot_porosity                [Hnat06] Fig. 5 (alpha_poro sweep: clay_p00 ... clay_p50)
  film_copper                       [Lag13] (films over a dielectric ground; copper under water)
  film_thickness                    [Lag13] (film depths 0, 0.5 mm, 50 cm: concrete_f0 ... copper_f500)

flowerpot_porosity and film_thickness need the presets scenes/gallery/variants.txt
adds: install the zip scenes/blender/variant_addon.py makes (make gallery does).

Each build function empties the file, builds its scene and returns a list of
renders: (name, [frames]); several frames are tiled 2 x 2 into one picture
by render_all.py. Run through render_all.py."""
import atexit
import importlib.util
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

import bmesh
import bpy
from mathutils import Vector

try:
    import numpy as np
except ImportError:   # Debian 13's blender package has no numpy (Blender's own builds bundle it)
    np = None

NUMPY_SCENES = ("wet_paper_front", "wet_paper_back", "beach_rock", "cognac_table")
REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def _module(relpath):
    """A helper of the other columns (scenes/gallery/meshes.py, the POV-Ray
    gallery's relief_mesh.py): the same geometry and maps in all three."""
    spec = importlib.util.spec_from_file_location(os.path.basename(relpath)[:-3], os.path.join(REPO, relpath))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _soak(*args):
    """Runs the soak tool (the add-on's preference, then PATH), as the other
    columns' scripts do for their bakes."""
    prefs = next((m for k, m in sys.modules.items() if k.endswith("soak.preferences")), None)
    exe = prefs.find_soak() if prefs else shutil.which("soak")
    if not exe:
        raise RuntimeError("soak executable not found: render_all.py --soak PATH, or put it on PATH")
    r = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"soak {args[0]} {args[1]} failed (exit {r.returncode}): {r.stderr.strip()[-400:]}")
    return r.stdout


def _workdir():
    """A folder for the bakes and meshes a scene reads from disk while it
    renders (kept until Blender exits, then removed: image sequences are read
    per frame)."""
    path = tempfile.mkdtemp(prefix="soak_seeds_")
    atexit.register(shutil.rmtree, path, True)
    return path

# ---------------------------------------------------------------- scene set-up


def _reset():
    for coll in (bpy.data.objects, bpy.data.meshes, bpy.data.materials, bpy.data.lights, bpy.data.cameras,
                 bpy.data.worlds, bpy.data.node_groups, bpy.data.images, bpy.data.textures, bpy.data.curves):
        for item in list(coll):
            if getattr(item, "type", "") != "RENDER_RESULT":
                coll.remove(item)
    sc = bpy.context.scene
    if "soak_inset" in sc:             # render_all.py's inset belongs to the scene that set it
        del sc["soak_inset"]
    sc.render.engine = "CYCLES"
    cy = sc.cycles
    cy.use_denoising = False          # Debian's Blender has no OpenImageDenoise
    cy.use_adaptive_sampling = True
    cy.adaptive_threshold = 0.02
    cy.max_bounces, cy.diffuse_bounces, cy.glossy_bounces = 8, 3, 4
    cy.transmission_bounces, cy.transparent_max_bounces = 8, 8
    cy.sample_clamp_indirect = 3.0     # no fireflies from the film's mirror of the sun
    cy.blur_glossy = 1.0
    cy.caustics_reflective = cy.caustics_refractive = False
    cy.seed = 1
    sc.render.filter_size = 1.5
    sc.render.dither_intensity = 0.0   # dither noise does not compress (PNG size)
    sc.render.resolution_percentage = 100
    sc.render.film_transparent = False
    sc.render.image_settings.file_format = "PNG"
    sc.render.image_settings.color_mode = "RGB"
    sc.render.image_settings.color_depth = "8"
    sc.render.image_settings.compression = 100
    sc.view_settings.view_transform = "Filmic"
    for look in ("Medium High Contrast", "Filmic - Medium High Contrast", "None"):  # 4.x prefixes looks
        try:
            sc.view_settings.look = look
            break
        except TypeError:
            continue
    sc.view_settings.exposure = 0.0
    sc.frame_start, sc.frame_end = 1, 1
    sc.frame_set(1)
    return sc


def _sky(sc, zenith=(0.06, 0.17, 0.55), horizon=(0.75, 0.78, 0.8), ground=(0.12, 0.11, 0.1), strength=0.6):
    """A gradient sky (HDR-like: bright horizon, blue zenith, dark ground)."""
    w = bpy.data.worlds.new("Sky")
    w.use_nodes = True
    nt = w.node_tree
    coord = nt.nodes.new("ShaderNodeTexCoord")
    sep = nt.nodes.new("ShaderNodeSeparateXYZ")
    ramp = nt.nodes.new("ShaderNodeValToRGB")
    nt.links.new(coord.outputs["Generated"], sep.inputs[0])
    # Generated in a world is the view direction: z in [-1, 1] -> [0, 1]
    mr = nt.nodes.new("ShaderNodeMapRange")
    mr.inputs["From Min"].default_value = -1.0
    nt.links.new(sep.outputs["Z"], mr.inputs["Value"])
    nt.links.new(mr.outputs["Result"], ramp.inputs["Fac"])
    el = ramp.color_ramp.elements
    el[0].position, el[0].color = 0.0, (*ground, 1)
    el[1].position, el[1].color = 1.0, (*zenith, 1)
    e = el.new(0.49)
    e.color = (*[0.6 * g + 0.4 * h for g, h in zip(ground, horizon)], 1)
    e = el.new(0.505)
    e.color = (*horizon, 1)
    e = el.new(0.62)
    e.color = (*[0.5 * h + 0.5 * z for h, z in zip(horizon, zenith)], 1)
    bg = nt.nodes["Background"]
    nt.links.new(ramp.outputs["Color"], bg.inputs["Color"])
    bg.inputs["Strength"].default_value = strength
    sc.world = w
    return w


def _hdri(sc, name, strength=1.0, rotation=0.0):
    """One of Blender's own CC0 world HDRIs (Poly Haven; datafiles/studiolights/world,
    Debian's blender-data) as the world, oriented as soak render's "environment"
    map with "hdri": NAME (scenes/README.md): Cycles' equirectangular mapping, the
    image's centre at azimuth `rotation` degrees, so the vector is turned by
    -rotation about Z. SOAK_HDRI_DIR names another folder, as for soak render."""
    folder = os.environ.get("SOAK_HDRI_DIR") or bpy.utils.system_resource("DATAFILES", path="studiolights/world")
    path = os.path.join(folder or "", name + ".exr")
    if not os.path.isfile(path):
        raise RuntimeError(f"HDRI {path} not found: Blender's world HDRIs come with Debian's blender-data "
                           "package (installed by the README's set-up), or set SOAK_HDRI_DIR")
    w = bpy.data.worlds.new("HDRI " + name)
    w.use_nodes = True
    nt = w.node_tree
    coord = nt.nodes.new("ShaderNodeTexCoord")
    mapping = nt.nodes.new("ShaderNodeMapping")
    mapping.inputs["Rotation"].default_value = (0.0, 0.0, math.radians(-rotation))
    env = nt.nodes.new("ShaderNodeTexEnvironment")
    env.image = bpy.data.images.load(path, check_existing=True)
    nt.links.new(coord.outputs["Generated"], mapping.inputs["Vector"])
    nt.links.new(mapping.outputs["Vector"], env.inputs["Vector"])
    bg = nt.nodes["Background"]
    nt.links.new(env.outputs["Color"], bg.inputs["Color"])
    bg.inputs["Strength"].default_value = strength
    sc.world = w
    return w


def _sun(sc, elevation, azimuth, strength=3.0, angle=2.0, colour=(1.0, 0.96, 0.9)):
    """A sun at `elevation` degrees above the horizon, shining from `azimuth`
    degrees (0 = from +y, the camera usually looks along +y, 90 = from +x)."""
    ld = bpy.data.lights.new("Sun", "SUN")
    ld.energy = strength
    ld.angle = math.radians(angle)
    ld.color = colour
    lo = bpy.data.objects.new("Sun", ld)
    sc.collection.objects.link(lo)
    el, az = math.radians(elevation), math.radians(azimuth)
    to_sun = Vector((math.sin(az) * math.cos(el), math.cos(az) * math.cos(el), math.sin(el)))
    lo.rotation_euler = to_sun.to_track_quat("Z", "Y").to_euler()
    return lo


def _sun_to(sc, direction, irradiance, angle=1.0):
    """soak render's sun: `direction` towards the sun, `irradiance` W/m^2
    (a number or RGB) on a surface facing it, which is a Cycles sun's
    strength (docs: environment notes)."""
    rgb = irradiance if isinstance(irradiance, (tuple, list)) else (irradiance,) * 3
    d = Vector(direction).normalized()
    el = math.degrees(math.asin(d.z))
    az = math.degrees(math.atan2(d.x, d.y))
    top = max(rgb)
    return _sun(sc, el, az, strength=top, angle=angle, colour=tuple(c / top for c in rgb))


def _camera(sc, loc, target, lens=50, focus=None, fstop=None, vfov=None, aperture=None):
    """vfov: soak render's vertical field of view, degrees (instead of lens);
    aperture: its thin lens's radius, metres (instead of fstop)."""
    cd = bpy.data.cameras.new("Cam")
    cd.lens = lens
    if vfov is not None:
        cd.sensor_fit = "VERTICAL"
        cd.lens = 0.5 * cd.sensor_height / math.tan(math.radians(vfov) / 2)
    if aperture is not None:
        fstop = cd.lens / 1000.0 / (2.0 * aperture)    # N = focal length / aperture diameter
    cd.clip_start = 0.01
    if focus is not None:
        cd.dof.use_dof = True
        cd.dof.focus_distance = focus
        cd.dof.aperture_fstop = fstop
    co = bpy.data.objects.new("Cam", cd)
    sc.collection.objects.link(co)
    co.location = loc
    co.rotation_euler = (Vector(target) - Vector(loc)).to_track_quat("-Z", "Y").to_euler()
    sc.camera = co
    return co


def _shade_smooth(ob, angle=60):
    for p in ob.data.polygons:
        p.use_smooth = True
    if hasattr(ob.data, "use_auto_smooth"):   # 3.x; 4.1+ smooths by angle through a modifier
        ob.data.use_auto_smooth = True
        ob.data.auto_smooth_angle = math.radians(angle)
    elif angle < 180:
        # 4.1+: without it every edge is smoothed, and a lathe's wall of one
        # face row takes the normals of its corners (a glass tilted 45 degrees
        # inside: black by total internal reflection)
        m = ob.modifiers.new("Sharp edges", "EDGE_SPLIT")
        m.split_angle = math.radians(angle)
        m.use_edge_angle, m.use_edge_sharp = True, False


# ------------------------------------------------------------------ materials


class Tree:
    """A small helper to write a dry material's node tree."""

    def __init__(self, name):
        self.mat = bpy.data.materials.new(name)
        self.mat.use_nodes = True
        self.nt = self.mat.node_tree
        self.bsdf = self.nt.nodes["Principled BSDF"]

    def node(self, kind, **inputs):
        n = self.nt.nodes.new(kind)
        for k, v in inputs.items():
            if k in n.inputs:
                n.inputs[k].default_value = v
            else:
                setattr(n, k, v)
        return n

    def link(self, a, b):
        self.nt.links.new(a, b)

    def set(self, **inputs):
        for k, v in inputs.items():
            self.bsdf.inputs[k.replace("_", " ")].default_value = v

    def ramp(self, fac, stops):
        r = self.nt.nodes.new("ShaderNodeValToRGB")
        el = r.color_ramp.elements
        el[0].position, el[0].color = stops[0][0], (*stops[0][1], 1)
        el[1].position, el[1].color = stops[-1][0], (*stops[-1][1], 1)
        for pos, col in stops[1:-1]:
            el.new(pos).color = (*col, 1)
        self.link(fac, r.inputs["Fac"])
        return r.outputs["Color"]

    def noise(self, scale, detail=4.0, roughness=0.5, vector=None, coords="Object"):
        n = self.node("ShaderNodeTexNoise", Scale=scale, Detail=detail, Roughness=roughness)
        if vector is None:
            vector = self.node("ShaderNodeTexCoord").outputs[coords]
        self.link(vector, n.inputs["Vector"])
        return n.outputs["Fac"]

    def bump(self, height, strength, distance=0.02):
        b = self.node("ShaderNodeBump", Strength=strength, Distance=distance)
        self.link(height, b.inputs["Height"])
        self.link(b.outputs["Normal"], self.bsdf.inputs["Normal"])


def _assign(ob, mat):
    ob.data.materials.clear()
    ob.data.materials.append(mat)


def make_wet(ob, preset, liquid="water", wetness=1.0, source="CONSTANT", colours="MATERIAL", **settings):
    """The artist's steps: select the object, set the Wetness panel, Make Wet."""
    bpy.ops.object.select_all(action="DESELECT")
    ob.select_set(True)
    bpy.context.view_layer.objects.active = ob
    s = ob.active_material.soak
    s.preset, s.liquid, s.wetness, s.colour_source = preset, liquid, wetness, colours
    for k, v in settings.items():
        setattr(s, k, v)
    s.wetness_source = source
    r = bpy.ops.soak.make_wet()
    if r != {"FINISHED"}:
        raise RuntimeError(f"Make Wet on {ob.name}: {r}")
    return ob.active_material


def group_node(mat):
    return next(n for n in mat.node_tree.nodes if n.type == "GROUP" and n.node_tree and "Soak" in n.node_tree.name)


# --------------------------------------------------------- wet maps (numpy)


def _need_numpy():
    if np is None:
        raise RuntimeError("this scene makes its wet map with numpy, which this Blender's Python lacks "
                           "(Blender's own builds bundle it; Debian's python3-numpy provides it)")


def _value_noise(n, cells, rng):
    g = rng.random((cells + 1, cells + 1))
    x = np.linspace(0, cells, n, endpoint=False)
    i = x.astype(int)
    f = x - i
    f = f * f * (3 - 2 * f)
    fy, fx = f[:, None], f[None, :]
    a, b = g[i][:, i], g[i + 1][:, i]
    c, d = g[i][:, i + 1], g[i + 1][:, i + 1]
    return (a * (1 - fx) + c * fx) * (1 - fy) + (b * (1 - fx) + d * fx) * fy


def fbm(n, seed, base=4, octaves=5):
    _need_numpy()
    rng = np.random.default_rng(seed)
    out, amp, tot = np.zeros((n, n)), 1.0, 0.0
    for o in range(octaves):
        out += amp * _value_noise(n, base * 2 ** o, rng)
        tot += amp
        amp *= 0.5
    return out / tot


def smoothstep(e0, e1, x):
    t = np.clip((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3 - 2 * t)


def wet_image(name, arr):
    """A float image from arr[v, u] (row 0 = v = 0), 0 dry .. 1 wet, packed."""
    n = arr.shape[0]
    img = bpy.data.images.new(name, arr.shape[1], n, float_buffer=True)
    px = np.ones((n, arr.shape[1], 4), dtype=np.float32)
    px[..., 0] = px[..., 1] = px[..., 2] = arr
    img.pixels.foreach_set(px.ravel())
    img.pack()
    img.colorspace_settings.name = "Non-Color"
    return img


def _grid(n):
    u = (np.arange(n) + 0.5) / n
    return np.meshgrid(u, u)   # U[v, u], V[v, u]


def blot_map(n, centres, seed, warp=0.35, edge=0.03, rect=(0.0, 0.0, 1.0, 1.0)):
    """Blots: union of warped discs ((x, y, radius), ...) with soft edges
    (edge: width in the same units), over the UV square mapped onto the
    rectangle rect = (x0, y0, x1, y1) of the surface."""
    U, V = _grid(n)
    X, Y = rect[0] + (rect[2] - rect[0]) * U, rect[1] + (rect[3] - rect[1]) * V
    wu, wv = fbm(n, seed) - 0.5, fbm(n, seed + 1) - 0.5
    f = np.full((n, n), -1e9)
    for cx, cy, r in centres:
        d = np.hypot(X + warp * r * 2 * wu - cx, Y + warp * r * 2 * wv - cy)
        f = np.maximum(f, r - d)
    return smoothstep(0.0, edge, f)


# ---------------------------------------------------------------- geometry


def _plane(name, size, loc=(0, 0, 0), rot=(0, 0, 0), cuts=0):
    bpy.ops.mesh.primitive_plane_add(size=1, location=loc, rotation=rot)
    ob = bpy.context.object
    ob.name = name
    ob.scale = (size[0], size[1], 1) if isinstance(size, tuple) else (size, size, 1)
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    if cuts:
        bpy.ops.object.mode_set(mode="EDIT")
        bpy.ops.mesh.subdivide(number_cuts=cuts)
        bpy.ops.object.mode_set(mode="OBJECT")
    return ob


def _box(name, size, loc, bevel=0.0):
    bpy.ops.mesh.primitive_cube_add(size=1, location=loc)
    ob = bpy.context.object
    ob.name = name
    ob.scale = size
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    if bevel > 0:
        m = ob.modifiers.new("Bevel", "BEVEL")
        m.width, m.segments = bevel, 3
        _shade_smooth(ob, 40)
    return ob


def _lathe(name, profile, loc=(0, 0, 0), steps=64):
    """A surface of revolution about z from an (r, z) polyline."""
    me = bpy.data.meshes.new(name)
    bm = bmesh.new()
    vs = [bm.verts.new((r, 0.0, z)) for r, z in profile]
    es = [bm.edges.new((a, b)) for a, b in zip(vs, vs[1:])]
    bmesh.ops.spin(bm, geom=vs + es, cent=(0, 0, 0), axis=(0, 0, 1), angle=2 * math.pi, steps=steps,
                   use_duplicate=False)
    bmesh.ops.remove_doubles(bm, verts=bm.verts, dist=1e-5)
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces)
    bm.to_mesh(me)
    bm.free()
    ob = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(ob)
    ob.location = loc
    _shade_smooth(ob, 50)
    return ob


def _rock(name, loc, scale, seed):
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=5, radius=1.0, location=loc)
    ob = bpy.context.object
    ob.name = name
    tex = bpy.data.textures.new(name + " shape", "CLOUDS")
    tex.noise_scale, tex.noise_depth = 0.9, 3
    m = ob.modifiers.new("Shape", "DISPLACE")
    m.texture, m.strength, m.mid_level, m.texture_coords = tex, 0.45, 0.5, "OBJECT"
    empty = bpy.data.objects.new(name + " seed", None)
    bpy.context.scene.collection.objects.link(empty)
    empty.location = (seed * 3.7, seed * 1.3, seed * 2.1)
    m.texture_coords_object = empty
    bpy.context.view_layer.objects.active = ob
    bpy.ops.object.modifier_apply(modifier="Shape")
    bpy.data.objects.remove(empty)
    ob.scale = scale
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    _shade_smooth(ob, 180)
    return ob


# ------------------------------------------------------- 1, 2: wet paper


def _paper_sheet(back_lit):
    """A sheet of paper (A4-ish, 0.30 x 0.21 m) with a wet blot (image wet map)."""
    ob = _plane("Paper", (0.30, 0.21), cuts=24)
    # a gentle curl so that the light grazes it
    for v in ob.data.vertices:
        v.co.z = 0.006 + 0.012 * (v.co.x / 0.15) ** 2 + 0.004 * math.sin(v.co.y * 14)
    _shade_smooth(ob, 180)
    t = Tree("Paper")
    t.set(Roughness=0.6)
    fibres = t.noise(900.0, 2.0, 0.6)
    t.link(t.ramp(fibres, [(0.3, (0.80, 0.80, 0.78)), (0.7, (0.86, 0.86, 0.84))]), t.bsdf.inputs["Base Color"])
    _assign(ob, t.mat)
    wet = blot_map(256, [(0.42, 0.5, 0.2), (0.64, 0.6, 0.09), (0.6, 0.3, 0.05)], seed=5, edge=0.012)
    make_wet(ob, "paper", wetness=0.8, source="IMAGE", wet_map=wet_image("paper wet", wet))
    return ob


def _window(y):
    """The bright window the sun shines through, seen beside the sheet: a glowing
    pane at distance y behind it (seen by the camera only) and two dark glazing bars."""
    pane = _plane("Window", (2.0, 1.2), loc=(0, y, 0.2), rot=(math.radians(90), 0, 0))
    t = Tree("Window")
    em = t.node("ShaderNodeEmission", Strength=2.5)
    em.inputs["Color"].default_value = (1.0, 0.9, 0.78, 1.0)
    t.link(em.outputs[0], t.mat.node_tree.nodes["Material Output"].inputs["Surface"])
    _assign(pane, t.mat)
    # a backdrop only: the sun is the window's light (a glowing pane would light the
    # sheet from behind as strongly as the sun and wash out the blot)
    pane.visible_shadow = pane.visible_diffuse = pane.visible_glossy = pane.visible_transmission = False
    pane.visible_volume_scatter = False
    bar = Tree("Glazing bar")
    bar.set(Roughness=0.5)
    bar.bsdf.inputs["Base Color"].default_value = (0.02, 0.02, 0.02, 1.0)
    for x in (-0.45, 0.32):
        _assign(_box("Glazing bar", (0.03, 0.02, 1.2), (x, y - 0.03, 0.2)), bar.mat)


def build_wet_paper(back_lit):
    sc = _reset()
    sheet = _paper_sheet(back_lit)
    if not back_lit:
        # on a dark desk, sun from the viewer's side
        desk = _plane("Desk", 3.0, loc=(0, 0, -0.002))
        t = Tree("Desk")
        mp = t.node("ShaderNodeMapping", Scale=(1, 12, 1))
        t.link(t.node("ShaderNodeTexCoord").outputs["Object"], mp.inputs["Vector"])
        grain = t.noise(30.0, 3.0, 0.6, vector=mp.outputs[0])
        t.link(t.ramp(grain, [(0.3, (0.09, 0.05, 0.03)), (0.7, (0.16, 0.09, 0.05))]), t.bsdf.inputs["Base Color"])
        t.set(Roughness=0.35)
        _assign(desk, t.mat)
        sheet.rotation_euler.z = math.radians(8)
        # a yellow pencil under the sheet, across the big blot and on under dry paper,
        # its end out on the left ([JLD99] Fig. 5a: seen through the wet spot only)
        pencil = _box("Pencil", (0.30, 0.007, 0.007), (-0.0495, -0.007, 0.0015))
        pencil.rotation_euler.z = math.radians(8)
        p = Tree("Pencil")
        p.set(Roughness=0.4)
        p.bsdf.inputs["Base Color"].default_value = (0.72, 0.5, 0.06, 1.0)
        _assign(pencil, p.mat)
        _sky(sc)
        _sun(sc, 50, 200, strength=2.5)
        _camera(sc, (0.0, -0.36, 0.30), (0.0, -0.005, 0.0), lens=50)
    else:
        # held up against the sun: the camera sees the unlit face
        sheet.rotation_euler = (math.radians(90), 0, math.radians(6))
        sheet.location = (0, 0, 0.16)
        # a dark room, the sun behind the sheet: the 0.1 mm preset passes about 30 %
        # of it dry, 40-50 % wet, so E = 12 W/m^2 puts the dry sheet near 1
        _sky(sc, zenith=(0.004, 0.004, 0.005), horizon=(0.006, 0.006, 0.006), ground=(0.003, 0.003, 0.003),
             strength=1.0)
        _sun(sc, 8, 0, strength=12.0, angle=3.0, colour=(1.0, 0.78, 0.55))
        _window(0.6)
        _camera(sc, (0.08, -0.62, 0.2), (0.0, 0.0, 0.16), lens=45)
    return [("wet_paper_" + ("back" if back_lit else "front"), [1])]


# ----------------------------------------------------- 3: beach rock


def build_beach_rock():
    """[JLD99] Fig. 6 (a)-(d) side by side, left to right: dry rock on dry
    sand; rock wet at its foot on sand with the lines of the last waves;
    rock covered with water on the same sand; all soaked."""
    sc = _reset()
    ground = _plane("Beach", (30.0, 16.0), loc=(0, 4.0, 0))
    t = Tree("Sand")
    co = t.node("ShaderNodeTexCoord").outputs["Object"]
    grain = t.noise(60.0, 6.0, 0.7, vector=co)
    t.link(t.ramp(grain, [(0.35, (0.50, 0.43, 0.30)), (0.65, (0.62, 0.54, 0.38))]), t.bsdf.inputs["Base Color"])
    ripple = t.node("ShaderNodeTexWave", Scale=2.2, Distortion=6.0, Detail=3.0)
    t.link(co, ripple.inputs["Vector"])
    t.bump(ripple.outputs["Fac"], 0.25, 0.02)
    t.set(Roughness=0.9)
    _assign(ground, t.mat)
    # the sand's wet map over its UVs (x from -15 to 15, y from -4 to 12):
    # the sea behind; dry on the left, in the middle the turbulent edges
    # the last four waves left, soaked on the right
    n = 1024
    U, V = _grid(n)
    x, y = -15 + 30 * U, -4 + 16 * V
    turb = fbm(n, 11, base=12)
    yt = y + 0.8 * (turb - 0.5) + 0.25 * np.sin(x * 1.3)
    waves = np.zeros_like(U)
    for k, edge in enumerate((1.6, 0.9, 0.1, -0.7)):   # older waves reached further, dried more
        band = smoothstep(edge - 0.05, edge + 0.15, yt) * smoothstep(edge + 0.9, edge + 0.2, yt)
        waves = np.maximum(waves, (1 - 0.2 * k) * band)
    mixed = np.maximum(waves, smoothstep(1.8, 2.6, yt))
    left = smoothstep(-2.4, -1.6, x + 0.6 * (turb - 0.5))
    right = smoothstep(1.6, 2.4, x + 0.6 * (turb - 0.5))
    wet = np.clip(left * (0.1 + 0.9 * mixed) * (1 - right) + right, 0, 1)
    # damp sand: the pores full where the map is 1 (sand's porosity 0.25), a
    # thin film just starting
    make_wet(ground, "sand", wetness=0.3, source="IMAGE", wet_map=wet_image("beach wet", wet))
    # the sea behind
    sea = _plane("Sea", (60.0, 40.0), loc=(0, 30.0, 0.03))
    s = Tree("Sea")
    s.set(Base_Color=(0.02, 0.06, 0.07, 1), Roughness=0.06)
    s.bump(s.noise(1.5, 4.0, 0.6), 0.3, 0.05)
    _assign(sea, s.mat)

    rock_tree = None
    for i, (state, seed) in enumerate((("dry", 1), ("foot", 2), ("covered", 3), ("soaked", 4))):
        rock = _rock(f"Rock {state}", (-3.0 + 2.0 * i, 0.15 * (i % 2), 0.18), (0.78, 0.62, 0.55), seed)
        r = Tree(f"Rock {state}")
        rco = r.node("ShaderNodeTexCoord").outputs["Object"]
        mottle = r.noise(3.0, 8.0, 0.65, vector=rco)
        r.link(r.ramp(mottle, [(0.3, (0.16, 0.155, 0.145)), (0.5, (0.26, 0.25, 0.23)), (0.7, (0.34, 0.32, 0.29))]),
               r.bsdf.inputs["Base Color"])
        pits = r.noise(18.0, 6.0, 0.7, vector=rco)
        r.bump(pits, 0.35, 0.05)
        r.set(Roughness=0.75)
        _assign(rock, r.mat)
        rock_tree = r
        if state == "dry":
            make_wet(rock, "limestone", wetness=0.0)
        elif state == "foot":
            # wet where the waves reached: a colour attribute by height
            ca = rock.data.color_attributes.new("wave_wet", "FLOAT_COLOR", "POINT")
            for v in rock.data.vertices:
                z = rock.location.z + v.co.z + 0.05 * math.sin(7 * v.co.x + 3 * v.co.y)
                w = float(smoothstep(0.34, 0.24, z))
                ca.data[v.index].color = (w, w, w, 1.0)
            make_wet(rock, "limestone", wetness=1.0, source="ATTRIBUTE", attribute_name="wave_wet")
        else:
            make_wet(rock, "limestone", wetness=1.0)
    del rock_tree
    _hdri(sc, "forest", 0.45, -60)    # as scenes/gallery/beach_rock.json
    _sun(sc, 30, 150, strength=3.0, angle=1.5)
    _camera(sc, (0.0, -8.0, 3.4), (0.0, 0.6, 0.0), lens=34)
    return [("beach_rock", [1])]


# ---------------------------------------------- 4: spilled cognac on oak


def _wood(name, scale=1.0, rough=0.2):
    """Polished oak: growth rings (distorted bands along x) darkened by
    pores (noise stretched along the grain)."""
    t = Tree(name)
    co = t.node("ShaderNodeTexCoord").outputs["Object"]
    mp = t.node("ShaderNodeMapping", Scale=(0.25 * scale, 4.0 * scale, 1.0 * scale))
    t.link(co, mp.inputs["Vector"])
    rings = t.node("ShaderNodeTexWave", wave_type="BANDS", bands_direction="Y", Scale=2.2, Distortion=7.0,
                   Detail=3.0)
    rings.inputs["Detail Scale"].default_value = 1.0
    t.link(mp.outputs[0], rings.inputs["Vector"])
    mp2 = t.node("ShaderNodeMapping", Scale=(1.5 * scale, 60.0 * scale, 1.5 * scale))
    t.link(co, mp2.inputs["Vector"])
    pores = t.noise(20.0, 2.0, 0.5, vector=mp2.outputs[0])
    mix = t.node("ShaderNodeMixRGB", blend_type="MULTIPLY", Fac=0.5)
    t.link(t.ramp(rings.outputs["Fac"], [(0.0, (0.17, 0.075, 0.03)), (0.5, (0.33, 0.17, 0.07)),
                                          (1.0, (0.46, 0.26, 0.11))]), mix.inputs["Color1"])
    t.link(t.ramp(pores, [(0.3, (0.45, 0.4, 0.35)), (0.6, (1, 1, 1))]), mix.inputs["Color2"])
    t.link(mix.outputs["Color"], t.bsdf.inputs["Base Color"])
    t.bump(pores, 0.05, 0.01)
    t.set(Roughness=rough)
    return t.mat


def build_cognac_table():
    """[JLD99] Fig. 7, arranged as the other columns (scenes/gallery/
    cognac_table.json, meshes.py): a tumbler standing on an oak table with
    5 cm of liquid in it, a pool spilled in front of it (meshes.py's spill
    map over the table top), the same low sun behind, the courtyard HDRI and
    a lens focused on the pool. Liquid: the add-on's nearest is cola (a
    caramel-coloured clear liquid, index 1.3325; the core has no measured
    cognac); the liquid in the glass takes the soak column's cognac."""
    _need_numpy()
    sc = _reset()
    meshes = _module("scenes/gallery/meshes.py")
    top = _plane("Table top", (1.0, 0.9), loc=(0.0, 0.05, 0.0))     # UVs over (-0.5, -0.4) .. (0.5, 0.5)
    _assign(top, _wood("Oak table", rough=0.3))
    nu, nv = 400, 360
    spill = np.array([[meshes.spill((i + 0.5) / nu, (j + 0.5) / nv) for i in range(nu)] for j in range(nv)])
    mat = make_wet(top, "oak", liquid="cola", wetness=1.0, source="IMAGE", wet_map=wet_image("cognac spill", spill),
                   colours="MATERIAL")
    group_node(mat).inputs["Spill Edge"].default_value = 1.0
    slab = _box("Table edge", (1.0, 0.9, 0.04), (0.0, 0.05, -0.0201), bevel=0.004)
    _assign(slab, _wood("Oak edge"))
    glass = _lathe("Glass", [(0, 0), (0.035, 0), (0.036, 0.16), (0.034, 0.16), (0.033, 0.008), (0, 0.008)],
                   loc=(0.04, 0.23, 0.0), steps=128)
    g = Tree("Glass")
    g.nt.nodes.remove(g.bsdf)
    gb = g.node("ShaderNodeBsdfGlass", IOR=1.5, Roughness=0.0)
    g.link(gb.outputs[0], g.nt.nodes["Material Output"].inputs["Surface"])
    _assign(glass, g.mat)
    liquid = _lathe("Cognac", [(0, 0.0083), (0.0327, 0.0083), (0.0327, 0.058), (0, 0.058)],
                    loc=(0.04, 0.23, 0.0), steps=128)
    c = Tree("Cognac")
    c.nt.nodes.remove(c.bsdf)
    cb = c.node("ShaderNodeBsdfGlass", IOR=1.36, Roughness=0.0)
    out = c.nt.nodes["Material Output"]
    c.link(cb.outputs[0], out.inputs["Surface"])
    # the soak column's cognac: absorption (3.4, 12.3, 32.6) per metre; Cycles'
    # Volume Absorption is density x (1 - colour)
    va = c.node("ShaderNodeVolumeAbsorption", Density=32.6)
    va.inputs["Color"].default_value = (1 - 3.4 / 32.6, 1 - 12.3 / 32.6, 0.0, 1)
    c.link(va.outputs[0], out.inputs["Volume"])
    _assign(liquid, c.mat)
    floor = _plane("Floor", 20.0, loc=(0, 0, -0.75))
    fl = Tree("Floor")
    fl.set(Base_Color=(0.2, 0.16, 0.13, 1), Roughness=0.9)
    _assign(floor, fl.mat)
    _hdri(sc, "courtyard", 0.15, 38)   # as scenes/gallery/cognac_table.json
    sun = _sun_to(sc, (-0.4359, 0.7268, 0.5299), (3.6, 3.1, 2.5), angle=2.0)
    # the caustic the glass throws on the table: Cycles' shadow caustics
    # (manifold next-event estimation, 3.2+) from the sun through the glass
    if hasattr(sun.data, "cycles") and hasattr(sun.data.cycles, "is_caustics_light"):
        sun.data.cycles.is_caustics_light = True
        for ob in (glass, liquid):
            ob.cycles.is_caustics_caster = True
        top.cycles.is_caustics_receiver = True
    _camera(sc, (-0.05, -0.6, 0.13), (0.0, 0.12, 0.02), vfov=30, focus=0.62, aperture=0.003)
    return [("cognac_table", [1])]


# ------------------------------------------------------ 5: bricks drying


DRYING_TIMES = (0.0, 0.2, 0.4, 0.6)   # as the soak column (scenes/gallery/render.sh)


def _drying_maps(work):
    """The other columns' splash (soak bake turbulence, 320 x 180 over the
    wall) dried by `soak bake drying` with the brick preset's fill time at
    DRYING_TIMES: the pore schedule run as emptying, each texel starting to
    dry by its distance to the patch's border, so the patches shrink from
    their borders. Written as the sequence brick_wet.0001.png ... (frame k)."""
    splash = os.path.join(work, "splash.png")
    _soak("bake", "turbulence", "--width", 320, "--height", 180, "--frequency", 3, "--threshold", -0.05,
          "--softness", 0.25, "--seed", 11, "--threads", 2, "-o", splash)
    export = os.path.join(work, "export.json")
    _soak("export", "--target", "json", "-o", export)
    with open(export) as f:
        t_fill = next(m["t_fill"] for m in json.load(f)["materials"] if m["name"] == "brick")
    for k, t in enumerate(DRYING_TIMES, 1):
        _soak("bake", "drying", splash, "--t-fill", t_fill, "--time", t, "-o",
              os.path.join(work, f"brick_wet.{k:04d}.png"))
    return os.path.join(work, "brick_wet.0001.png")


def build_bricks_drying():
    """[Hnat06] Fig. 6: a brick wall 1.6 x 0.9 m splashed with water, drying:
    the soak column's four maps (t = 0, 0.2, 0.4, 0.6 of the pore schedule)
    as an image sequence over frames 1-4, one map per frame. The bricks'
    own colour varies little, so that the wet patches are the darkest thing
    on the wall."""
    sc = _reset()
    wall = _plane("Wall", (1.6, 0.9), loc=(0.8, 0, 0.45), rot=(math.radians(90), 0, 0))
    t = Tree("Bricks")
    co = t.node("ShaderNodeTexCoord").outputs["Object"]
    tint = t.noise(3.0, 2.0, 0.5, vector=co)
    brick = t.node("ShaderNodeTexBrick", Scale=1.0, Bias=0.0)
    brick.inputs["Mortar Size"].default_value = 0.008
    brick.inputs["Brick Width"].default_value = 0.23
    brick.inputs["Row Height"].default_value = 0.075
    brick.inputs["Mortar Smooth"].default_value = 0.2
    brick.offset, brick.squash = 0.5, 1.0
    t.link(co, brick.inputs["Vector"])
    t.link(t.ramp(tint, [(0.3, (0.42, 0.15, 0.08)), (0.7, (0.47, 0.18, 0.10))]), brick.inputs["Color1"])
    brick.inputs["Color2"].default_value = (0.44, 0.16, 0.09, 1)
    brick.inputs["Mortar"].default_value = (0.50, 0.48, 0.44, 1)
    t.link(brick.outputs["Color"], t.bsdf.inputs["Base Color"])
    grit = t.noise(60.0, 4.0, 0.6, vector=co)
    h = t.node("ShaderNodeMath", operation="MULTIPLY_ADD", Value=1.0)
    t.link(brick.outputs["Fac"], h.inputs[0])
    h.inputs[1].default_value = -1.0
    t.link(grit, h.inputs[2])
    t.bump(h.outputs[0], 0.3, 0.004)
    t.set(Roughness=0.85)
    _assign(wall, t.mat)
    first = _drying_maps(_workdir())
    img = bpy.data.images.load(first, check_existing=False)
    img.source = "SEQUENCE"
    img.colorspace_settings.name = "Non-Color"
    mat = make_wet(wall, "brick", wetness=1.0, source="IMAGE", wet_map=img)
    tex = next(n for n in mat.node_tree.nodes if n.type == "TEX_IMAGE" and n.image == img)
    iu = tex.image_user            # file k at scene frame k (rain.py's drops_user convention)
    iu.frame_duration, iu.frame_start, iu.frame_offset = len(DRYING_TIMES), 1, 0
    iu.use_cyclic, iu.use_auto_refresh = False, True
    sc.frame_start, sc.frame_end = 1, len(DRYING_TIMES)
    ground = _plane("Paving", 20.0, loc=(0.8, 0, 0))
    p = Tree("Paving")
    p.link(p.ramp(p.noise(20.0, 4.0, 0.6), [(0.3, (0.25, 0.25, 0.24)), (0.7, (0.33, 0.32, 0.30))]),
           p.bsdf.inputs["Base Color"])
    p.set(Roughness=0.8)
    _assign(ground, p.mat)
    make_wet(ground, "concrete", wetness=0.1)
    _hdri(sc, "forest", 0.5, -60)     # as scenes/gallery/bricks_drying.json
    _sun_to(sc, (-0.8, -1.0, 0.9), 3.0)
    _camera(sc, (0.8, -1.62, 0.5), (0.8, 0.0, 0.45), vfov=29.4)
    return [("bricks_drying", list(range(1, len(DRYING_TIMES) + 1)))]


# ----------------------------------------------- 6: bas-relief under rain


def _relief(work):
    """The other columns' carved panel (scenes/povray/gallery/relief_mesh.py at
    240 cells a metre: 2.6 x 1.3 m from x = 0, z = 0, carved towards -y) and
    their rain bake on it (povray/render_gallery.sh, scenes/gallery/render.sh:
    ten minutes of 6 mm/h rain from the front and steeply above, no runoff),
    imported with its UVs; returns (object, wet map path)."""
    mesh = _module("scenes/povray/gallery/relief_mesh.py")
    argv = sys.argv
    try:
        sys.argv = ["relief_mesh.py", work, "240"]
        mesh.main()
    finally:
        sys.argv = argv
    path, wet = os.path.join(work, "relief.obj"), os.path.join(work, "relief_wet.png")
    _soak("bake", "rain", path, "-o", wet, "--up", "z", "--rain-dir", "0,-0.55,1", "--spread", 15, "--rainfall", 6,
          "--duration", 600, "--drop-size", 0.0005, "--splat", 0.004, "--flow-iterations", 0, "--width", 800,
          "--height", 400, "--rays", 32, "--threads", 2)
    return import_relief(path), wet


def import_relief(path):
    """The relief's OBJ (z up, as relief_mesh.py writes it), smooth-shaded."""
    if hasattr(bpy.ops.wm, "obj_import"):
        bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")
    else:
        bpy.ops.import_scene.obj(filepath=path, axis_forward="Y", axis_up="Z")
    ob = bpy.context.selected_objects[0]
    ob.name = "Relief"
    for p in ob.data.polygons:
        p.use_smooth = True
    return ob


def build_bas_relief_rain():
    """[Hnat06] Fig. 7: rain on a carved limestone panel, the relief and the
    wet map of the other columns (scenes/gallery/bas_relief_rain.json): the
    faces open to the rain wet, the strips sheltered under the cornice and
    the string course dry. The panel stands on the paving, against a wall of
    the same stone; the same sun, grey sky and camera."""
    sc = _reset()
    panel, wet_path = _relief(_workdir())
    t = Tree("Limestone")
    co = t.node("ShaderNodeTexCoord").outputs["Object"]
    t.link(t.ramp(t.noise(6.0, 8.0, 0.6, vector=co), [(0.3, (0.52, 0.48, 0.41)), (0.7, (0.58, 0.54, 0.46))]),
           t.bsdf.inputs["Base Color"])
    t.bump(t.noise(80.0, 4.0, 0.7, vector=co), 0.1, 0.002)
    t.set(Roughness=0.8)
    _assign(panel, t.mat)
    img = bpy.data.images.load(wet_path, check_existing=False)
    img.colorspace_settings.name = "Non-Color"
    img.pack()
    make_wet(panel, "limestone", wetness=1.0, source="IMAGE", wet_map=img)
    sc["soak_inset"] = wet_path       # render_all.py pastes the map in a corner, as the other columns
    wall = _box("Wall", (6.0, 0.399, 1.8), (1.0, 0.2005, 0.7))
    stone = Tree("Wall stone")
    stone.link(stone.ramp(stone.noise(5.0, 6.0, 0.6), [(0.3, (0.50, 0.46, 0.40)), (0.7, (0.56, 0.52, 0.45))]),
               stone.bsdf.inputs["Base Color"])
    stone.set(Roughness=0.85)
    _assign(wall, stone.mat)
    make_wet(wall, "limestone", wetness=0.5)
    ground = _plane("Paving", 40.0, loc=(1.3, -3.0, 0))
    gr = Tree("Paving")
    gr.link(gr.ramp(gr.noise(8.0, 6.0, 0.6), [(0.3, (0.22, 0.21, 0.2)), (0.7, (0.30, 0.29, 0.27))]),
            gr.bsdf.inputs["Base Color"])
    gr.set(Roughness=0.5)
    _assign(ground, gr.mat)
    make_wet(ground, "concrete", wetness=0.99)   # the paving after the rain, with a film
    w = bpy.data.worlds.new("Overcast")
    w.use_nodes = True
    w.node_tree.nodes["Background"].inputs["Color"].default_value = (0.55, 0.55, 0.55, 1)
    sc.world = w
    _sun_to(sc, (-1.6, -1.0, 0.8), (3.6, 3.2, 2.7), angle=3.0)
    _camera(sc, (1.3, -4.6, 0.95), (1.3, 0.0, 0.62), vfov=24.4)
    return [("bas_relief_rain", [1])]


# ------------------------------------------- 7: flowerpot porosity sweep


# clay at the open porosities alpha_poro of [Hnat06] Fig. 5's sweep: presets the
# core adds with `soak export --variant` (scenes/gallery/variants.txt, in the add-on
# zip scenes/blender/variant_addon.py makes; `make gallery` installs that one)
POROSITY_SWEEP = (("clay_p00", 0.0), ("clay_p10", 0.1), ("clay_p20", 0.2), ("clay_p30", 0.3), ("clay_p40", 0.4),
                  ("clay_p50", 0.5))


def _terracotta(name):
    t = Tree(name)
    co = t.node("ShaderNodeTexCoord").outputs["Object"]
    t.link(t.ramp(t.noise(30.0, 6.0, 0.55, vector=co), [(0.3, (0.53, 0.20, 0.105)), (0.7, (0.57, 0.22, 0.115))]),
           t.bsdf.inputs["Base Color"])
    t.bump(t.noise(300.0, 3.0, 0.6, vector=co), 0.15, 0.0015)
    t.set(Roughness=0.8)
    return t


POT_PROFILE = [(0, 0), (0.055, 0), (0.08, 0.14), (0.088, 0.142), (0.088, 0.16), (0.072, 0.16), (0.072, 0.145),
               (0.05, 0.012), (0, 0.012)]   # scenes/gallery/meshes.py's pot, 0.16 m high


def build_flowerpot_porosity():
    """[Hnat06] Fig. 5, arranged as the other columns (scenes/gallery/
    flowerpot_porosity.json): the same terracotta pot on the clay class with
    its open porosity alpha_poro = 0, 0.1 ... 0.5 (left to right). Front row:
    the pores just full (Wetness = the porosity, no film yet); back row:
    dry. The same sun, courtyard HDRI, round lamp near the camera (whose
    highlight the pore water shows), oak shelf, pale wall and camera."""
    sc = _reset()
    for i, (preset, porosity) in enumerate(POROSITY_SWEEP):
        for y, wetness in ((0.0, porosity), (0.3, 0.0)):
            state = "wet" if y == 0.0 else "dry"
            pot = _lathe(f"Pot {preset} {state}", POT_PROFILE, loc=(-0.525 + 0.21 * i, y, 0), steps=96)
            t = _terracotta(f"Terracotta ({preset}, {state})")
            _assign(pot, t.mat)
            make_wet(pot, preset, wetness=wetness)
    shelf = _plane("Shelf", (6.0, 2.8), loc=(0, -0.6, 0))
    _assign(shelf, _wood("Shelf oak", scale=4.0, rough=0.5))
    make_wet(shelf, "oak", wetness=0.0)
    wall = _plane("Wall", (4.0, 1.2), loc=(0, 0.8, 0.6), rot=(math.radians(90), 0, 0))
    w = Tree("Plaster")
    w.set(Base_Color=(0.6, 0.6, 0.6, 1), Roughness=1.0)
    _assign(wall, w.mat)
    _hdri(sc, "courtyard", 0.45, 18)  # as scenes/gallery/flowerpot_porosity.json
    _sun_to(sc, (-0.4, -0.8, 0.8), 3.0, angle=2.0)
    # the round lamp near the camera, radius 0.25 m, radiance 40: a Cycles point
    # light's power is radiance x 4 pi^2 r^2
    lamp = bpy.data.lights.new("Lamp", "POINT")
    lamp.shadow_soft_size = 0.25
    lamp.energy = 40.0 * 4 * math.pi ** 2 * 0.25 ** 2
    lo = bpy.data.objects.new("Lamp", lamp)
    lo.location = (-0.9, -2.2, 0.9)
    sc.collection.objects.link(lo)
    _camera(sc, (0.0, -1.6, 0.55), (0.0, 0.2, 0.08), vfov=24)
    return [("flowerpot_porosity", [1])]


# ------------------------------ 8: films of increasing thickness, copper


FILM_STEPS = (0.0, 0.2857, 0.5714, 0.8571, 1.0)   # as scenes/gallery/film_copper.json


def build_film_copper():
    """[Lag13], arranged as the other columns (scenes/gallery/film_copper.json):
    a concrete slab 1 x 1 x 0.1 m of five strips wetting from left to right
    (Wetness 0, 0.29, 0.57, 0.86, 1: the pores fill, then the film's coverage
    grows to the preset's depth), two polished copper balls on it (the core's
    copper preset and colour), the left one dry, the right one under water,
    on dry asphalt; the same sun, grey sky and camera."""
    sc = _reset()
    for i, w in enumerate(FILM_STEPS):
        strip = _box(f"Concrete {w:.2f}", (0.2, 1.0, 0.1), (0.1 + 0.2 * i, 0.5, -0.05))
        _assign(strip, Tree(f"Concrete {w:.2f}").mat)
        make_wet(strip, "concrete", wetness=w, colours="PRESET")
    for state, x, w in (("dry", 0.25, 0.0), ("wet", 0.84, 1.0)):
        bpy.ops.mesh.primitive_uv_sphere_add(radius=0.12, location=(x, 0.6, 0.12), segments=96, ring_count=48)
        ball = bpy.context.object
        ball.name = f"Copper ball {state}"
        _shade_smooth(ball, 180)
        _assign(ball, Tree(f"Copper {state}").mat)
        make_wet(ball, "copper", wetness=w, colours="PRESET")
    ground = _plane("Paving", 40.0, loc=(0.5, 0.5, -0.1))
    _assign(ground, Tree("Asphalt").mat)
    make_wet(ground, "asphalt", wetness=0.0, colours="PRESET")
    w = bpy.data.worlds.new("Grey sky")
    w.use_nodes = True
    w.node_tree.nodes["Background"].inputs["Color"].default_value = (0.5, 0.5, 0.5, 1)
    sc.world = w
    _sun_to(sc, (-0.8, 0.45, 0.5), (4.7124, 3.927, 2.9845), angle=1.0)
    _camera(sc, (0.5, -0.95, 0.85), (0.5, 0.42, 0.02), vfov=30.683)
    return [("film_copper", [1])]


# ------------------------- 8b: [Lag13]'s film depths at full coverage


FILM_DEPTHS = ("", "_f0", "_f05", "_f500")   # dry, then 0, 0.5 mm, 50 cm (scenes/gallery/variants.txt)


def build_film_thickness():
    """[Lag13]: a rough dielectric ground (the concrete class with the colour of
    scenes/gallery/film_thickness.json, back row) and copper (front row), left
    to right dry, then fully covered by water 0, 0.5 mm and 50 cm deep (the
    presets concrete_f0 ... copper_f500 of `soak export --variant`); a round
    lamp far behind that the films and the metal mirror."""
    sc = _reset()
    for i, depth in enumerate(FILM_DEPTHS):
        x, wet = -0.75 + 0.5 * i, 1.0 if i else 0.0
        tile = _box(f"Ground{depth or ' dry'}", (0.46, 0.46, 0.01), (x, 0.53, 0.005))
        t = Tree(f"Ground{depth or ' dry'}")
        t.set(Base_Color=(0.45, 0.3, 0.2, 1), Roughness=0.8)
        _assign(tile, t.mat)
        make_wet(tile, "concrete" + depth, wetness=wet)
        plate = _box(f"Copper{depth or ' dry'}", (0.46, 0.46, 0.01), (x, -0.02, 0.005))
        _assign(plate, Tree(f"Copper{depth or ' dry'}").mat)
        make_wet(plate, "copper" + depth, wetness=wet, colours="PRESET")
    floor = _plane("Floor", 20.0, loc=(0, 0, -0.001))
    f = Tree("Floor")
    f.set(Base_Color=(0.05, 0.05, 0.05, 1), Roughness=1.0)
    _assign(floor, f.mat)
    w = bpy.data.worlds.new("Grey")
    w.use_nodes = True
    w.node_tree.nodes["Background"].inputs["Color"].default_value = (0.35, 0.35, 0.35, 1)
    sc.world = w
    lamp = bpy.data.lights.new("Lamp", "POINT")
    lamp.energy, lamp.shadow_soft_size = 1900.0, 0.4
    lo = bpy.data.objects.new("Lamp", lamp)
    lo.location = (0.0, 6.0, 2.2)
    sc.collection.objects.link(lo)
    _camera(sc, (0.0, -2.3, 1.1), (0.0, 0.2, 0.0), lens=37.7)   # 51 degrees across, as the soak column
    return [("film_thickness", [1])]


SCENES = {
    "wet_paper_front": lambda: build_wet_paper(False),
    "wet_paper_back": lambda: build_wet_paper(True),
    "beach_rock": build_beach_rock,
    "cognac_table": build_cognac_table,
    "bricks_drying": build_bricks_drying,
    "bas_relief_rain": build_bas_relief_rain,
    "flowerpot_porosity": build_flowerpot_porosity,
    "film_copper": build_film_copper,
    "film_thickness": build_film_thickness,
}
