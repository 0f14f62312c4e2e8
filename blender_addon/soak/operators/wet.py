"""Make Wet, Make Dry, Key Drying. Each is all or nothing: on an error the
material is as before (insertion.make_wet/set_source/rebuild roll back) and the
message says why."""
import json

import bpy

from .. import compat, eevee_settings, insertion, material_tree, osl_nodes, removal, specialise
from ..data import SoakDataError
from ..predicates import key_icon, osl_available, poll_editable, poll_message, wet_poll


def _material(context):
    ob = context.object
    return ob.active_material if ob is not None else None


def internal_error(op, what, e):
    op.report({"ERROR"}, f"{what} failed, material unchanged: {type(e).__name__}: {e}")
    return {"CANCELLED"}


def _specialise(op, mat):
    """A keyed (or unkeyed) input: the group follows (specialise.specialise)."""
    try:
        specialise.specialise(mat)
        return True
    except (RuntimeError, SoakDataError) as e:
        op.report({"ERROR"}, str(e))
    except Exception as e:
        internal_error(op, "rebuilding the group", e)
    return False


class SOAK_OT_make_wet(bpy.types.Operator):
    """Insert a Soak Wet node group in front of the material's Principled BSDF (undoable; Make Dry takes it out)"""
    bl_idname = "soak.make_wet"
    bl_label = "Make Wet"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        mat = _material(context)
        if mat is not None and (mat.library is not None or getattr(mat, "override_library", None) is not None):
            return True     # an Asset Browser material: made local first (execute)
        if not poll_editable(cls, context):
            return False
        if material_tree.find_group_node(context.object.active_material.node_tree) is not None:
            return poll_message(cls, "The material is already wet (Make Dry first)")
        return True

    def _make_local(self, context, mat):
        """A linked (or overridden) material, as the Asset Browser's Link
        import gives, becomes this file's own (its edits would be lost on
        reload otherwise); the object's slot is pointed at the local copy."""
        where = mat.library.filepath if mat.library is not None else "a library override"
        local = mat.make_local()
        if local is None or local.library is not None:
            raise RuntimeError(f"material '{mat.name}' from {where} could not be made local")
        ob = context.object
        if ob.active_material != local:
            ob.active_material = local
        self.report({"INFO"}, f"{local.name}: made local (was linked from {where})")
        return local

    @staticmethod
    def _wet(context, mat, settings, opened):
        """Make Wet proper, exact lookups first in an EEVEE scene (put back
        when Make Wet fails: all or nothing)."""
        exact = settings.exact_lookups
        note = eevee_settings.ensure_exact_lookups(context.scene, settings)
        try:
            insertion.make_wet(mat, settings, opened)
        except BaseException:
            if settings.exact_lookups != exact:
                settings.exact_lookups = exact
            raise
        return note

    def execute(self, context):
        mat = _material(context)
        opened = []
        try:
            if mat.library is not None or getattr(mat, "override_library", None) is not None:
                mat = self._make_local(context, mat)
            if material_tree.find_group_node(mat.node_tree) is not None:
                raise RuntimeError(f"material '{mat.name}' is already wet (Make Dry first)")
            settings = mat.soak
            exact_note = self._wet(context, mat, settings, opened)
        except (RuntimeError, SoakDataError) as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        except Exception as e:  # a bug of ours: still nothing changed (make_wet rolled back)
            return internal_error(self, "Make Wet", e)
        if settings.use_osl:
            self._osl(context, mat, settings)
        if opened:
            self.report({"INFO"}, f"{mat.name}: node groups {', '.join(repr(n) for n in opened)} opened in this "
                                  "material to reach their Principled BSDF (the groups themselves are unchanged "
                                  "for their other users)")
        if exact_note:
            self.report({"INFO"}, exact_note)
        eevee_note = eevee_settings.ensure_reflections(context.scene)
        if eevee_note:
            self.report({"INFO"}, eevee_note)
        gns = material_tree.group_nodes(mat.node_tree)
        if len(gns) > 1:
            names = ", ".join(f"'{json.loads(g[material_tree.RESTORE_KEY])['bsdf']}'" for g in gns)
            self.report({"INFO"}, f"{mat.name}: wet ({settings.preset}, {settings.liquid}): {len(gns)} Principled "
                                  f"BSDFs ({names}), one set of controls")
        else:
            self.report({"INFO"}, f"{mat.name}: wet ({settings.preset}, {settings.liquid})")
        return {"FINISHED"}

    def _osl(self, context, mat, settings):
        if not osl_available(context):
            self.report({"WARNING"}, "OSL needs Cycles with Open Shading Language enabled; native nodes used")
            return
        if not osl_nodes.apply_osl_variant(mat, settings):
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
        if not any(n.get(material_tree.NODE_TAG) for n in tree.nodes):
            return poll_message(cls, "The material is not wet")
        return True

    def execute(self, context):
        mat = _material(context)
        try:
            problems = removal.make_dry(mat)
        except RuntimeError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        if problems:
            self.report({"WARNING"}, f"{mat.name}: dry; could not restore: " + "; ".join(problems))
        else:
            self.report({"INFO"}, f"{mat.name}: dry, restored")
        return {"FINISHED"}


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
        return wet_poll(cls, context)

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
        gn = material_tree.find_group_node(tree)
        start = gn.inputs["Start Time"].default_value
        fill = gn.inputs["Fill Time"].default_value
        if not fill > 0.0:
            self.report({"ERROR"}, f"Fill Time is {fill:g} s: set a positive drying time first")
            return {"CANCELLED"}
        for g in material_tree.group_nodes(tree):   # every wetted BSDF dries together
            self._key(context, tree, g, start, fill)
        if not _specialise(self, mat):
            return {"CANCELLED"}
        context.scene.frame_set(context.scene.frame_current)
        self.report({"INFO"}, f"{mat.name}: Time keyed {start:g} s (frame {self.frame_start}, wet) to "
                              f"{start + fill:g} s (frame {self.frame_end}, dry); Start Time and Fill Time kept")
        return {"FINISHED"}

    def _key(self, context, tree, gn, start, fill):
        gn.inputs["Start Time"].default_value = start
        gn.inputs["Fill Time"].default_value = fill
        index = list(gn.inputs).index(gn.inputs["Time"])
        path = f'nodes["{gn.name}"].inputs[{index}].default_value'
        # the Time curve is kept and only its keys replaced: removing it would
        # free every reference to it (the Graph Editor's, a script's: in 5.x
        # a freed channel-bag F-curve reads back garbage) and its modifiers
        old = compat.find_fcurve(tree, path)
        if old is not None:
            old.keyframe_points.clear()
        gn.inputs["Schedule"].default_value = 1.0
        gn.inputs["Drying"].default_value = 1.0
        t = gn.inputs["Time"]
        for frame, value in ((self.frame_start, start), (self.frame_end, start + fill)):
            t.default_value = value
            t.keyframe_insert("default_value", frame=frame)
        fc = compat.find_fcurve(tree, path)
        if fc is not None:
            for k in fc.keyframe_points:
                k.interpolation = "LINEAR"


class SOAK_OT_key_control(bpy.types.Operator):
    """Insert a keyframe on this Soak Wet input at the current frame (or delete the one there); the key lives on the group node's input socket"""
    bl_idname = "soak.key_control"
    bl_label = "Key Control"
    bl_options = {"REGISTER", "UNDO", "INTERNAL"}

    name: bpy.props.StringProperty(name="Input", description="Name of the Soak Wet group input to key")

    @classmethod
    def poll(cls, context):
        return wet_poll(cls, context)

    def execute(self, context):
        tree = _material(context).node_tree
        gn = material_tree.find_group_node(tree)
        if gn.inputs.get(self.name) is None:
            self.report({"ERROR"}, f"the Soak Wet group has no input '{self.name}'")
            return {"CANCELLED"}
        f = context.scene.frame_current
        delete = key_icon(context, tree, gn, self.name) == "DECORATE_KEYFRAME"
        for g in material_tree.group_nodes(tree):   # one set of controls for every wetted BSDF
            sock = g.inputs[self.name]
            if delete:
                try:
                    sock.keyframe_delete("default_value", frame=f)
                except RuntimeError:
                    pass
            else:
                sock.default_value = gn.inputs[self.name].default_value
                sock.keyframe_insert("default_value", frame=f)
        return {"FINISHED"} if _specialise(self, _material(context)) else {"CANCELLED"}


classes = (SOAK_OT_make_wet, SOAK_OT_make_dry, SOAK_OT_key_drying, SOAK_OT_key_control)
