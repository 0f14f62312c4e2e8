"""Bake Rain: runs `soak bake drops` (the selected mesh's UVs, sheltered by
the rest of the visible scene, as Bake Wet Map does), `soak bake ripples`
and `soak bake rain --frames` (the same mesh and frames: the film running
down steep faces, the water on the flat) in subprocesses (modal,
cancellable with Esc), then loads the frame sequences and wires them into
the wet material (rain.wire): all or nothing.

The frames go to a folder next to the .blend (`//soak_rain/OBJECT/`; a
temporary folder while the file is unsaved): Blender cannot pack image
sequences. A bake is written into a staging folder, renamed to a folder of
its own (OBJECT.NNN) when both bakes succeeded, and removed when wiring
fails; earlier bakes' folders are kept (undo brings their images back)."""

import os
import shutil
import subprocess
import tempfile

import bpy

from .. import material_tree, properties, rain
from ..predicates import poll_message
from ..preferences import find_soak
from .bake import export_scene_obj

RIPPLE_FRAMES = 64        # one flipbook file per scene frame, looping
RIPPLE_TILE = 0.5         # metres (soak bake ripples' default)
RIPPLE_SIZE = 256


def scene_fps(scene):
    return scene.render.fps / scene.render.fps_base


def map_size(ob, settings):
    """Metres across the UV square: the setting, or the object's largest
    horizontal dimension (a plane's side)."""
    if settings.map_size > 0.0:
        return settings.map_size
    return max(ob.dimensions.x, ob.dimensions.y, 1e-3)


def drops_command(exe, mesh, out, s, fps, first, last, width, size_m, shelter):
    dur = (s.end_frame - s.start_frame) / fps
    cmd = [exe, "bake", "drops", "--rate", f"{s.rate:.9g}", "--duration", f"{dur:.9g}", "--fps", f"{fps:.9g}",
           "--map-size", f"{size_m:.9g}", "--width", str(width), "--height", str(width), "--seed", str(s.seed),
           "--dry-time", f"{s.dry_time:.9g}", "--frames", f"{first}-{last}", "--frame-origin", str(first),
           "-o", out]
    if shelter:
        cmd[3:3] = [mesh]
        cmd += ["--up", "z", "--rays", str(s.rays)]
    return cmd


def film_command(exe, mesh, out, s, fps, first, last, width):
    """`soak bake rain --frames` over the drops' frames: file f at t = (f -
    first) / fps, the rain (the drops' rate, mm/h) falling from the first
    frame to the panel's end frame."""
    dur = (s.end_frame - s.start_frame) / fps
    return [exe, "bake", "rain", mesh, "--up", "z", "--rainfall", f"{s.rate:.9g}", "--duration", f"{dur:.9g}",
            "--fps", f"{fps:.9g}", "--width", str(width), "--height", str(width), "--rays", str(s.rays),
            "--seed", str(s.seed), "--frames", f"{first}-{last}", "--frame-origin", str(first), "-o", out]


def ripples_command(exe, out, s, fps):
    return [exe, "bake", "ripples", "--rate", f"{s.rate:.9g}", "--tile", f"{RIPPLE_TILE:.9g}",
            "--width", str(RIPPLE_SIZE), "--height", str(RIPPLE_SIZE), "--loop-frames", str(RIPPLE_FRAMES),
            "--period", f"{RIPPLE_FRAMES / fps:.9g}", "--seed", str(s.seed),
            "--frames", f"0-{RIPPLE_FRAMES - 1}", "-o", out, "--far", far_path(out)]


REACH_REPORT = {
    rain.NEAR: "near only (the whole object is nearer the camera than the far ripples start: one flipbook)",
    rain.FAR: "far only (the whole object is beyond where the far ripples take over: one flipbook)",
    rain.BAND: "near to far blend (the object spans the distances where the far ripples take over)",
}


def ripple_view(scene, mat, ob):
    """The far ripples' distances for the scene's camera and which
    flipbooks the objects showing `mat` need from it, now (a camera moved
    later needs a new bake)."""
    near, far = rain.far_distances(scene)
    return rain.RippleView(near, far, rain.ripple_reach(scene, rain.material_objects(scene, mat, ob), (near, far)))


def far_path(out):
    """The --far flipbook beside the sharp one: ripples.%04d.exr -> ripples_far.%04d.exr."""
    head, tail = os.path.split(out)
    return os.path.join(head, tail.replace("ripples", "ripples_far", 1))


def output_folder(ob):
    """(folder, saved): //soak_rain/OBJECT next to a saved .blend, else a
    temporary folder."""
    name = bpy.path.clean_name(ob.name)
    if bpy.data.filepath:
        return os.path.join(bpy.path.abspath("//soak_rain"), name), True
    return os.path.join(tempfile.gettempdir(), "soak_rain", name), False


def _free_name(base):
    """base, or base.NNN: a name no image has (renaming onto a taken name
    can rename the other image in Blender 3.4)."""
    name, n = base, 0
    while bpy.data.images.get(name) is not None:
        n += 1
        name = f"{base}.{n:03d}"
    return name


def check(context, s):
    """The reason the bake cannot run (a message), or None."""
    ob = context.object
    if not ob.data.uv_layers:
        return f"mesh '{ob.name}' has no UV map: the drops are baked over the UVs"
    if not s.end_frame > s.start_frame:
        return f"the rain ends (frame {s.end_frame}) before it starts (frame {s.start_frame})"
    if context.scene.frame_end < s.start_frame:
        return f"the scene ends (frame {context.scene.frame_end}) before the rain starts (frame {s.start_frame})"
    mat = ob.active_material
    if mat.node_tree is None or not material_tree.group_nodes(mat.node_tree):
        return f"material '{mat.name}' is not wet: Make Wet first, then bake the rain"
    return None


class SOAK_OT_bake_rain(bpy.types.Operator):
    """Bake drops (wetting during the rain, then drying), the film running down steep faces and ripples on puddles over the active mesh's UVs with the soak tool, and animate them in the wet material over the scene's frames. Only the ripple flipbooks the scene camera needs are wired (near, far or both): after moving the camera, bake again"""
    bl_idname = "soak.bake_rain"
    bl_label = "Bake Rain"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        ob = context.object
        if ob is None or ob.type != "MESH":
            return poll_message(cls, "Select a mesh object: the drops are baked over its UVs")
        mat = ob.active_material
        if mat is None:
            return poll_message(cls, f"'{ob.name}' has no material: add one and Make Wet")
        if mat.library is not None:
            return poll_message(cls, "The material is linked from a library: make it local first")
        if mat.node_tree is None or not material_tree.group_nodes(mat.node_tree):
            return poll_message(cls, f"Material '{mat.name}' is not wet: Make Wet first")
        return True

    def _start(self, context):
        s = context.scene.soak_rain
        exe = find_soak(context)
        if exe is None:
            self.report({"ERROR"}, "soak executable not found: set its path in the add-on preferences or put it on PATH")
            return False
        why = check(context, s)
        if why is not None:
            self.report({"ERROR"}, why)
            return False
        ob = context.object
        self._base, self._saved = output_folder(ob)
        parent = os.path.dirname(self._base)
        try:
            os.makedirs(parent, exist_ok=True)
            self._stage = tempfile.mkdtemp(prefix=".staging-", dir=parent)
            mesh = os.path.join(self._stage, "mesh.obj")
            self._counts = export_scene_obj(context, ob, "SCENE" if s.shelter else "NONE", mesh)
        except OSError as e:
            self.report({"ERROR"}, f"cannot write the rain bake's folder {parent}: {e}")
            return False
        sc = context.scene
        fps = scene_fps(sc)
        self._first, self._last = s.start_frame, max(sc.frame_end, s.start_frame + 1)
        self._cmds = [drops_command(exe, mesh, os.path.join(self._stage, "drops.%04d.exr"), s, fps, self._first,
                                    self._last, s.size, map_size(ob, s), s.shelter),
                      ripples_command(exe, os.path.join(self._stage, "ripples.%04d.exr"), s, fps),
                      film_command(exe, mesh, os.path.join(self._stage, "film.%04d.exr"), s, fps, self._first,
                                   self._last, s.size)]
        self._steps = len(self._cmds)
        self._repeat = map_size(ob, s) / RIPPLE_TILE
        self._mat, self._ob, self._scene_start = ob.active_material, ob, sc.frame_start
        self._uv = ob.data.uv_layers.active.name
        self._proc = None
        return self._next()

    def _next(self):
        """Starts the next command; False (and reported) when it cannot."""
        cmd = self._cmds.pop(0)
        try:
            self._proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        except OSError as e:
            shutil.rmtree(self._stage, ignore_errors=True)
            self.report({"ERROR"}, f"cannot run {cmd[0]}: {e}")
            return False
        self._what = " ".join(cmd[1:3])
        return True

    def _failed(self):
        """None when the running command succeeded, else the report."""
        out, err = self._proc.communicate()
        if self._proc.returncode == 0:
            return None
        msg = (err or out or "").strip().splitlines()
        return f"soak {self._what} failed (exit {self._proc.returncode}): {msg[-1] if msg else 'no message'}"

    def _finish(self, context):
        try:
            return self._load(context)
        finally:
            shutil.rmtree(self._stage, ignore_errors=True)

    def _install(self):
        """Renames the staged frames to a folder of their own (the previous
        bake's frames stay until the new ones are wired)."""
        mesh = os.path.join(self._stage, "mesh.obj")
        if os.path.exists(mesh):
            os.remove(mesh)
        n = 1
        while os.path.exists(f"{self._base}.{n:03d}"):
            n += 1
        self._folder = f"{self._base}.{n:03d}"
        os.rename(self._stage, self._folder)

    def _base_name(self, name):
        return f"{self._ob.name} rain {name}"

    def _sequence(self, name, frame, colorspace="Non-Color"):
        path = os.path.join(self._folder, f"{name}.{frame:04d}.exr")
        img = bpy.data.images.load(path, check_existing=False)
        img.source = "SEQUENCE"
        img.colorspace_settings.name = colorspace
        img.name = _free_name(self._base_name(name))   # never renames another image
        img[rain.TAG] = self._ob.name
        img[rain.FOLDER_KEY] = self._folder
        if self._saved:
            img.filepath = bpy.path.relpath(path)
        return img

    def _load(self, context):
        msg = self._failed()
        if msg is not None:
            self.report({"ERROR"}, msg)
            return {"CANCELLED"}
        try:
            self._install()
        except OSError as e:
            self.report({"ERROR"}, f"cannot move the baked frames to {self._folder}: {e}")
            return {"CANCELLED"}
        view = ripple_view(context.scene, self._mat, self._ob)
        drops, film = self._sequence("drops", self._first), self._sequence("film", self._first)
        ripples = self._sequence("ripples", 0) if view.reach != rain.FAR else None
        far = self._sequence("ripples_far", 0) if view.reach != rain.NEAR else None
        loaded = tuple(i for i in (drops, ripples, far, film) if i is not None)
        try:
            rain.wire(self._mat, drops, self._first, self._last, ripples, RIPPLE_FRAMES, self._scene_start,
                      self._repeat, self._uv, far, view, film)
        except Exception as e:         # ours (RuntimeError) or a bug: the tree is back as it was either way
            for img in loaded:
                bpy.data.images.remove(img)
            shutil.rmtree(self._folder, ignore_errors=True)
            why = str(e) if isinstance(e, RuntimeError) else f"{type(e).__name__}: {e}"
            self.report({"ERROR"}, f"rain baked but not wired (frames removed): {why}")
            return {"CANCELLED"}
        # the panel's Source shows the drops (set without re-wiring: the node is in place)
        properties._revert(self._mat.soak, {"wetness_source": "IMAGE", "wet_map": drops})
        rain.drop_old_images(self._ob.name, loaded)
        for img, name in ((drops, "drops"), (ripples, "ripples"), (far, "ripples_far"), (film, "film")):
            if img is not None and bpy.data.images.get(self._base_name(name)) is None:
                img.name = self._base_name(name)
        where = (" (earlier bakes' folders are kept for undo)" if self._saved
                 else " (a temporary folder: save the .blend and bake again to keep them)")
        self.report({"INFO"}, f"rain baked: drops and film frames {self._first}-{self._last} and "
                              f"{RIPPLE_FRAMES} ripple frames in {self._folder}{where}; "
                              f"ripples {REACH_REPORT[view.reach]}")
        return {"FINISHED"}

    def execute(self, context):  # blocking variant (scripts, tests)
        if not self._start(context):
            return {"CANCELLED"}
        while True:
            self._proc.wait()
            if not self._cmds or self._proc.returncode != 0:
                return self._finish(context)
            self._proc.communicate()
            if not self._next():
                return {"CANCELLED"}

    def invoke(self, context, event):
        if not self._start(context):
            return {"CANCELLED"}
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.2, window=context.window)
        wm.progress_begin(0, 100)
        wm.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def _progress(self):
        """(frames written, frames to write) over the three bakes: the files
        in the staging folder (each frame is renamed into place when done)."""
        names = os.listdir(self._stage) if os.path.isdir(self._stage) else []
        done = sum(1 for n in names if n.endswith(".exr") and not n.startswith("."))
        return done, 2 * (self._last - self._first + 1) + 2 * RIPPLE_FRAMES    # drops, film; sharp and far ripples

    def _stop(self, context):
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        context.workspace.status_text_set(None)

    def modal(self, context, event):
        if event.type == "ESC":
            self._proc.terminate()
            self._proc.wait()
            shutil.rmtree(self._stage, ignore_errors=True)
            self._stop(context)
            self.report({"WARNING"}, "rain bake cancelled")
            return {"CANCELLED"}
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        done, total = self._progress()
        step = self._steps - len(self._cmds)     # 1 drops, 2 ripples, 3 film
        context.window_manager.progress_update(min(99, int(100 * done / total)))
        context.workspace.status_text_set(f"Soak: {self._what} ({step}/{self._steps}), {done} of {total} frames... "
                                          "(Esc cancels)")
        if self._proc.poll() is None:
            return {"PASS_THROUGH"}
        if self._cmds and self._proc.returncode == 0:
            self._proc.communicate()
            if self._next():
                return {"PASS_THROUGH"}
            self._stop(context)
            return {"CANCELLED"}
        self._stop(context)
        return self._finish(context)


classes = (SOAK_OT_bake_rain,)
