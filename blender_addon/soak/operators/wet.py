import importlib

import bpy

from .. import nodes
from ..data import SoakDataError


def _material(context):
    ob = context.object
    return ob.active_material if ob is not None else None


def osl_available(context):
    scene = context.scene
    return scene.render.engine == "CYCLES" and bool(getattr(scene.cycles, "shading_system", False))


class SOAK_OT_make_wet(bpy.types.Operator):
    """Insert a Soak Wet node group in front of the material's Principled BSDF"""
    bl_idname = "soak.make_wet"
    bl_label = "Make Wet"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        mat = _material(context)
        return mat is not None and mat.use_nodes

    def execute(self, context):
        mat = _material(context)
        settings = mat.soak
        try:
            nodes.make_wet(mat, settings)
        except (RuntimeError, SoakDataError) as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        if settings.use_osl:
            if not osl_available(context):
                self.report({"WARNING"}, "OSL needs Cycles with Open Shading Language enabled; native nodes used")
            else:
                try:
                    osl = importlib.import_module(__package__.rsplit(".", 1)[0] + ".osl_nodes")
                except ImportError:
                    self.report({"WARNING"}, "the OSL variant is not installed (osl_nodes missing); native nodes used")
                else:
                    if not osl.apply_osl_variant(mat, settings):
                        self.report({"WARNING"}, "the OSL variant could not be applied; native nodes used")
        self.report({"INFO"}, f"{mat.name}: wet ({settings.preset}, {settings.liquid})")
        return {"FINISHED"}


class SOAK_OT_make_dry(bpy.types.Operator):
    """Remove the Soak Wet group and restore the material exactly"""
    bl_idname = "soak.make_dry"
    bl_label = "Make Dry"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        mat = _material(context)
        return mat is not None and mat.node_tree is not None and nodes.find_group_node(mat.node_tree) is not None

    def execute(self, context):
        mat = _material(context)
        try:
            nodes.make_dry(mat)
        except (RuntimeError, KeyError, ValueError) as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        return {"FINISHED"}


class SOAK_OT_key_drying(bpy.types.Operator):
    """Keyframe a drying animation: wet at the start frame, dry at the end frame"""
    bl_idname = "soak.key_drying"
    bl_label = "Key Drying"
    bl_options = {"REGISTER", "UNDO"}

    frame_start: bpy.props.IntProperty(name="Start", default=1)
    frame_end: bpy.props.IntProperty(name="End", default=48)

    @classmethod
    def poll(cls, context):
        return SOAK_OT_make_dry.poll(context)

    def execute(self, context):
        gn = nodes.find_group_node(_material(context).node_tree)
        gn.inputs["Schedule"].default_value = 1.0
        gn.inputs["Drying"].default_value = 1.0
        gn.inputs["Start Time"].default_value = 0.0
        gn.inputs["Fill Time"].default_value = 1.0
        t = gn.inputs["Time"]
        for frame, value in ((self.frame_start, 0.0), (self.frame_end, 1.0)):
            t.default_value = value
            t.keyframe_insert("default_value", frame=frame)
        return {"FINISHED"}


classes = (SOAK_OT_make_wet, SOAK_OT_make_dry, SOAK_OT_key_drying)
