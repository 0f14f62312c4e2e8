"""Bake Rain: runs `soak bake drops` (the selected mesh's UVs, sheltered by
the rest of the visible scene, as Bake Wet Map does), `soak bake ripples`
and `soak bake rain --frames` (the same mesh and frames: the film running
down steep faces, the water on the flat), the three at once in
subprocesses (modal, cancellable with Esc, a progress bar in the status
bar), then loads the frame sequences and wires them into the wet material
(rain.wire): all or nothing.

Time: the drops and the film are simulated at the panel's Time Scale
(simulated seconds per frame; frame f is at t = (f - Start Frame) x scale),
so a normal shot covers the minutes rain takes to wet a surface (about 76 s
of 10 mm/h fill the 0.2 mm film a flat surface holds). The ripples are a
splash pattern seen in real time: their flipbook runs at the scene's frame
rate and depends only on the rate and seed, so it is kept in a cache folder
beside the bakes and reused by the next bake with the same rate and seed.

The frames go to a folder next to the .blend (`//soak_rain/OBJECT/`; a
temporary folder while the file is unsaved): Blender cannot pack image
sequences. A bake is written into a staging folder, renamed to a folder of
its own (OBJECT.NNN) when both bakes succeeded, and removed when wiring
fails; earlier bakes' folders are kept (undo brings their images back)."""

import hashlib
import math
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


def seconds_per_frame(settings):
    """Simulated seconds per scene frame (the panel's Time Scale)."""
    return settings.seconds_per_frame


def rain_seconds(settings):
    """Simulated seconds of rain: Start Frame to End Frame at the Time Scale."""
    return (settings.end_frame - settings.start_frame) * seconds_per_frame(settings)


def drops_command(exe, mesh, out, s, first, last, width, size_m, shelter):
    """`soak bake drops`: file f at t = (f - first) x Time Scale."""
    sim_fps = 1.0 / seconds_per_frame(s)
    cmd = [exe, "bake", "drops", "--rate", f"{s.rate:.9g}", "--duration", f"{rain_seconds(s):.9g}",
           "--fps", f"{sim_fps:.9g}", "--map-size", f"{size_m:.9g}", "--width", str(width), "--height", str(width),
           "--seed", str(s.seed), "--dry-time", f"{s.dry_time:.9g}", "--frames", f"{first}-{last}",
           "--frame-origin", str(first), "-o", out]
    if s.splashes:
        cmd.append("--splash")
    if shelter:
        cmd[3:3] = [mesh]
        cmd += ["--up", "z", "--rays", str(s.rays)]
    return cmd


def runnel_options(s, preset):
    """The film bake's runnel options: the panel's Runnels (the preset's
    contact angle, a given one in degrees, or none)."""
    if s.runnels == "PRESET":
        return ["--preset", preset]
    if s.runnels == "CUSTOM" and s.contact_angle > 0.0:
        return ["--contact-angle", f"{math.degrees(s.contact_angle):.6g}"]   # a float32 angle: 6 digits
    return []


def film_command(exe, mesh, out, s, first, last, width, preset="concrete"):
    """`soak bake rain --frames` over the drops' frames and times: the
    rain (the drops' rate, mm/h) falling from the first frame to the
    panel's end frame; runnels as the panel says (`preset`: the
    material's)."""
    sim_fps = 1.0 / seconds_per_frame(s)
    return [exe, "bake", "rain", mesh, "--up", "z", "--rainfall", f"{s.rate:.9g}",
            "--duration", f"{rain_seconds(s):.9g}", "--fps", f"{sim_fps:.9g}", "--width", str(width),
            "--height", str(width), "--rays", str(s.rays), "--seed", str(s.seed), "--frames", f"{first}-{last}",
            "--frame-origin", str(first), "-o", out] + runnel_options(s, preset)


def ripples_command(exe, out, s, fps):
    return [exe, "bake", "ripples", "--rate", f"{s.rate:.9g}", "--tile", f"{RIPPLE_TILE:.9g}",
            "--width", str(RIPPLE_SIZE), "--height", str(RIPPLE_SIZE), "--loop-frames", str(RIPPLE_FRAMES),
            "--period", f"{RIPPLE_FRAMES / fps:.9g}", "--seed", str(s.seed),
            "--frames", f"0-{RIPPLE_FRAMES - 1}", "-o", out, "--far", far_path(out)]


RIPPLE_NAMES = ("ripples", "ripples_far")


def ripple_cache(parent, exe, s, fps):
    """The folder holding the ripple flipbooks of these settings (a key of
    everything the ripples bake reads, and the soak binary's size and
    time: a rebuilt soak bakes again)."""
    try:
        st = os.stat(exe)
        tool = f"{st.st_size}-{int(st.st_mtime)}"
    except OSError:
        tool = "unknown"
    key = f"{s.rate:.9g}|{s.seed}|{fps:.9g}|{RIPPLE_SIZE}|{RIPPLE_FRAMES}|{RIPPLE_TILE:.9g}|{tool}"
    digest = hashlib.sha1(key.encode()).hexdigest()[:16]
    return os.path.join(parent, ".ripple-cache", digest)


def _ripple_files(folder):
    return [os.path.join(folder, f"{n}.{k:04d}.exr") for n in RIPPLE_NAMES for k in range(RIPPLE_FRAMES)]


def ripples_cached(cache):
    return all(os.path.isfile(f) for f in _ripple_files(cache))


def _link_or_copy(src, dst):
    try:
        os.link(src, dst)
    except OSError:
        shutil.copy2(src, dst)


def take_cached_ripples(cache, stage):
    """Puts the cached flipbooks into the staging folder; False when the
    cache is incomplete or cannot be read."""
    if not ripples_cached(cache):
        return False
    try:
        for f in _ripple_files(cache):
            _link_or_copy(f, os.path.join(stage, os.path.basename(f)))
    except OSError:
        return False
    return True


def keep_ripples(stage, cache):
    """Copies a fresh ripple bake into the cache (best effort: a cache that
    cannot be written only costs the next bake its time)."""
    tmp = cache + f".tmp{os.getpid()}"
    try:
        os.makedirs(tmp, exist_ok=True)
        for f in _ripple_files(stage):
            _link_or_copy(f, os.path.join(tmp, os.path.basename(f)))
        if os.path.isdir(cache):
            shutil.rmtree(cache, ignore_errors=True)
        os.rename(tmp, cache)
    except OSError:
        shutil.rmtree(tmp, ignore_errors=True)


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
    if not seconds_per_frame(s) > 0.0:
        return f"Time Scale is {seconds_per_frame(s):g} s per frame: give a positive number of seconds"
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
        self._cache = ripple_cache(parent, exe, s, fps)
        self._cached = take_cached_ripples(self._cache, self._stage)
        cmds = [drops_command(exe, mesh, os.path.join(self._stage, "drops.%04d.exr"), s, self._first,
                              self._last, s.size, map_size(ob, s), s.shelter),
                film_command(exe, mesh, os.path.join(self._stage, "film.%04d.exr"), s, self._first, self._last,
                             s.size, ob.active_material.soak.preset)]
        if not self._cached:
            cmds.append(ripples_command(exe, os.path.join(self._stage, "ripples.%04d.exr"), s, fps))
        self._repeat = map_size(ob, s) / RIPPLE_TILE
        self._mat, self._ob, self._scene_start = ob.active_material, ob, sc.frame_start
        self._uv = ob.data.uv_layers.active.name
        self._procs = []
        # all at once: each bake has stretches on one thread (start-up, mesh,
        # writing frames) that the others fill
        for cmd in cmds:
            if not self._launch(cmd):
                self._kill()
                shutil.rmtree(self._stage, ignore_errors=True)
                return False
        return True

    def _launch(self, cmd):
        """Starts one bake, its output in a log file (pipes could fill and
        stall a bake nobody reads); False (and reported) when it cannot."""
        what = " ".join(cmd[1:3])
        try:
            log = open(os.path.join(self._stage, f".{cmd[2]}.log"), "w+", encoding="utf-8")
        except OSError as e:
            self.report({"ERROR"}, f"cannot write the rain bake's log in {self._stage}: {e}")
            return False
        try:
            proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, text=True)
        except OSError as e:
            log.close()
            self.report({"ERROR"}, f"cannot run {cmd[0]}: {e}")
            return False
        self._procs.append((proc, what, log))
        return True

    def _kill(self):
        for proc, _what, log in self._procs:
            if proc.poll() is None:
                proc.terminate()
            proc.wait()
            log.close()

    def _failed(self):
        """None when every bake succeeded, else the report of the first that
        failed (the others are stopped)."""
        msg = None
        for proc, what, log in self._procs:
            proc.wait()
            if proc.returncode != 0 and msg is None:
                log.seek(0)
                lines = log.read().strip().splitlines()
                msg = f"soak {what} failed (exit {proc.returncode}): {lines[-1] if lines else 'no message'}"
        for _proc, _what, log in self._procs:
            log.close()
        return msg

    def _finish(self, context):
        try:
            return self._load(context)
        finally:
            shutil.rmtree(self._stage, ignore_errors=True)

    def _install(self):
        """Renames the staged frames to a folder of their own (the previous
        bake's frames stay until the new ones are wired)."""
        for name in os.listdir(self._stage):
            if name == "mesh.obj" or name.endswith(".log"):
                os.remove(os.path.join(self._stage, name))
        if not self._cached:
            keep_ripples(self._stage, self._cache)
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
        for proc, _what, _log in self._procs:
            proc.wait()
        return self._finish(context)

    def invoke(self, context, event):
        if not self._start(context):
            return {"CANCELLED"}
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.2, window=context.window)
        wm.progress_begin(0, 100)
        self._fraction = 0.0
        self._draw_status = self._status_bar()
        context.workspace.status_text_set(self._draw_status)
        wm.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def _progress(self):
        """(frames written, frames to write) over the bakes: the files in
        the staging folder (each frame is renamed into place when done)."""
        names = os.listdir(self._stage) if os.path.isdir(self._stage) else []
        done = sum(1 for n in names if n.endswith(".exr") and not n.startswith("."))
        return done, 2 * (self._last - self._first + 1) + 2 * RIPPLE_FRAMES    # drops, film; sharp and far ripples

    def _status_bar(self):
        """The status bar's draw function while baking: a progress bar (4.0+:
        UILayout.progress; 3.x: the share as text) and how to cancel. A plain
        function (Blender calls it as the status bar header's draw and
        refuses a bound method)."""
        op = self

        def draw(header, _context):
            layout = header.layout
            done = int(100 * op._fraction)
            text = f"Soak: Bake Rain {done} %"
            if hasattr(layout, "progress"):
                row = layout.row()
                row.ui_units_x = 12          # a header sizes a bar to almost nothing otherwise
                row.progress(factor=op._fraction, type="BAR", text=text)
            else:
                layout.label(text=text + "  " + "\u2588" * (done // 5) + "\u2591" * (20 - done // 5))
            layout.label(text="Esc cancels", icon="EVENT_ESC")
        return draw

    def _stop(self, context):
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        context.workspace.status_text_set(None)

    def modal(self, context, event):
        if event.type == "ESC":
            self._kill()
            shutil.rmtree(self._stage, ignore_errors=True)
            self._stop(context)
            self.report({"WARNING"}, "rain bake cancelled")
            return {"CANCELLED"}
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        done, total = self._progress()
        self._fraction = min(0.99, done / total)
        context.window_manager.progress_update(int(100 * self._fraction))
        context.workspace.status_text_set(self._draw_status)     # redraws the status bar
        running = [proc.poll() is None for proc, _what, _log in self._procs]
        failed = any(proc.returncode not in (None, 0) for proc, _what, _log in self._procs)
        if any(running) and not failed:
            return {"PASS_THROUGH"}
        if failed:                       # no use waiting for the others
            for proc, _what, _log in self._procs:
                if proc.poll() is None:
                    proc.terminate()
        self._stop(context)
        return self._finish(context)


classes = (SOAK_OT_bake_rain,)
