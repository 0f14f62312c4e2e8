"""Bake Wet Map: runs `soak bake rain` on the active mesh in a subprocess
(modal, cancellable with Esc), then loads the map and selects it as the
material's wetness source (wired in at once when the material is already
wet).

The rain is blocked by the whole visible scene (or a chosen collection, or
nothing): the occluders go into the same OBJ as the active mesh with every
UV at OCCLUDER_UV, outside the unit square, so `soak bake rain` traces them
but rasterises no texel of them (degenerate in UV space)."""

import os
import shutil
import subprocess
import tempfile

import bpy

from ..preferences import find_soak
from ..predicates import poll_message

OCCLUDER_UV = (4.5, 4.5)
# Bake Wet Map's default rain, seconds at 10 mm/h: open flat ground reaches
# 1 - exp(-(10 - 0.5) mm/h * 60 s / 0.2 mm) = 0.55 while sheltered ground is
# still dry; past ~76 s the film overflows and flows under the shelters
# (soak bake rain's routing), and by 600 s (the CLI's default) the map is
# almost uniform (issue 46: 0.1137 vs 0.1136 rendered).
DEFAULT_RAIN_S = 60.0
OCCLUDER_TYPES = {"MESH", "CURVE", "SURFACE", "META", "FONT"}


def _write_mesh(f, ev, matrix, base, uv):
    """Appends an evaluated object's triangles, transformed by `matrix`
    (world space), to an OBJ file; uv: True for the mesh's active UV map,
    else OCCLUDER_UV. Returns the number of triangles written."""
    me = ev.to_mesh()
    if me is None:
        return 0
    try:
        me.calc_loop_triangles()
        for v in me.vertices:
            p = matrix @ v.co
            f.write(f"v {p.x:.9g} {p.y:.9g} {p.z:.9g}\n")
        uvl = me.uv_layers.active if uv else None
        if uvl is not None:
            for d in uvl.data:
                f.write(f"vt {d.uv[0]:.9g} {d.uv[1]:.9g}\n")
        else:
            f.write(f"vt {OCCLUDER_UV[0]} {OCCLUDER_UV[1]}\n")
        for tri in me.loop_triangles:
            vs = [base["v"] + i + 1 for i in tri.vertices]
            ts = [base["vt"] + l + 1 for l in tri.loops] if uvl is not None else [base["vt"] + 1] * 3
            f.write("f " + " ".join(f"{a}/{b}" for a, b in zip(vs, ts)) + "\n")
        base["v"] += len(me.vertices)
        base["vt"] += len(uvl.data) if uvl is not None else 1
        return len(me.loop_triangles)
    finally:
        ev.to_mesh_clear()


def check_occluders(mode, collection_name=""):
    """Raises RuntimeError for a Shelter setting that names nothing."""
    if mode == "COLLECTION" and bpy.data.collections.get(collection_name) is None:
        raise RuntimeError(f"no collection named '{collection_name}' for the occluders")


def _shelters(inst, ob, mode, members):
    """True for a depsgraph instance that blocks the rain on `ob`: visible
    geometry (instances included: collection instances, particles, geometry
    nodes) other than `ob` itself, from the whole scene or a collection."""
    owner = inst.parent.original if inst.is_instance and inst.parent is not None else inst.object.original
    if inst.object.type not in OCCLUDER_TYPES or owner.hide_render:
        return False
    if not inst.is_instance and inst.object.original == ob:
        return False
    if mode == "COLLECTION":
        return owner in members or inst.object.original in members
    return True


def export_scene_obj(context, ob, mode, path, collection_name=""):
    """The active mesh (with its UVs) and the rain's shelter (mode SCENE:
    everything visible; COLLECTION: one collection's objects; NONE) in one
    OBJ, world space, Blender's Z up. Returns (triangles of ob, occluder
    triangles)."""
    check_occluders(mode, collection_name)
    depsgraph = context.evaluated_depsgraph_get()
    members = set(bpy.data.collections[collection_name].all_objects) if mode == "COLLECTION" else set()
    base = {"v": 0, "vt": 0}
    with open(path, "w", encoding="utf-8") as f:
        f.write("# soak bake rain: active mesh, then occluders (UVs outside the unit square)\no target\n")
        ev = ob.evaluated_get(depsgraph)
        n = _write_mesh(f, ev, ev.matrix_world.copy(), base, True)
        m = 0
        if mode != "NONE":
            for inst in depsgraph.object_instances:
                if _shelters(inst, ob, mode, members):
                    f.write(f"o occluder_{m}\n")
                    m += _write_mesh(f, inst.object, inst.matrix_world.copy(), base, False)
    return n, m


def bake_command(exe, mesh_path, out_path, size, rays, duration, rain_from=(0.0, 0.0, 1.0), spread=10.0,
                 exposure_path=None):
    """rain_from: the direction the rain comes from, world space (the OBJ's
    frame, Z up); spread: the rain cone's half-angle, degrees; exposure_path:
    also write the sky exposure there."""
    cmd = [exe, "bake", "rain", mesh_path, "-o", out_path, "--width", str(size), "--height", str(size),
           "--rays", str(rays), "--duration", str(duration), "--up", "z",
           "--rain-dir", ",".join(f"{c:.9g}" for c in rain_from), "--spread", f"{spread:.9g}"]
    if exposure_path:
        cmd += ["--exposure", exposure_path]
    return cmd


# The image a bake made is tagged with its object's name: the next bake of
# the same object replaces it (same name, its users moved to the new one).
BAKE_TAG = "soak_baked_for"


def replace_baked_image(img, owner):
    """Makes `img` the one baked wet map of object `owner`: an earlier bake's
    image of it hands its users over and is removed, and `img` takes its
    name. Images the user made or opened are never touched."""
    img[BAKE_TAG] = owner
    for old in [i for i in bpy.data.images if i != img and i.get(BAKE_TAG) == owner]:
        name = old.name
        old.user_remap(img)
        bpy.data.images.remove(old)
        img.name = name
    return img


class SOAK_OT_bake_wetmap(bpy.types.Operator):
    """Bake a rain wet map over the active mesh's UVs with the soak tool (sheltered by the visible scene), and use it as the material's wetness source"""
    bl_idname = "soak.bake_wetmap"
    bl_label = "Bake Wet Map"
    bl_options = {"REGISTER"}

    size: bpy.props.IntProperty(name="Size", default=256, min=8, max=8192,
                                description="Width and height of the wet map, pixels")
    rays: bpy.props.IntProperty(name="Rays", default=32, min=1, max=4096,
                                description="Rays per texel for the sky exposure (more: less noise, slower)")
    duration: bpy.props.FloatProperty(
        name="Rain Duration (s)", default=DEFAULT_RAIN_S, min=0.0, soft_max=86400.0,
        description="How long it rains before the map is taken, in seconds (10 mm/h). The default, one "
                    "minute, leaves open ground about half wet and sheltered ground dry: the rain shadow shows. "
                    "After about 76 s open flat ground holds its full 0.2 mm film and the extra water runs "
                    "downhill and spreads, under shelters too: after 10 minutes a flat floor is wet almost "
                    "everywhere. 0 bakes the sky exposure instead (1 open to the rain, 0 sheltered)")
    occluders: bpy.props.EnumProperty(
        name="Shelter", default="SCENE",
        description="What blocks the rain besides the mesh itself",
        items=(("SCENE", "Visible Scene", "Every visible, renderable object of the view layer, instances included"),
               ("COLLECTION", "Collection", "The objects of one collection"),
               ("NONE", "Nothing", "The active mesh alone")))
    rain_from: bpy.props.FloatVectorProperty(
        name="Rain From", size=3, subtype="DIRECTION", default=(0.0, 0.0, 1.0),
        description="Direction the rain comes from, world space (straight down: 0, 0, 1; wind-driven rain "
                    "tilts it towards the wind)")
    spread: bpy.props.FloatProperty(
        name="Spread", default=10.0, min=0.0, max=89.0, subtype="NONE",
        description="Half-angle of the cone of rain directions around Rain From, degrees")
    collection: bpy.props.StringProperty(name="Collection", default="",
                                         description="Collection whose objects block the rain (Shelter: "
                                                     "Collection)")

    @classmethod
    def poll(cls, context):
        ob = context.object
        if ob is None or ob.type != "MESH":
            return poll_message(cls, "Select a mesh object: the wet map is baked over its UVs")
        if ob.active_material is None:
            return poll_message(cls, f"'{ob.name}' has no material to receive the wet map")
        if ob.active_material.library is not None:
            return poll_message(cls, "The material is linked from a library: make it local first")
        return True

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        for p in ("size", "rays", "duration", "rain_from", "spread", "occluders"):
            layout.prop(self, p)
        if self.occluders == "COLLECTION":
            layout.prop_search(self, "collection", bpy.data, "collections")

    def _start(self, context):
        exe = find_soak(context)
        if exe is None:
            self.report({"ERROR"}, "soak executable not found: set its path in the add-on preferences or put it on PATH")
            return False
        ob = context.object
        if not ob.data.uv_layers:
            self.report({"ERROR"}, f"mesh '{ob.name}' has no UV map: the wet map is baked over the UVs")
            return False
        if not sum(c * c for c in self.rain_from) > 1e-12:
            self.report({"ERROR"}, "Rain From is a zero vector: give the direction the rain comes from")
            return False
        if not self.rain_from[2] > 0.0:
            self.report({"ERROR"}, f"Rain From {tuple(round(c, 3) for c in self.rain_from)} points below the "
                                   "horizon: the rain must come from above (positive Z)")
            return False
        try:
            check_occluders(self.occluders, self.collection)
        except RuntimeError as e:
            self.report({"ERROR"}, str(e))
            return False
        self._dir = tempfile.mkdtemp(prefix="soak_bake_")
        mesh = os.path.join(self._dir, "mesh.obj")
        self._out = os.path.join(self._dir, f"{bpy.path.clean_name(ob.name)}_wet.exr")
        # no rain: the wetness would be all zero; the map is the sky exposure
        self._exposure = self._out if self.duration == 0.0 else None
        wet_out = os.path.join(self._dir, "wetness.exr") if self._exposure else self._out
        try:
            self._counts = export_scene_obj(context, ob, self.occluders, mesh, self.collection)
        except OSError as e:
            shutil.rmtree(self._dir, ignore_errors=True)
            self.report({"ERROR"}, f"cannot write the mesh for soak: {e}")
            return False
        cmd = bake_command(exe, mesh, wet_out, self.size, self.rays, self.duration, tuple(self.rain_from),
                           self.spread, self._exposure)
        try:
            self._proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        except OSError as e:
            shutil.rmtree(self._dir, ignore_errors=True)
            self.report({"ERROR"}, f"cannot run {exe}: {e}")
            return False
        self._mat = ob.active_material
        self._owner = ob.name
        return True

    def _finish(self, context):
        try:
            return self._load(context)
        finally:
            shutil.rmtree(self._dir, ignore_errors=True)

    def _load(self, context):
        out, err = self._proc.communicate()
        if self._proc.returncode != 0:
            msg = (err or out or "").strip().splitlines()
            self.report({"ERROR"}, f"soak bake failed (exit {self._proc.returncode}): {msg[-1] if msg else 'no message'}")
            return {"CANCELLED"}
        img = bpy.data.images.load(self._out, check_existing=False)
        img.colorspace_settings.name = "Non-Color"
        img.pack()
        s = self._mat.soak
        old = (s.wet_map, s.wetness_source)
        s.status = ""
        s.wet_map = img
        s.wetness_source = "IMAGE"
        if s.status:                       # the wet material refused the new source: keep it as it was
            msg = s.status
            s.wet_map, s.wetness_source = old
            s.status = ""
            self.report({"ERROR"}, f"wet map baked ({img.name}) but not wired: {msg}")
            return {"CANCELLED"}
        replace_baked_image(img, self._owner)
        n, m = self._counts
        what = "sky exposure (no rain)" if self._exposure else "wet map"
        self.report({"INFO"}, f"{what} baked: {img.name} ({n} triangles, sheltered by {m} occluder triangles)")
        return {"FINISHED"}

    def execute(self, context):  # blocking variant (scripts, tests)
        if not self._start(context):
            return {"CANCELLED"}
        self._proc.wait()
        return self._finish(context)

    def invoke(self, context, event):
        if not self._start(context):
            return {"CANCELLED"}
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.2, window=context.window)
        self._ticks = 0
        wm.progress_begin(0, 100)
        wm.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def _stop(self, context):
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()

    def modal(self, context, event):
        if event.type == "ESC":
            self._proc.terminate()
            self._proc.wait()
            shutil.rmtree(self._dir, ignore_errors=True)
            self._stop(context)
            context.workspace.status_text_set(None)
            self.report({"WARNING"}, "wet-map bake cancelled")
            return {"CANCELLED"}
        if event.type == "TIMER":
            self._ticks += 1
            context.window_manager.progress_update(min(99, self._ticks))
            context.workspace.status_text_set("Soak: baking wet map... (Esc cancels)")
            if self._proc.poll() is not None:
                self._stop(context)
                context.workspace.status_text_set(None)
                return self._finish(context)
        return {"PASS_THROUGH"}


classes = (SOAK_OT_bake_wetmap,)
