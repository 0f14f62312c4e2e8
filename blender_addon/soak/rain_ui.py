"""The Rain sub-panel of the Wetness panel and its settings (Scene.soak_rain):
the rain of the scene (rate, when it falls), the drops map of the selected
object (scale, size, seed) and the Bake Rain operator."""
import bpy
from bpy.props import BoolProperty, FloatProperty, IntProperty, PointerProperty

from . import nodes


class SoakRainSettings(bpy.types.PropertyGroup):
    rate: FloatProperty(name="Rate (mm/h)", default=10.0, min=0.01, max=500.0, soft_max=100.0,
                        description="How hard it rains, millimetres of water per hour (drizzle 1, moderate 5, "
                                    "heavy 10-50). Drop sizes after Marshall & Palmer (1948), fall speeds after "
                                    "Atlas et al. (1973)")
    start_frame: IntProperty(name="Start Frame", default=1, min=0,
                             description="Scene frame where the rain starts (the surface is dry before it)")
    end_frame: IntProperty(name="End Frame", default=200, min=1,
                           description="Scene frame where the rain stops; after it the surface dries over "
                                       "Drying Time")
    seconds_per_frame: FloatProperty(
        name="Time Scale (s/frame)", default=0.5, min=1e-3, max=3600.0, soft_max=10.0,
        description="Simulated seconds of rain per scene frame (a time-lapse). Rain takes minutes to wet a "
                    "surface: 10 mm/h fills the 0.2 mm a flat surface holds in about 76 s. The default, 0.5 s "
                    "a frame, shows 100 s of rain over frames 1-200, enough to wet open ground; 1 / frame rate "
                    "(0.042 at 24 fps) is real time")
    dry_time: FloatProperty(name="Drying Time (s)", default=60.0, min=1e-3, soft_max=3600.0,
                            description="Simulated seconds the surface takes to dry after the rain stops (at the "
                                        "Time Scale: 60 s are 120 frames at 0.5 s a frame)")
    map_size: FloatProperty(name="Scale (m)", default=0.0, min=0.0, soft_max=100.0, subtype="DISTANCE",
                            description="Metres across the UV square, for the drops' physical size (0: the "
                                        "object's largest horizontal dimension, right for a plane)")
    size: IntProperty(name="Map Size", default=256, min=8, max=4096,
                      description="Width and height of the drops maps, pixels (a texel should be about 1-4 mm "
                                  "for single drops to show)")
    seed: IntProperty(name="Seed", default=0, min=0,
                      description="Random seed of the impacts: same seed, same frames")
    shelter: BoolProperty(name="Shelter by Scene", default=True,
                          description="The visible scene blocks the rain (the drops fall only where the sky "
                                      "reaches, as Bake Wet Map computes it); off: the object is open to the sky")
    rays: IntProperty(name="Rays", default=32, min=1, max=4096,
                      description="Rays per texel for the sky exposure (Shelter by Scene)")


class SOAK_PT_wetness_rain(bpy.types.Panel):
    bl_label = "Rain"
    bl_idname = "SOAK_PT_wetness_rain"
    bl_parent_id = "SOAK_PT_wetness"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "material"

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
        mat = ob.active_material if ob is not None else None
        if mat is not None and mat.node_tree is not None and any(
                n.get(nodes.ROLE_KEY) == "rain" for n in mat.node_tree.nodes):
            col.label(text="Ripples show where the drops reach Puddle Level", icon="INFO")
        layout.operator("soak.bake_rain", icon="OUTLINER_OB_FORCE_FIELD")


classes = (SoakRainSettings, SOAK_PT_wetness_rain)
_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()
    bpy.types.Scene.soak_rain = PointerProperty(type=SoakRainSettings)


def unregister():
    del bpy.types.Scene.soak_rain
    _unregister_classes()
