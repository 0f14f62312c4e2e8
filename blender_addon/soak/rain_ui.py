"""The Rain sub-panel of the Soak panel: the scene's rain settings
(Scene.soak_rain, properties.SoakRainSettings: rate, when it falls), the
drops map of the selected object (scale, size, seed) and the Bake Rain
operator."""
import bpy

from . import material_tree, ui


class _Rain:
    bl_label = "Rain"

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        s = context.scene.soak_rain
        col = layout.column()
        col.prop(s, "rate")
        sub = col.column(align=True)
        sub.prop(s, "start_frame", text="Frame Start")
        sub.prop(s, "end_frame", text="End")
        col.prop(s, "seconds_per_frame")
        rain_s = (s.end_frame - s.start_frame) * s.seconds_per_frame
        col.label(text=f"{rain_s:.4g} s of rain (simulated) over {max(0, s.end_frame - s.start_frame)} frames",
                  icon="TIME")
        col.prop(s, "dry_time")
        col.separator()
        col.prop(s, "map_size")
        ob = context.object
        if s.map_size == 0.0 and ob is not None and ob.type == "MESH":
            size = max(ob.dimensions.x, ob.dimensions.y, 1e-3)
            col.label(text=f"Scale 0: the object's size, {size:.3g} m", icon="INFO")
        col.prop(s, "size")
        col.prop(s, "seed")
        col.prop(s, "shelter")
        if s.shelter:
            col.prop(s, "rays")
        col.separator()
        col.prop(s, "runnels")
        if s.runnels == "CUSTOM":
            col.prop(s, "contact_angle")
        col.prop(s, "splashes")
        mat = ob.active_material if ob is not None else None
        if mat is not None and mat.node_tree is not None and any(
                n.get(material_tree.ROLE_KEY) == "rain" for n in mat.node_tree.nodes):
            col.label(text="Ripples show where the drops reach Puddle Level", icon="INFO")
        layout.operator("soak.bake_rain", icon="OUTLINER_OB_FORCE_FIELD")
        layout.operator("soak.bake_beads")


# SOAK_PT_wetness_rain under the Soak panel, SOAK_PT_node_wetness_rain in the Shader Editor's sidebar
classes = ui.both_editors(_Rain, "wetness_rain", "wetness")
_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()


def unregister():
    _unregister_classes()
