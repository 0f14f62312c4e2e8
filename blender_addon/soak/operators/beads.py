"""Bake Beads: runs `soak bake beads` for the active material's preset (its
contact angle from materials.json, or the operator's Contact Angle), loads
the map and wires it into the wet material as a Bump (beads.wire): all or
nothing, undoable. The map goes next to the .blend (`//soak_beads/`; a
temporary folder while the file is unsaved), written by soak to a
temporary and renamed."""

import os
import subprocess
import tempfile

import bpy

from .. import beads
from ..predicates import poll_message
from ..preferences import find_soak


class SOAK_OT_bake_beads(bpy.types.Operator):
    """Bake rain standing as beads (the preset's contact angle) and bump the wet material with them"""
    bl_idname = "soak.bake_beads"
    bl_label = "Bake Beads"
    bl_options = {"REGISTER", "UNDO"}

    contact_angle: bpy.props.FloatProperty(
        name="Contact Angle", description="Water's contact angle in degrees; 0 takes the preset's "
        "(materials.json)", default=0.0, min=0.0, max=179.0)
    duration: bpy.props.FloatProperty(name="Rain Seconds", description="Seconds of rain", default=10.0,
                                      min=0.0, max=1e5)
    rate: bpy.props.FloatProperty(name="Rate", description="Rain rate, mm/h", default=10.0, min=0.01, max=500.0)
    map_size: bpy.props.FloatProperty(name="Map Size", description="Metres across the map (it tiles over the "
                                      "UV square Repeat times)", default=0.256, min=1e-3, max=100.0)
    repeat: bpy.props.FloatProperty(name="Repeat", description="Map tiles across the UV square", default=1.0,
                                    min=1e-3, max=1e4)
    resolution: bpy.props.IntProperty(name="Resolution", description="Texels across the map", default=512,
                                      min=8, max=8192)
    seed: bpy.props.IntProperty(name="Seed", description="Which random drops fall: another seed, another bead "
                                "pattern with the same statistics", default=0, min=0)

    @classmethod
    def poll(cls, context):
        ob = context.object
        if ob is None or ob.type != "MESH":
            return poll_message(cls, "Select a mesh object: the beads are mapped over its UVs")
        mat = ob.active_material
        if mat is None:
            return poll_message(cls, f"'{ob.name}' has no material: add one and Make Wet")
        if mat.library is not None:
            return poll_message(cls, "The material is linked from a library: make it local first")
        return True

    def _folder(self):
        if bpy.data.filepath:
            return bpy.path.abspath("//soak_beads")
        return os.path.join(tempfile.gettempdir(), "soak_beads")

    def execute(self, context):
        soak = find_soak(context)
        if soak is None:
            self.report({"ERROR"}, "soak not found: set its path in the add-on's preferences or put it on PATH")
            return {"CANCELLED"}
        ob = context.object
        mat = ob.active_material
        folder = self._folder()
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, f"{bpy.path.clean_name(ob.name)}_{bpy.path.clean_name(mat.name)}.exr")
        height_range = 0.006
        cmd = [soak, "bake", "beads", "--width", str(self.resolution), "--height", str(self.resolution),
               "--texel", repr(self.map_size / self.resolution), "--rate", repr(self.rate),
               "--duration", repr(self.duration), "--seed", str(self.seed),
               "--height-range", repr(height_range), "-o", path]
        cmd += (["--contact-angle", repr(self.contact_angle)] if self.contact_angle > 0
                else ["--preset", mat.soak.preset])
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            self.report({"ERROR"}, f"soak bake beads failed (exit {r.returncode}): {r.stderr.strip()[-300:]}")
            return {"CANCELLED"}
        image = bpy.data.images.load(path, check_existing=False)
        image.reload()
        # the Bump's Distance is in object units: the range over the map's metres per UV square
        scale = max(ob.dimensions.x, ob.dimensions.y, 1e-6) / (self.map_size * self.repeat)
        try:
            beads.wire(mat, image, repeat=self.repeat, distance=height_range * scale)
        except RuntimeError as e:
            bpy.data.images.remove(image)
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self.report({"INFO"}, r.stderr.strip().splitlines()[-1] if r.stderr.strip() else f"beads baked: {path}")
        return {"FINISHED"}


classes = (SOAK_OT_bake_beads,)
