import os
import shutil

import bpy
from bpy.props import StringProperty


class SoakPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    soak_path: StringProperty(name="soak executable", subtype="FILE_PATH", default="",
                              description="Path of the soak tool (empty: search PATH)")

    def draw(self, context):
        self.layout.prop(self, "soak_path")
        exe = find_soak(context)
        self.layout.label(text=f"Using: {exe}" if exe else "soak not found (needed for baking only)")


def find_soak(context=None):
    """The soak executable: the preference, then PATH; None if missing."""
    ctx = context or bpy.context
    addon = ctx.preferences.addons.get(__package__)
    path = addon.preferences.soak_path if addon else ""
    if path:
        path = bpy.path.abspath(path)
        return path if os.path.isfile(path) and os.access(path, os.X_OK) else None
    return shutil.which("soak")


classes = (SoakPreferences,)


register, unregister = bpy.utils.register_classes_factory(classes)
