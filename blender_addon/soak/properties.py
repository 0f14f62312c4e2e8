"""Per-material settings (Material.soak). The wetness, time and spill values
live on the group node's inputs, so they are keyframable like any socket."""

import bpy
from bpy.props import EnumProperty, FloatProperty, PointerProperty, StringProperty

from . import data, nodes


def _rebuild(self, context):
    mat = self.id_data
    if mat is not None and mat.node_tree is not None and nodes.find_group_node(mat.node_tree) is not None:
        nodes.rebuild(mat, self)


class SoakMaterialSettings(bpy.types.PropertyGroup):
    preset: EnumProperty(name="Preset", description="Material class from the Soak core (porosity, phase "
                         "change, film)", items=data.preset_items, update=_rebuild)
    liquid: EnumProperty(name="Liquid", items=data.liquid_items, update=_rebuild)
    colour_source: EnumProperty(
        name="Colours",
        items=(("MATERIAL", "Material's own", "Darken the material's own base colour and roughness "
                "(textures included) through the preset's wetness function"),
               ("PRESET", "Preset", "Use the preset's dry colour and roughness")),
        default="MATERIAL")
    wetness: FloatProperty(name="Wetness", min=0.0, max=1.0, default=1.0, subtype="FACTOR",
                           description="Initial wetness (then edit it on the group's input)")
    wetness_source: EnumProperty(
        name="Wetness Source",
        items=(("CONSTANT", "Constant", "The same wetness everywhere"),
               ("IMAGE", "Image", "A wet map image over the UVs (e.g. from soak bake)"),
               ("ATTRIBUTE", "Attribute", "A mesh attribute, e.g. Dynamic Paint's dp_wetmap"),
               ("NOISE", "Noise", "Procedural patches")),
        default="CONSTANT")
    wet_map: PointerProperty(name="Wet Map", type=bpy.types.Image)
    attribute_name: StringProperty(name="Attribute", default="dp_wetmap")
    noise_scale: FloatProperty(name="Noise Scale", default=5.0, min=0.0)
    exact_lookups: bpy.props.BoolProperty(
        name="Exact lookups (EEVEE)", default=False, update=_rebuild,
        description="Interpolate the core's tables with four exact texel reads each (EEVEE's image filter "
                    "is not plain bilinear); slower, same result in Cycles")
    use_osl: bpy.props.BoolProperty(name="Use OSL shader", default=False,
                                    description="Cycles with Open Shading Language only")


classes = (SoakMaterialSettings,)


def register():
    for c in classes:
        bpy.utils.register_class(c)
    bpy.types.Material.soak = PointerProperty(type=SoakMaterialSettings)


def unregister():
    del bpy.types.Material.soak
    for c in reversed(classes):
        bpy.utils.unregister_class(c)
