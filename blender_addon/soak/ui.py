import bpy

from . import nodes
from .operators.wet import osl_available

GROUP_CONTROLS = ("Wetness", "Puddle Level", "Schedule", "Drying", "Time", "Start Time", "Fill Time", "Spill Edge")


class SOAK_PT_wetness(bpy.types.Panel):
    bl_label = "Wetness"
    bl_idname = "SOAK_PT_wetness"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "material"

    @classmethod
    def poll(cls, context):
        return context.object is not None and context.object.active_material is not None

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        mat = context.object.active_material
        s = mat.soak
        layout.prop(s, "preset")
        layout.prop(s, "liquid")
        layout.prop(s, "exact_lookups")
        gn = nodes.find_group_node(mat.node_tree) if mat.node_tree else None
        if gn is None:
            layout.prop(s, "colour_source")
            layout.prop(s, "wetness")
            layout.prop(s, "wetness_source")
            if s.wetness_source == "IMAGE":
                layout.template_ID(s, "wet_map", open="image.open")
            elif s.wetness_source == "ATTRIBUTE":
                layout.prop(s, "attribute_name")
            elif s.wetness_source == "NOISE":
                layout.prop(s, "noise_scale")
            if osl_available(context):
                layout.prop(s, "use_osl")
            layout.operator("soak.make_wet", icon="MOD_FLUIDSIM")
        else:
            for name in GROUP_CONTROLS:
                layout.prop(gn.inputs[name], "default_value", text=name)
            row = layout.row()
            row.operator("soak.key_drying", icon="KEY_HLT")
            row.operator("soak.make_dry", icon="CANCEL")
        row = layout.row()
        row.operator("soak.bake_wetmap", icon="RENDER_STILL")
        row.operator("soak.import_volume", icon="VOLUME_DATA")


classes = (SOAK_PT_wetness,)


def register():
    for c in classes:
        bpy.utils.register_class(c)


def unregister():
    for c in reversed(classes):
        bpy.utils.unregister_class(c)
