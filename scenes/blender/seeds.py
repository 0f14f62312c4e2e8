"""The seed scenes of the physics sources as a Blender gallery, built from
scratch (no .blend) with the Soak add-on's operators, as an artist would:
build a dry material, set the Wetness panel, Make Wet (Key Drying, Bake Wet
Map where the scene needs them).

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
import math
import os

import bmesh
import bpy
from mathutils import Vector

try:
    import numpy as np
except ImportError:   # Debian 13's blender package has no numpy (Blender's own builds bundle it)
    np = None

NUMPY_SCENES = ("wet_paper_front", "wet_paper_back", "beach_rock", "cognac_table", "bas_relief_rain")

# ---------------------------------------------------------------- scene set-up


def _reset():
    for coll in (bpy.data.objects, bpy.data.meshes, bpy.data.materials, bpy.data.lights, bpy.data.cameras,
                 bpy.data.worlds, bpy.data.node_groups, bpy.data.images, bpy.data.textures, bpy.data.curves):
        for item in list(coll):
            if getattr(item, "type", "") != "RENDER_RESULT":
                coll.remove(item)
    sc = bpy.context.scene
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


def _camera(sc, loc, target, lens=50, focus=None, fstop=None):
    cd = bpy.data.cameras.new("Cam")
    cd.lens = lens
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


def spill_map(n, balls, seed, rect, warp=0.02, edge=0.06):
    """A liquid spill: metaballs ((x, y, radius), ...) merged where their
    Gaussian sum passes 0.5, the outline warped by noise (warp in the rect's
    units), over the UV square mapped onto rect = (x0, y0, x1, y1)."""
    U, V = _grid(n)
    X = rect[0] + (rect[2] - rect[0]) * U + warp * (fbm(n, seed, base=6) - 0.5) * 2
    Y = rect[1] + (rect[3] - rect[1]) * V + warp * (fbm(n, seed + 1, base=6) - 0.5) * 2
    f = np.zeros((n, n))
    for cx, cy, r in balls:
        f += np.exp(-((X - cx) ** 2 + (Y - cy) ** 2) / (r * r))
    return smoothstep(0.5 - edge, 0.5 + edge, f)


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
    """[JLD99] Fig. 7: cognac spilled from a tipped glass on a polished wood
    table. Cognac: the add-on's nearest liquid is cola (a caramel-coloured
    clear liquid, index 1.3325; the core has no measured cognac)."""
    sc = _reset()
    rect = (-1.2, -0.5, 1.2, 0.9)
    top = _plane("Table top", (2.4, 1.4), loc=(0, 0.2, 0.0))
    _assign(top, _wood("Oak table", rough=0.3))
    # the spill's shape, in metres on the table (UVs cover rect)
    spill = spill_map(1024, [(0.19, 0.36, 0.07), (0.14, 0.29, 0.08), (0.21, 0.23, 0.06), (0.08, 0.21, 0.06),
                             (0.03, 0.15, 0.045), (0.25, 0.15, 0.035), (0.28, 0.10, 0.02), (-0.03, 0.10, 0.03),
                             (0.11, 0.11, 0.03), (0.33, 0.26, 0.015), (-0.09, 0.05, 0.012),
                             (0.06, 0.02, 0.01), (0.31, 0.05, 0.009)],
                      seed=21, rect=rect, warp=0.012, edge=0.05)
    mat = make_wet(top, "oak", liquid="cola", wetness=1.0, source="IMAGE", wet_map=wet_image("cognac spill", spill),
                   colours="MATERIAL")
    group_node(mat).inputs["Spill Edge"].default_value = 1.0
    # the table's thickness, dry oak
    slab = _box("Table edge", (2.4, 1.4, 0.05), (0, 0.2, -0.0255), bevel=0.006)
    _assign(slab, _wood("Oak edge"))
    # the tipped glass, lying on its side where the spill starts
    profile = [(0.0, 0.0), (0.034, 0.0), (0.038, 0.006), (0.036, 0.10), (0.033, 0.10), (0.031, 0.007),
               (0.0, 0.008)]
    glass = _lathe("Glass", profile, steps=64)
    glass.rotation_euler = (math.radians(90), 0, math.radians(25))
    glass.location = (0.24, 0.47, 0.038)
    g = Tree("Glass")
    g.nt.nodes.remove(g.bsdf)
    gb = g.node("ShaderNodeBsdfGlass", IOR=1.5, Roughness=0.0)
    g.link(gb.outputs[0], g.nt.nodes["Material Output"].inputs["Surface"])
    _assign(glass, g.mat)
    # a bottle behind, out of focus
    bottle = _lathe("Bottle", [(0.0, 0.0), (0.045, 0.0), (0.048, 0.01), (0.048, 0.17), (0.02, 0.22),
                               (0.014, 0.25), (0.014, 0.29), (0.0, 0.29)], loc=(-0.25, 0.75, 0.0))
    b = Tree("Bottle")
    b.nt.nodes.remove(b.bsdf)
    bb = b.node("ShaderNodeBsdfGlass", IOR=1.5, Roughness=0.02, Color=(0.8, 0.45, 0.15, 1))
    b.link(bb.outputs[0], b.nt.nodes["Material Output"].inputs["Surface"])
    _assign(bottle, b.mat)
    _hdri(sc, "courtyard", 0.15, 38)   # as scenes/gallery/cognac_table.json
    # the sun low behind the spill, mirrored by the liquid towards the camera
    _sun(sc, 25, 40, strength=3.0, angle=2.0)
    _camera(sc, (-0.02, -0.42, 0.25), (0.13, 0.27, 0.0), lens=45, focus=0.72, fstop=2.8)
    return [("cognac_table", [1])]


# ------------------------------------------------------ 5: bricks drying


def build_bricks_drying():
    """[Hnat06] Fig. 6: a brick wall splashed with water (noise patches),
    drying over 40 frames (Key Drying), frames 1, 14, 27 and 40."""
    sc = _reset()
    wall = _plane("Wall", (3.2, 1.8), loc=(0, 0, 0.9), rot=(math.radians(90), 0, 0))
    t = Tree("Bricks")
    co = t.node("ShaderNodeTexCoord").outputs["Object"]
    tint = t.noise(4.0, 2.0, 0.5, vector=co)
    c1 = t.ramp(tint, [(0.3, (0.30, 0.10, 0.06)), (0.7, (0.42, 0.16, 0.09))])
    brick = t.node("ShaderNodeTexBrick", Scale=3.2, Bias=0.0)
    brick.inputs["Mortar Size"].default_value = 0.015
    brick.inputs["Brick Width"].default_value = 0.5
    brick.inputs["Row Height"].default_value = 0.21
    brick.inputs["Mortar Smooth"].default_value = 0.1
    brick.offset = 0.5
    brick.squash = 1.0
    t.link(co, brick.inputs["Vector"])
    t.link(c1, brick.inputs["Color1"])
    brick.inputs["Color2"].default_value = (0.22, 0.075, 0.05, 1)
    brick.inputs["Mortar"].default_value = (0.45, 0.43, 0.40, 1)
    t.link(brick.outputs["Color"], t.bsdf.inputs["Base Color"])
    grit = t.noise(40.0, 4.0, 0.6, vector=co)
    h = t.node("ShaderNodeMath", operation="MULTIPLY_ADD", Value=1.0)
    t.link(brick.outputs["Fac"], h.inputs[0])
    h.inputs[1].default_value = -1.0
    t.link(grit, h.inputs[2])
    t.bump(h.outputs[0], 0.5, 0.02)
    t.set(Roughness=0.85)
    _assign(wall, t.mat)
    mat = make_wet(wall, "brick", wetness=1.0, source="NOISE", noise_scale=1.2)
    group_node(mat).inputs["Puddle Level"].default_value = 0.6   # the splashes soaked through
    sc.frame_start, sc.frame_end = 1, 40
    bpy.ops.soak.key_drying(frame_start=1, frame_end=40)
    ground = _plane("Pavement", 8.0, loc=(0, 1.5, 0))
    p = Tree("Pavement")
    p.link(p.ramp(p.noise(20.0, 4.0, 0.6), [(0.3, (0.25, 0.25, 0.24)), (0.7, (0.33, 0.32, 0.30))]),
           p.bsdf.inputs["Base Color"])
    p.set(Roughness=0.8)
    _assign(ground, p.mat)
    del mat
    _hdri(sc, "forest", 0.5, -60)     # as scenes/gallery/bricks_drying.json
    _sun(sc, 30, 255, strength=3.0, angle=1.0)
    _camera(sc, (0.8, -2.0, 1.05), (0.0, 0.0, 0.9), lens=50)
    return [("bricks_drying", [1, 14, 27, 40])]


# ----------------------------------------------- 6: bas-relief under rain


def _relief_heights(n):
    """A carved panel: a raised frame, moulded bands (ledges that catch the
    rain), three medallions with a rosette, weathering noise."""
    U, V = _grid(n)
    h = np.zeros((n, n))
    frame = np.minimum(np.minimum(U, 1 - U), np.minimum(V, 1 - V))
    h += 0.8 * smoothstep(0.07, 0.06, frame)
    for v0 in (0.33, 0.67):                         # horizontal moulded bands
        h = np.maximum(h, 0.6 * smoothstep(0.035, 0.0, np.abs(V - v0)) ** 0.5)
    for cu in (0.2, 0.5, 0.8):                      # medallions between the bands
        for cv in (0.17, 0.5, 0.83):
            r = np.hypot(U - cu, (V - cv) * 1.0)
            dome = np.clip(1 - (r / 0.11) ** 2, 0, 1) ** 0.5
            theta = np.arctan2(V - cv, U - cu)
            petals = 0.5 + 0.5 * np.cos(6 * theta + (cu * 7))
            rosette = dome * (0.55 + 0.45 * smoothstep(0.3, 0.9, petals * (1.2 - r / 0.11)))
            ring = 0.35 * smoothstep(0.012, 0.0, np.abs(r - 0.125))
            h = np.maximum(h, np.maximum(rosette, ring))
    h += 0.08 * (fbm(n, 31, base=8) - 0.5)
    return np.clip(h, 0, 1)


def build_bas_relief_rain():
    """[Hnat06] Fig. 7: rain on a carved stone panel under a cornice; the wet
    map is the add-on's Bake Wet Map (soak bake rain, sheltered by the whole
    visible scene): ledges and the tops of the carvings catch the rain, the
    strip under the cornice stays dry."""
    sc = _reset()
    bpy.ops.mesh.primitive_grid_add(x_subdivisions=200, y_subdivisions=200, size=1.0)
    panel = bpy.context.object
    panel.name = "Relief"
    panel.scale = (1.6, 1.6, 1)
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    n = 512
    hh = _relief_heights(n)
    for v in panel.data.vertices:    # carve: the height field along the panel's normal
        i = min(n - 1, int((v.co.y / 1.6 + 0.5) * n))
        j = min(n - 1, int((v.co.x / 1.6 + 0.5) * n))
        v.co.z = 0.09 * hh[i, j]
    panel.data.update()
    panel.rotation_euler = (math.radians(78), 0, 0)   # a stele leaning back a little
    panel.location = (0, 0, 0.95)
    _shade_smooth(panel, 180)
    t = Tree("Sandstone")
    co = t.node("ShaderNodeTexCoord").outputs["Object"]
    t.link(t.ramp(t.noise(6.0, 8.0, 0.6, vector=co), [(0.3, (0.50, 0.42, 0.33)), (0.7, (0.62, 0.54, 0.43))]),
           t.bsdf.inputs["Base Color"])
    t.bump(t.noise(60.0, 4.0, 0.7, vector=co), 0.2, 0.01)
    t.set(Roughness=0.8)
    _assign(panel, t.mat)
    make_wet(panel, "limestone", wetness=1.0)
    # the cornice over it and the wall around it shelter the top
    cornice = _box("Cornice", (2.2, 0.4, 0.16), (0, 0.25, 1.86), bevel=0.02)
    stone = Tree("Wall stone")
    stone.link(stone.ramp(stone.noise(5.0, 6.0, 0.6), [(0.3, (0.40, 0.36, 0.30)), (0.7, (0.50, 0.45, 0.38))]),
               stone.bsdf.inputs["Base Color"])
    stone.set(Roughness=0.85)
    _assign(cornice, stone.mat)
    ground = _plane("Ground", 40.0, loc=(0, 0, 0))
    gr = Tree("Paving")
    gr.link(gr.ramp(gr.noise(8.0, 6.0, 0.6), [(0.3, (0.22, 0.21, 0.2)), (0.7, (0.30, 0.29, 0.27))]),
            gr.bsdf.inputs["Base Color"])
    gr.set(Roughness=0.5)
    _assign(ground, gr.mat)
    make_wet(ground, "concrete", wetness=0.6)   # the paving after the rain, with a film
    bpy.ops.object.select_all(action="DESELECT")
    panel.select_set(True)
    bpy.context.view_layer.objects.active = panel
    r = bpy.ops.soak.bake_wetmap(size=512, rays=32, duration=3600.0, occluders="SCENE")
    if r != {"FINISHED"}:
        raise RuntimeError(f"Bake Wet Map: {r}")
    # the artist's tweak: a third of the baked map's value already reads as soaked
    group_node(panel.active_material).inputs["Puddle Level"].default_value = 0.35
    # overcast: a bright grey sky, a weak hazy sun
    _sky(sc, zenith=(0.42, 0.46, 0.52), horizon=(0.62, 0.64, 0.66), ground=(0.12, 0.12, 0.12), strength=1.2)
    _sun(sc, 35, 250, strength=1.5, angle=6.0)
    _camera(sc, (0.6, -4.7, 1.2), (0.0, 0.0, 0.95), lens=45)
    return [("bas_relief_rain", [1])]


# ------------------------------------------- 7: flowerpot porosity sweep


POT_PROFILE = [(0.0, 0.0), (0.36, 0.0), (0.38, 0.015), (0.50, 0.86), (0.56, 0.87), (0.57, 0.88),
               (0.575, 1.02), (0.565, 1.04), (0.53, 1.04), (0.515, 1.0), (0.49, 0.89), (0.33, 0.07),
               (0.0, 0.07)]
# clay at the open porosities alpha_poro of [Hnat06] Fig. 5's sweep: presets the
# core adds with `soak export --variant` (scenes/gallery/variants.txt, in the add-on
# zip scenes/blender/variant_addon.py makes; `make gallery` installs that one)
POROSITY_SWEEP = (("clay_p00", 0.0), ("clay_p10", 0.1), ("clay_p20", 0.2), ("clay_p30", 0.3), ("clay_p40", 0.4),
                  ("clay_p50", 0.5))


def _terracotta(name):
    t = Tree(name)
    co = t.node("ShaderNodeTexCoord").outputs["Object"]
    t.link(t.ramp(t.noise(5.0, 6.0, 0.55, vector=co), [(0.3, (0.53, 0.20, 0.105)), (0.7, (0.57, 0.22, 0.115))]),
           t.bsdf.inputs["Base Color"])
    t.bump(t.noise(50.0, 3.0, 0.6, vector=co), 0.15, 0.01)
    t.set(Roughness=0.8)
    return t


def build_flowerpot_porosity():
    """[Hnat06] Fig. 5: the same terracotta pot on the clay class with its open
    porosity alpha_poro = 0, 0.1 ... 0.5 (left to right). Front row: the pores
    just full (Wetness = the porosity, no film yet); back row: dry. The more
    porous, the darker and glossier; a lamp near the camera gives the pore
    water a highlight to show."""
    sc = _reset()
    k = len(POROSITY_SWEEP)
    for i, (preset, porosity) in enumerate(POROSITY_SWEEP):
        for row, wetness in ((0, porosity), (1, 0.0)):
            pot = _lathe(f"Pot {preset} {'wet' if row == 0 else 'dry'}", POT_PROFILE,
                         loc=((i - (k - 1) / 2) * 1.3, row * 2.0, 0))
            t = _terracotta(f"Terracotta ({preset}, {'wet' if row == 0 else 'dry'})")
            _assign(pot, t.mat)
            make_wet(pot, preset, wetness=wetness)
    shelf = _box("Table", (12.0, 7.0, 0.12), (0, 0.0, -0.06), bevel=0.02)
    _assign(shelf, _wood("Shelf oak", scale=0.4, rough=0.5))
    wall = _plane("Wall", (14.0, 6.0), loc=(0, 3.4, 2.0), rot=(math.radians(90), 0, 0))
    w = Tree("Plaster")
    w.link(w.ramp(w.noise(3.0, 6.0, 0.6), [(0.3, (0.55, 0.55, 0.52)), (0.7, (0.62, 0.61, 0.58))]),
           w.bsdf.inputs["Base Color"])
    w.set(Roughness=0.9)
    _assign(wall, w.mat)
    _hdri(sc, "courtyard", 0.45, 18)  # as scenes/gallery/flowerpot_porosity.json
    _sun(sc, 55, 215, strength=2.5, angle=2.0)
    lamp = bpy.data.lights.new("Lamp", "POINT")     # near the camera: its highlight on the pore water
    lamp.energy, lamp.shadow_soft_size = 2500.0, 0.3
    lo = bpy.data.objects.new("Lamp", lamp)
    lo.location = (-2.5, -8.0, 5.5)
    sc.collection.objects.link(lo)
    _camera(sc, (0.0, -9.5, 4.4), (0.0, 0.8, 0.45), lens=45)
    return [("flowerpot_porosity", [1])]


# ------------------------------ 8: films of increasing thickness, copper


FILM_STEPS = (0.0, 0.25, 0.5, 0.75, 1.0)


def build_film_copper():
    """[Lag13]: the same ground dry, with pores full, and under a growing
    water film (concrete tiles, back row; Wetness 0, 0.25 = concrete's
    porosity, then film coverage 1/3, 2/3, 1), and polished copper under the
    same wetness (front row; copper has no pores: the film grows from 0)."""
    sc = _reset()
    for i, w in enumerate(FILM_STEPS):
        x = (i - 2) * 0.62
        tile = _box(f"Concrete {w}", (0.56, 0.56, 0.04), (x, 0.35, 0.02), bevel=0.004)
        t = Tree(f"Concrete {w}")
        co = t.node("ShaderNodeTexCoord").outputs["Object"]
        t.link(t.ramp(t.noise(12.0, 6.0, 0.6, vector=co), [(0.3, (0.40, 0.39, 0.37)), (0.7, (0.55, 0.54, 0.51))]),
               t.bsdf.inputs["Base Color"])
        t.bump(t.noise(80.0, 3.0, 0.6, vector=co), 0.12, 0.01)
        t.set(Roughness=0.7)
        _assign(tile, t.mat)
        make_wet(tile, "concrete", wetness=w)
        plate = _box(f"Copper {w}", (0.56, 0.40, 0.02), (x, -0.22, 0.01), bevel=0.003)
        c = Tree(f"Copper {w}")
        _assign(plate, c.mat)
        make_wet(plate, "copper", wetness=w, colours="PRESET")
    ground = _plane("Ground", 12.0, loc=(0, 0, -0.001))
    g = Tree("Slate")
    g.link(g.ramp(g.noise(6.0, 4.0, 0.6), [(0.3, (0.05, 0.05, 0.055)), (0.7, (0.08, 0.08, 0.085))]),
           g.bsdf.inputs["Base Color"])
    g.set(Roughness=0.6)
    _assign(ground, g.mat)
    # something for the films and the copper to mirror: the balls, and behind
    # them a pale wall with dark window bays (a mirror shows its edges sharply,
    # a rough dry tile only their average)
    for j, (x, col) in enumerate(((-1.0, (0.7, 0.15, 0.1)), (0.1, (0.85, 0.8, 0.7)), (1.1, (0.1, 0.3, 0.7)))):
        bpy.ops.mesh.primitive_uv_sphere_add(radius=0.18, location=(x, 0.95, 0.18), segments=48,
                                             ring_count=24)
        s = bpy.context.object
        _shade_smooth(s, 180)
        m = Tree(f"Ball {j}")
        m.set(Base_Color=(*col, 1), Roughness=0.4)
        _assign(s, m.mat)
    wall = _box("Wall", (8.0, 0.2, 3.0), (0.0, 2.6, 1.5))
    wm = Tree("Wall")
    wm.set(Base_Color=(0.8, 0.78, 0.72, 1), Roughness=0.8)
    _assign(wall, wm.mat)
    bay = Tree("Window bay")
    bay.set(Base_Color=(0.02, 0.02, 0.025, 1), Roughness=0.3)
    for k in range(-3, 4):
        win = _box(f"Window {k}", (0.5, 0.05, 1.4), (k * 1.1, 2.48, 1.3))
        _assign(win, bay.mat)
    _sky(sc, zenith=(0.03, 0.08, 0.3), horizon=(1.0, 0.85, 0.65), strength=0.7)
    _sun(sc, 35, 150, strength=3.0, angle=2.0)
    # low: the films and the copper mirror the wall, its windows and the balls
    _camera(sc, (0.0, -3.0, 0.95), (0.0, 0.3, 0.08), lens=40)
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
