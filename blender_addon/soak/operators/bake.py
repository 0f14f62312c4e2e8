"""Bake Wet Map: runs `soak bake rain` on the active mesh in a subprocess
(modal, cancellable with Esc), then loads the map and selects it as the
material's wetness source."""

import os
import shutil
import subprocess
import tempfile

import bpy

from ..preferences import find_soak


def _export_obj(context, ob, path):
    kw = dict(filepath=path, export_selected_objects=True, export_uv=True, export_materials=False,
              forward_axis="NEGATIVE_Z", up_axis="Y")
    sel = [o for o in context.view_layer.objects if o.select_get()]
    for o in sel:
        o.select_set(False)
    ob.select_set(True)
    try:
        bpy.ops.wm.obj_export(**kw)
    finally:
        ob.select_set(False)
        for o in sel:
            o.select_set(True)


def bake_command(exe, mesh_path, out_path, size, rays, duration):
    return [exe, "bake", "rain", mesh_path, "-o", out_path, "--width", str(size), "--height", str(size),
            "--rays", str(rays), "--duration", str(duration), "--up", "y"]


class SOAK_OT_bake_wetmap(bpy.types.Operator):
    """Bake a rain wet map for the active mesh with the soak tool"""
    bl_idname = "soak.bake_wetmap"
    bl_label = "Bake Wet Map"
    bl_options = {"REGISTER"}

    size: bpy.props.IntProperty(name="Size", default=256, min=8, max=8192)
    rays: bpy.props.IntProperty(name="Rays", default=32, min=1, max=4096)
    duration: bpy.props.FloatProperty(name="Rain (s)", default=600.0, min=0.0)

    @classmethod
    def poll(cls, context):
        ob = context.object
        return ob is not None and ob.type == "MESH" and ob.active_material is not None

    def _start(self, context):
        exe = find_soak(context)
        if exe is None:
            self.report({"ERROR"}, "soak executable not found: set its path in the add-on preferences or put it on PATH")
            return False
        ob = context.object
        if not ob.data.uv_layers:
            self.report({"ERROR"}, f"mesh '{ob.name}' has no UV map: the wet map is baked over the UVs")
            return False
        self._dir = tempfile.mkdtemp(prefix="soak_bake_")
        mesh = os.path.join(self._dir, "mesh.obj")
        self._out = os.path.join(self._dir, f"{bpy.path.clean_name(ob.name)}_wet.exr")
        _export_obj(context, ob, mesh)
        cmd = bake_command(exe, mesh, self._out, self.size, self.rays, self.duration)
        try:
            self._proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        except OSError as e:
            self.report({"ERROR"}, f"cannot run {exe}: {e}")
            return False
        self._mat = ob.active_material
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
        s.wet_map = img
        s.wetness_source = "IMAGE"
        self.report({"INFO"}, f"wet map baked: {img.name}")
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
            self.report({"WARNING"}, "wet-map bake cancelled")
            return {"CANCELLED"}
        if event.type == "TIMER":
            self._ticks += 1
            context.window_manager.progress_update(min(99, self._ticks))
            context.workspace.status_text_set(f"Soak: baking wet map... (Esc cancels)")
            if self._proc.poll() is not None:
                self._stop(context)
                context.workspace.status_text_set(None)
                return self._finish(context)
        return {"PASS_THROUGH"}


classes = (SOAK_OT_bake_wetmap,)
