"""The Wetness panel (Properties > Material), laid out like Blender's own:
property split, sub-panels, greyed buttons with their reason (poll
messages), and the render settings the wet look needs."""
import bpy

from . import compat, material_tree, specialise
from .predicates import key_icon, osl_available
from .properties import CONTROLS


def _material(context):
    ob = context.object
    return ob.active_material if ob is not None else None


def _engine_hints(layout, context, s):
    """The render settings wet reflections need, with the switch at hand."""
    scene = context.scene
    engine = scene.render.engine
    switch = compat.eevee_reflection_switch(scene) if compat.is_eevee(engine) else None
    if switch is not None and not getattr(switch[0], switch[1]):
        box = layout.box()
        box.label(text=switch[2][0], icon="INFO")
        box.label(text=switch[2][1])
        box.prop(switch[0], switch[1])
    if compat.is_eevee(engine) and not s.exact_lookups and not compat.exact_lookups_required():
        layout.label(text="EEVEE: turn on Exact lookups for the core's values", icon="INFO")


class _MaterialPanel:
    """Where the Wetness panels live: Properties editor, Material tab."""
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "material"


class SOAK_PT_wetness(_MaterialPanel, bpy.types.Panel):
    bl_label = "Wetness"
    bl_idname = "SOAK_PT_wetness"

    @classmethod
    def poll(cls, context):
        return _material(context) is not None

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        mat = _material(context)
        s = mat.soak
        gn = material_tree.find_group_node(mat.node_tree) if mat.node_tree else None
        if mat.library is not None:
            layout.label(text="Linked from a library: make it local to wet it", icon="LIBRARY_DATA_DIRECT")
        col = layout.column()
        col.prop(s, "preset")
        col.prop(s, "liquid")
        col.prop(s, "quality")
        if compat.exact_lookups_required():
            # 4.2-4.x always build the exact path (compat.exact_lookups_required):
            # the setting cannot change anything there, so say so.
            col.label(text="Exact lookups: always on in this Blender (EEVEE needs them)", icon="CHECKBOX_HLT")
        else:
            col.prop(s, "exact_lookups")
        if gn is None:
            col.prop(s, "colour_source")
            col.prop(s, "wetness")
        if s.status:
            box = layout.box()
            box.alert = True
            box.label(text=s.status, icon="ERROR")
        _engine_hints(layout, context, s)
        if gn is None:
            if osl_available(context):
                layout.prop(s, "use_osl")
            layout.operator("soak.make_wet", icon="MOD_FLUIDSIM")
        else:
            row = layout.row(align=True)
            row.operator("soak.key_drying", icon="KEY_HLT")
            row.operator("soak.make_dry", icon="CANCEL")
        row = layout.row(align=True)
        row.operator("soak.bake_wetmap", icon="RENDER_STILL")
        row.operator("soak.import_volume", icon="VOLUME_DATA")


class SOAK_PT_wetness_source(_MaterialPanel, bpy.types.Panel):
    bl_label = "Source"
    bl_idname = "SOAK_PT_wetness_source"
    bl_parent_id = "SOAK_PT_wetness"

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        s = _material(context).soak
        layout.prop(s, "wetness_source", text="Wetness Source")
        if s.wetness_source == "IMAGE":
            layout.template_ID(s, "wet_map", open="image.open")
            if s.wet_map is None:
                layout.label(text="Choose or bake a wet map", icon="ERROR")
        elif s.wetness_source == "ATTRIBUTE":
            layout.prop(s, "attribute_name")
        elif s.wetness_source == "NOISE":
            layout.prop(s, "noise_scale")


class SOAK_PT_wetness_controls(_MaterialPanel, bpy.types.Panel):
    bl_label = "Controls"
    bl_idname = "SOAK_PT_wetness_controls"
    bl_parent_id = "SOAK_PT_wetness"

    @classmethod
    def poll(cls, context):
        mat = _material(context)
        return mat is not None and mat.node_tree is not None and material_tree.find_group_node(mat.node_tree) is not None

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        mat = _material(context)
        s = mat.soak
        gn = material_tree.find_group_node(mat.node_tree)
        col = layout.column()
        for name, prop in CONTROLS:
            sock = gn.inputs.get(name)
            if sock is None:
                continue
            row = col.row(align=True)
            sub = row.row(align=True)
            sub.active = not sock.is_linked
            sub.prop(s, prop)
            # the keyframe button of the node's input (the proxy above is not animatable)
            op = row.operator("soak.key_control", text="", icon=key_icon(context, mat.node_tree, gn, name),
                              emboss=False)
            op.name = name
            if name == "Drying":
                col.separator()
        if s.schedule:
            col.label(text="Time runs from Start Time to Start + Fill Time", icon="TIME")
        if specialise.is_specialised(gn):
            col.label(text="Constant wetness: the group is built for it (faster)", icon="INFO")
        elif specialise.is_film_free(gn):
            col.label(text="Wetness stays below the film: the group leaves it out", icon="INFO")


classes = (SOAK_PT_wetness, SOAK_PT_wetness_source, SOAK_PT_wetness_controls)


register, unregister = bpy.utils.register_classes_factory(classes)
