"""Rain over time in a wet material (issue 37): the drops bake's frame
sequence as the wetness source, the wetter of it and the rain bake's frame
(the film on steep faces) into the Wet Map, the ripple flipbook as a normal
mixed in where the drops reach the puddle level.

Kept apart from wet_group.py and the material surgery (insertion.py, sources.py, ...): it only adds nodes around the
Soak Wet group node (tagged like the other nodes Make Wet adds, so Make Dry
removes them) and never changes the group itself.

  drops frame (the wetness source, role "source")
       |    rain frame (`soak bake rain --frames`: the film running down steep
       |    faces, water on the flat)
       |      |
       +------+--> Maximum  -->  group Wet Map
       |
       +--> Greater Than (Puddle Level - 1e-4, kept equal by the panel's Puddle Level) = mask
  ripple frame, far ripple frame (the --far flipbook) mixed by
    f = smoothstep(near, far, Camera Data View Distance)
    --> Normal Map (tangent, the mesh's UVs) = r
  base normal (the user's link into the group's Normal, else Geometry Normal) = b
  normalize(b + mask (r - b))  -->  group Normal

The far flipbook is the sharp one low-passed (`soak bake ripples --far`):
where a pixel covers more than half the rings' wavelength the sharp rings
alias into noise, so the far one takes over there. `far` is the distance
at which a pixel of the scene's camera spans half a wavelength (set when
wired, from the camera and resolution; far_distances), `near` half of it.
The mix is of the encoded colours (a linear blend of the two textures, as a
texture's own mip levels blend), before the Normal Map node.

Only what the shot needs is wired (ripple_reach, decided at wiring time
from the camera and the bounding boxes of the objects showing the
material): all nearer than `near`, the sharp flipbook alone; all farther
than `far`, the far one alone; else both and the blend. Cycles evaluates
every lookup that reaches the output, whatever the blend factor: one lookup
instead of two and no blend cost ~0.12 x the wet group less (Blender 5.2,
c_core/bench/results/2026-11-29-blender-ripples.md). The ripple Normal Map
node's label says which ("Ripples: near only"); a camera moved later needs
a new Bake Rain for the choice to follow.

Image sequences (Blender's image user, ``BKE_image_user_frame_get``): the
file number is clamp(scene frame - frame_start + 1, 0, duration) +
frame_offset, or with cycling the same modulo duration (0 -> duration)."""

import math

import bpy
import mathutils

from . import checks, material_tree, snapshot, sources

RAIN_ROLE = "rain"
BASE_KEY = "soak_rain_base"      # on the node whose input 0 takes the base normal
MASK_KEY = "soak_rain_flood"     # on the Greater Than node: its threshold follows Puddle Level
FLOOD_EPS = 1e-4                 # a texel at the puddle level floods (float rounding)


def drops_user(iu, first, last):
    """Image user of the drops sequence drops.<first>..<last>: file f at
    scene frame f, the first file before it, the last after it (no missing
    frame, no cycling). Scene frame F maps to clamp(F - first, 0, last -
    first) + first."""
    iu.frame_duration = max(1, last - first)
    iu.frame_start = first + 1
    iu.frame_offset = first
    iu.use_cyclic = False
    iu.use_auto_refresh = True


def ripples_user(iu, frames, scene_start):
    """Image user of the looping flipbook ripples.0000..<frames-1>: file 0
    at the scene's first frame, one file per scene frame, cycling."""
    iu.frame_duration = frames
    iu.frame_start = scene_start
    iu.frame_offset = -1
    iu.use_cyclic = True
    iu.use_auto_refresh = True


def _node(tree, kind, x, y, label):
    return material_tree.new_node(tree, kind, x, y, label, RAIN_ROLE)


def rain_nodes(tree):
    return material_tree.role_nodes(tree, RAIN_ROLE)


def _base_normal(tree, gn):
    """The normal the ripples bend: what feeds the group's Normal now, seen
    through an earlier rain mix (then its base), or None (the surface's)."""
    links = gn.inputs["Normal"].links
    if not links:
        return None
    src = links[0].from_socket
    if src.node.get(material_tree.ROLE_KEY) != RAIN_ROLE:
        return src
    base = next((n for n in rain_nodes(tree) if n.get(BASE_KEY)), None)
    if base is None or not base.inputs[0].links:
        return None
    src = base.inputs[0].links[0].from_socket
    return None if src.node.get(material_tree.ROLE_KEY) == RAIN_ROLE else src


def _drops_node(tree, gn, drops, first, last):
    n = _node(tree, "ShaderNodeTexImage", gn.location.x - 700, gn.location.y - 200, "Soak Rain: drops")
    n[material_tree.ROLE_KEY] = "source"                 # the wetness source: the panel's Source, Make Dry
    n.image = drops
    n.extension = "EXTEND"
    n.interpolation = "Linear"
    drops_user(n.image_user, first, last)
    return n


RIPPLE_WAVELENGTH = 0.0171      # m, soak bake ripples' default carrier
FAR_KEY = "soak_rain_far"        # on the Map Range node: From Min / Max are near / far (m)


def far_distances(scene, wavelength=RIPPLE_WAVELENGTH):
    """(near, far) camera distances in metres: at `far` one pixel of the
    scene's camera spans half the rings' wavelength (the sharp flipbook
    aliases beyond it), `near` = far / 2. An orthographic camera's pixel
    has one size at every distance: all near (1e6 m) or all far (0 m)."""
    cam = scene.camera
    res = max(scene.render.resolution_x, scene.render.resolution_y) * scene.render.resolution_percentage / 100
    if cam is None or cam.type != "CAMERA" or res < 1:
        return 5.0, 10.0
    if cam.data.type == "ORTHO":
        far = 1e6 if cam.data.ortho_scale / res < wavelength / 2 else 1e-6
        return far / 2, far
    pixel = 2.0 * math.tan(cam.data.angle / 2) / res      # radians: angle spans the larger side
    far = wavelength / 2 / max(pixel, 1e-9)
    return far / 2, far


NEAR, FAR, BAND = "NEAR", "FAR", "BAND"
REACH_KEY = "soak_rain_reach"    # on the ripple Normal Map node: which flipbooks were wired
REACH_LABEL = {NEAR: "near only", FAR: "far only", BAND: "near to far blend"}


class RippleView(tuple):
    """(near, far) metres plus `reach`: the flipbooks the objects need
    (NEAR: the sharp one alone, FAR: the far one alone, BAND: both and the
    blend). Unpacks and indexes like the (near, far) pair."""
    def __new__(cls, near, far, reach):
        view = super().__new__(cls, (near, far))
        view.reach = reach
        return view


def _closest_on_box(m, lo, hi, p):
    """The point of the box lo..hi (local) under the affine map m nearest
    to world point p: coordinate descent on |m u - p|^2 over the box, which
    is convex, so it reaches the minimum (exact in one sweep when m's
    columns are orthogonal, as without shear)."""
    cols = [m.col[i].xyz for i in range(3)]
    u = [(a + b) / 2 for a, b in zip(lo, hi)]

    def at(u):
        return m.translation + cols[0] * u[0] + cols[1] * u[1] + cols[2] * u[2]

    for _ in range(64):
        for i in range(3):
            r = at(u) - cols[i] * u[i] - p              # the residual without coordinate i
            c2 = cols[i].length_squared
            u[i] = min(max(-r.dot(cols[i]) / c2 if c2 > 0.0 else lo[i], lo[i]), hi[i])
    return at(u)


def ripple_reach(scene, objects, distances):
    """NEAR when every point of the objects' bounding boxes is nearer the
    scene camera than `near` (the blend is all sharp there), FAR when every
    point is farther than `far`, else BAND. Farthest point: a box corner;
    nearest: the box's point nearest the camera. An orthographic camera's
    pixel has one size everywhere (far_distances gives 5e5..1e6 m or
    ~0 m): near or far by pixel size. No camera or no object: BAND."""
    cam = scene.camera
    boxes = [ob for ob in objects if ob.type == "MESH"]
    if cam is None or cam.type != "CAMERA" or not boxes:
        return BAND
    near, far = distances
    if cam.data.type == "ORTHO":
        return NEAR if far > 1.0 else FAR
    eye = cam.matrix_world.translation
    lo_d, hi_d = math.inf, 0.0
    for ob in boxes:
        m = ob.matrix_world
        corners = [m @ mathutils.Vector(c) for c in ob.bound_box]
        hi_d = max(hi_d, max((c - eye).length for c in corners))
        lo = [min(c[i] for c in ob.bound_box) for i in range(3)]
        hi = [max(c[i] for c in ob.bound_box) for i in range(3)]
        lo_d = min(lo_d, (_closest_on_box(m, lo, hi, eye) - eye).length)
    if hi_d <= near:
        return NEAR
    if lo_d >= far:
        return FAR
    return BAND


def material_objects(scene, mat, ob):
    """`ob` and the scene's other mesh objects showing `mat` (one wiring
    serves them all)."""
    users = [o for o in scene.objects if o.type == "MESH" and o is not ob
             and any(slot.material == mat for slot in o.material_slots)]
    return [ob] + users


def _flipbook(tree, image, frames, scene_start, x, y, label):
    tex = _node(tree, "ShaderNodeTexImage", x, y, label)
    tex.image = image
    tex.extension = "REPEAT"
    tex.interpolation = "Linear"
    ripples_user(tex.image_user, frames, scene_start)
    return tex


def _far_mix(tree, sharp, far, distances, x, y):
    """sharp + f (far - sharp), f = smoothstep over the view distance."""
    cam = _node(tree, "ShaderNodeCameraData", x, y - 420, "Soak Rain: view distance")
    mr = _node(tree, "ShaderNodeMapRange", x + 180, y - 420, "Soak Rain: far ripples")
    mr.interpolation_type = "SMOOTHSTEP"
    mr.clamp = True
    mr[FAR_KEY] = True
    mr.inputs["From Min"].default_value, mr.inputs["From Max"].default_value = distances
    tree.links.new(cam.outputs["View Distance"], mr.inputs["Value"])
    d = _vmath(tree, "SUBTRACT", x + 180, y - 260, "Soak Rain: far - sharp")
    sc = _vmath(tree, "SCALE", x + 360, y - 260, "Soak Rain: by distance")
    a = _vmath(tree, "ADD", x + 540, y - 260, "Soak Rain: ripple colour")
    tree.links.new(far.outputs["Color"], d.inputs[0])
    tree.links.new(sharp.outputs["Color"], d.inputs[1])
    tree.links.new(d.outputs["Vector"], sc.inputs[0])
    tree.links.new(mr.outputs["Result"], sc.inputs["Scale"])
    tree.links.new(sharp.outputs["Color"], a.inputs[0])
    tree.links.new(sc.outputs["Vector"], a.inputs[1])
    return a.outputs["Vector"]


def _ripple_normal(tree, gn, ripples, frames, scene_start, repeat, uv_map, far=None, distances=(5.0, 10.0)):
    """The ripple normal. `distances` a RippleView: its reach picks the
    flipbooks (NEAR: `ripples` alone, FAR: `far` alone, BAND: both mixed
    by view distance); a plain (near, far) pair: BAND when `far` is given,
    else `ripples` alone."""
    reach = getattr(distances, "reach", BAND if far is not None else NEAR)
    if far is None and reach != NEAR:
        raise RuntimeError("the far ripple flipbook is needed here but was not given")
    x, y = gn.location.x - 1000, gn.location.y - 500
    uv = _node(tree, "ShaderNodeTexCoord", x, y, "Soak Rain: UV")
    mp = _node(tree, "ShaderNodeMapping", x + 180, y, "Soak Rain: ripple tiles")
    mp.inputs["Scale"].default_value = (repeat, repeat, 1.0)
    first = far if reach == FAR else ripples
    tex = _flipbook(tree, first, frames, scene_start, x + 360, y,
                    "Soak Rain: far ripples" if reach == FAR else "Soak Rain: ripples")
    nm = _node(tree, "ShaderNodeNormalMap", x + 640, y, f"Ripples: {REACH_LABEL[reach]}")
    nm[REACH_KEY] = reach
    nm.space = "TANGENT"
    nm.uv_map = uv_map
    tree.links.new(uv.outputs["UV"], mp.inputs["Vector"])
    tree.links.new(mp.outputs["Vector"], tex.inputs["Vector"])
    colour = tex.outputs["Color"]
    if reach == BAND:
        ftex = _flipbook(tree, far, frames, scene_start, x + 360, y - 280, "Soak Rain: far ripples")
        tree.links.new(mp.outputs["Vector"], ftex.inputs["Vector"])
        colour = _far_mix(tree, tex, ftex, tuple(distances), x + 360, y)
    tree.links.new(colour, nm.inputs["Color"])
    return nm.outputs["Normal"]


def _vmath(tree, op, x, y, label):
    n = _node(tree, "ShaderNodeVectorMath", x, y, label)
    n.operation = op
    return n


def _flood_mix(tree, gn, wet, ripple, base):
    """normalize(b + mask (r - b)), mask = wet > Puddle Level - eps."""
    x, y = gn.location.x - 360, gn.location.y - 420
    mask = _node(tree, "ShaderNodeMath", x - 180, y + 160, "Soak Rain: flooded")
    mask.operation = "GREATER_THAN"
    tree.links.new(wet, mask.inputs[0])
    mask[MASK_KEY] = True
    mask.inputs[1].default_value = gn.inputs["Puddle Level"].default_value - FLOOD_EPS
    if base is None:
        geo = _node(tree, "ShaderNodeNewGeometry", x - 360, y - 120, "Soak Rain: surface normal")
        base = geo.outputs["Normal"]
    d = _vmath(tree, "SUBTRACT", x - 180, y - 40, "Soak Rain: ripple - base")
    s = _vmath(tree, "SCALE", x, y, "Soak Rain: where flooded")
    a = _vmath(tree, "ADD", x + 180, y, "Soak Rain: base + ripple")
    a[BASE_KEY] = True
    nz = _vmath(tree, "NORMALIZE", x + 360, y, "Soak Rain: normal")
    tree.links.new(ripple, d.inputs[0])
    tree.links.new(base, d.inputs[1])
    tree.links.new(d.outputs["Vector"], s.inputs[0])
    tree.links.new(mask.outputs[0], s.inputs["Scale"])
    tree.links.new(base, a.inputs[0])
    tree.links.new(s.outputs["Vector"], a.inputs[1])
    tree.links.new(a.outputs["Vector"], nz.inputs[0])
    return nz.outputs["Vector"], mask


def sync_level(mat):
    """Sets the flood threshold of a material's rain mix to its group's
    Puddle Level (the panel's Puddle Level calls it, and wiring). Not a
    driver: a driver reading the tree it drives is a dependency cycle."""
    tree = mat.node_tree if mat is not None else None
    gns = material_tree.group_nodes(tree) if tree is not None else []
    if not gns:
        return
    level = gns[0].inputs["Puddle Level"].default_value
    for n in rain_nodes(tree):
        if n.get(MASK_KEY):
            n.inputs[1].default_value = level - FLOOD_EPS


def _film_max(tree, gn, drops_wet, film, first, last):
    """max(drops frame, rain frame): the rain bake's sequence (same frames
    as the drops) read like the drops, the larger wetness wins."""
    tex = _node(tree, "ShaderNodeTexImage", gn.location.x - 700, gn.location.y + 100, "Soak Rain: film")
    tex.image = film
    tex.extension = "EXTEND"
    tex.interpolation = "Linear"
    drops_user(tex.image_user, first, last)
    mx = _node(tree, "ShaderNodeMath", gn.location.x - 400, gn.location.y - 60, "Soak Rain: wetter of drops, film")
    mx.operation = "MAXIMUM"
    mx.use_clamp = False
    tree.links.new(drops_wet, mx.inputs[0])
    tree.links.new(tex.outputs["Color"], mx.inputs[1])
    return mx.outputs["Value"]


def _wire(mat, gns, drops, first, last, ripples, frames, scene_start, repeat, uv_map, far, distances, film):
    tree = mat.node_tree
    gn = gns[0]
    old = rain_nodes(tree) + sources.source_nodes(tree)
    base = _base_normal(tree, gn)
    src = _drops_node(tree, gn, drops, first, last)
    wet = src.outputs["Color"]
    ripple = _ripple_normal(tree, gn, ripples, frames, scene_start, repeat, uv_map, far, distances)
    normal, mask = _flood_mix(tree, gn, wet, ripple, base)    # ripples where the drops flood (not on a film)
    if film is not None:
        wet = _film_max(tree, gn, wet, film, first, last)
    for g in gns:
        tree.links.new(wet, g.inputs["Wet Map"])
        tree.links.new(normal, g.inputs["Normal"])
    # nothing below can fail: the old nodes go last (a snapshot cannot bring them back)
    for n in old:
        tree.nodes.remove(n)
    material_tree.record_our_nodes(tree, gns)
    return src


def wire(mat, drops, first, last, ripples, frames, scene_start, repeat, uv_map, far=None, distances=(5.0, 10.0),
         film=None):
    """Wires a baked drops sequence (files first..last, file f = scene frame
    f; with `film`, the rain bake's sequence of the same frames, the wetter
    of the two) and ripple flipbook (`frames` files from 0, looping from the scene's
    first frame, `repeat` tiles across the UV square) into a wet material;
    with `far` (the --far flipbook, same frames) blended in from distances
    (near, far) metres from the camera on (far_distances); `distances` a
    RippleView wires only the flipbooks its reach names (ripple_reach).
    All or nothing: on failure the tree is as before."""
    tree = mat.node_tree
    gns = material_tree.group_nodes(tree) if tree is not None else []
    if not gns:
        raise RuntimeError(f"material '{mat.name}' is not wet: Make Wet first, then bake the rain")
    checks.check_editable(mat)
    if any(material_tree.RESTORE_KEY not in g for g in gns):
        raise RuntimeError(f"material '{mat.name}': a Soak Wet node has no restore record (Make Dry, then Make Wet)")
    return snapshot.atomic(tree, _wire, mat, gns, drops, first, last, ripples, frames, scene_start, repeat, uv_map,
                           far, distances, film)


TAG = "soak_rain_for"            # on the images a rain bake loaded: the object's name
FOLDER_KEY = "soak_rain_folder"  # ... and the folder holding their frames


def drop_old_images(owner, keep):
    """After a new bake of `owner` is wired: the earlier bakes' images,
    now unused, go. Their frame folders stay: undo brings the images back,
    and they must find their files."""
    for img in [i for i in bpy.data.images if i.get(TAG) == owner and i not in keep and i.users == 0]:
        bpy.data.images.remove(img)
