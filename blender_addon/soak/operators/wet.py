"""Make Wet, Make Dry, Key Drying. Each is all or nothing: on an error the
material is as before (nodes.make_wet/set_source/rebuild roll back) and the
message says why."""
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


def poll_message(cls, text):
    """poll_message_set exists in Blender 3.0+; older ones just grey the button."""
    fn = getattr(cls, "poll_message_set", None)
    if fn is not None:
        fn(text)
    return False


def poll_editable(cls, context):
    """The reason an operator on the active material cannot run, or None."""
    ob = context.object
    if ob is None:
        return poll_message(cls, "No active object")
    mat = ob.active_material
    if mat is None:
        return poll_message(cls, f"'{ob.name}' has no material: add one in the Material tab")
    if mat.library is not None:
        return poll_message(cls, f"Material '{mat.name}' is linked from a library: make it local first "
                                 "(Object > Relations > Make Local)")
    if mat.node_tree is None or not mat.use_nodes:
        return poll_message(cls, f"Material '{mat.name}' does not use nodes: click Use Nodes first")
    return True


def internal_error(op, what, e):
    op.report({"ERROR"}, f"{what} failed, material unchanged: {type(e).__name__}: {e}")
    return {"CANCELLED"}


class SOAK_OT_make_wet(bpy.types.Operator):
    """Insert a Soak Wet node group in front of the material's Principled BSDF (undoable; Make Dry takes it out)"""
    bl_idname = "soak.make_wet"
    bl_label = "Make Wet"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        if not poll_editable(cls, context):
            return False
        if nodes.find_group_node(context.object.active_material.node_tree) is not None:
            return poll_message(cls, "The material is already wet (Make Dry first)")
        return True

    def execute(self, context):
        mat = _material(context)
        settings = mat.soak
        others = []
        try:
            bsdf, others = nodes.check_wettable(mat, settings)
            nodes.make_wet(mat, settings)
        except (RuntimeError, SoakDataError) as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        except Exception as e:  # a bug of ours: still nothing changed (make_wet rolled back)
            return internal_error(self, "Make Wet", e)
        if settings.use_osl:
            self._osl(context, mat, settings)
        if others:
            names = ", ".join(f"'{n.name}'" for n in others)
            self.report({"WARNING"}, f"{mat.name}: wetted '{bsdf.name}' only; {names} left dry (to wet another, "
                                     "Make Dry, make it the active node in the Shader Editor and Make Wet)")
        else:
            self.report({"INFO"}, f"{mat.name}: wet ({settings.preset}, {settings.liquid})")
        return {"FINISHED"}

    def _osl(self, context, mat, settings):
        if not osl_available(context):
            self.report({"WARNING"}, "OSL needs Cycles with Open Shading Language enabled; native nodes used")
            return
        try:
            osl = importlib.import_module(__package__.rsplit(".", 1)[0] + ".osl_nodes")
        except ImportError:
            self.report({"WARNING"}, "the OSL variant is not installed (osl_nodes missing); native nodes used")
            return
        if not osl.apply_osl_variant(mat, settings):
            self.report({"WARNING"}, "the OSL variant could not be applied; native nodes used")


class SOAK_OT_make_dry(bpy.types.Operator):
    """Remove the Soak Wet group and the nodes it added, and restore the Principled BSDF's links and values"""
    bl_idname = "soak.make_dry"
    bl_label = "Make Dry"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        if not poll_editable(cls, context):
            return False
        tree = context.object.active_material.node_tree
        if not any(n.get(nodes.NODE_TAG) for n in tree.nodes):
            return poll_message(cls, "The material is not wet")
        return True

    def execute(self, context):
        mat = _material(context)
        try:
            problems = nodes.make_dry(mat)
        except RuntimeError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        if problems:
            self.report({"WARNING"}, f"{mat.name}: dry; could not restore: " + "; ".join(problems))
        else:
            self.report({"INFO"}, f"{mat.name}: dry, restored")
        return {"FINISHED"}


def _wet_poll(cls, context):
    if not poll_editable(cls, context):
        return False
    if nodes.find_group_node(context.object.active_material.node_tree) is None:
        return poll_message(cls, "Make the material wet first")
    return True


class SOAK_OT_key_drying(bpy.types.Operator):
    """Keyframe a drying animation on the Soak Wet group: Time goes from Start Time (wet) to Start Time + Fill Time (dry) between two frames, linearly; Schedule and Drying are turned on; Start Time and Fill Time are kept; the group's earlier Time keys are replaced"""
    bl_idname = "soak.key_drying"
    bl_label = "Key Drying"
    bl_options = {"REGISTER", "UNDO"}

    frame_start: bpy.props.IntProperty(
        name="Wet at Frame", default=1,
        description="Frame where the surface is fully wet (Time = Start Time); default: the scene's start frame")
    frame_end: bpy.props.IntProperty(
        name="Dry at Frame", default=250,
        description="Frame where the surface is dry (Time = Start Time + Fill Time); default: the scene's end frame")

    @classmethod
    def poll(cls, context):
        return _wet_poll(cls, context)

    def invoke(self, context, event):
        self._scene_range(context)
        return self.execute(context)

    def _scene_range(self, context):
        sc = context.scene
        if not self.properties.is_property_set("frame_start"):
            self.frame_start = sc.frame_start
        if not self.properties.is_property_set("frame_end"):
            self.frame_end = sc.frame_end

    def execute(self, context):
        self._scene_range(context)
        if not self.frame_end > self.frame_start:
            self.report({"ERROR"}, f"the dry frame ({self.frame_end}) must come after the wet frame "
                                   f"({self.frame_start})")
            return {"CANCELLED"}
        mat = _material(context)
        tree = mat.node_tree
        gn = nodes.find_group_node(tree)
        start = gn.inputs["Start Time"].default_value
        fill = gn.inputs["Fill Time"].default_value
        if not fill > 0.0:
            self.report({"ERROR"}, f"Fill Time is {fill:g} s: set a positive drying time first")
            return {"CANCELLED"}
        index = list(gn.inputs).index(gn.inputs["Time"])
        path = f'nodes["{gn.name}"].inputs[{index}].default_value'
        ad = tree.animation_data
        if ad is not None and ad.action is not None:
            old = ad.action.fcurves.find(path)
            if old is not None:
                ad.action.fcurves.remove(old)
        gn.inputs["Schedule"].default_value = 1.0
        gn.inputs["Drying"].default_value = 1.0
        t = gn.inputs["Time"]
        for frame, value in ((self.frame_start, start), (self.frame_end, start + fill)):
            t.default_value = value
            t.keyframe_insert("default_value", frame=frame)
        fc = tree.animation_data.action.fcurves.find(path)
        if fc is not None:
            for k in fc.keyframe_points:
                k.interpolation = "LINEAR"
        context.scene.frame_set(context.scene.frame_current)
        self.report({"INFO"}, f"{mat.name}: Time keyed {start:g} s (frame {self.frame_start}, wet) to "
                              f"{start + fill:g} s (frame {self.frame_end}, dry); Start Time and Fill Time kept")
        return {"FINISHED"}


def control_fcurve(tree, gn, name):
    """The F-curve animating the group node's input `name`, or None."""
    sock = gn.inputs.get(name)
    ad = tree.animation_data
    if sock is None or ad is None or ad.action is None:
        return None
    index = list(gn.inputs).index(sock)
    return ad.action.fcurves.find(f'nodes["{gn.name}"].inputs[{index}].default_value')


def key_icon(context, tree, gn, name):
    """The decorator icon Blender draws for a keyable property: key on this
    frame, animated, or not animated."""
    fc = control_fcurve(tree, gn, name)
    if fc is None:
        return "DECORATE"
    f = context.scene.frame_current
    if any(abs(k.co[0] - f) < 0.5 for k in fc.keyframe_points):
        return "DECORATE_KEYFRAME"
    return "DECORATE_ANIMATE"


class SOAK_OT_key_control(bpy.types.Operator):
    """Insert a keyframe on this Soak Wet input at the current frame (or delete the one there); the key lives on the group node's input socket"""
    bl_idname = "soak.key_control"
    bl_label = "Key Control"
    bl_options = {"REGISTER", "UNDO", "INTERNAL"}

    name: bpy.props.StringProperty(name="Input", description="Name of the Soak Wet group input to key")

    @classmethod
    def poll(cls, context):
        return _wet_poll(cls, context)

    def execute(self, context):
        tree = _material(context).node_tree
        gn = nodes.find_group_node(tree)
        sock = gn.inputs.get(self.name)
        if sock is None:
            self.report({"ERROR"}, f"the Soak Wet group has no input '{self.name}'")
            return {"CANCELLED"}
        f = context.scene.frame_current
        if key_icon(context, tree, gn, self.name) == "DECORATE_KEYFRAME":
            sock.keyframe_delete("default_value", frame=f)
        else:
            sock.keyframe_insert("default_value", frame=f)
        return {"FINISHED"}


classes = (SOAK_OT_make_wet, SOAK_OT_make_dry, SOAK_OT_key_drying, SOAK_OT_key_control)
