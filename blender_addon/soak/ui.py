"""The Soak panel, laid out like Blender's own: property split, sub-panels,
greyed buttons with their reason (poll messages), and the render settings
the wet look needs.

Where an artist finds it (issue 46): a Soak row under the material slots
at the top of Properties > Material (the Surface panel is taller than a
default window and pushes an add-on panel off-screen, and a panel's
bl_order does not move it above panels the startup file already placed),
the Soak panel itself (bl_order -1), a Soak tab in the Shader Editor's
sidebar (N), and Add > Soak > Make Wet in the Shader Editor. The same panel classes are made for both editors
(both_editors)."""
import bpy

from . import compat, data, material_tree, price, specialise
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


def _price(layout, mat):
    """Beside Quality: what it costs for this material as wired (price.py)."""
    try:
        text = price.lines(mat)
    except (data.SoakDataError, KeyError) as e:
        layout.label(text=f"No price: {e}", icon="ERROR")
        return
    box = layout.box().column(align=True)
    box.scale_y = 0.8
    box.label(text=text[0], icon="TIME")
    box.label(text=text[1], icon="BLANK1")


class _MaterialPanel:
    """Where the Soak panels live: Properties editor, Material tab, first."""
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "material"


class _ShaderSidebar:
    """The same panels in the Shader Editor's sidebar, tab Soak."""
    bl_space_type = "NODE_EDITOR"
    bl_region_type = "UI"
    bl_category = "Soak"

    @classmethod
    def poll(cls, context):
        space = context.space_data
        if not (getattr(space, "tree_type", "") == "ShaderNodeTree" and getattr(space, "shader_type", "") == "OBJECT"
                and _material(context) is not None):
            return False
        base_poll = getattr(cls._base, "poll", None)      # the body's own (a classmethod of the body)
        return base_poll is None or base_poll(context)


class _Main:
    bl_label = "Soak"
    bl_order = -1

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
        _price(col, mat)
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
            _switch_note(layout, context)
        else:
            row = layout.row(align=True)
            row.operator("soak.key_drying", icon="KEY_HLT")
            row.operator("soak.make_dry", icon="CANCEL")
        row = layout.row(align=True)
        row.operator("soak.bake_wetmap", icon="RENDER_STILL")
        row.operator("soak.import_volume", icon="VOLUME_DATA")


class _Source:
    bl_label = "Source"

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


class _Controls:
    bl_label = "Controls"

    @classmethod
    def poll(cls, context):
        mat = _material(context)
        if mat is None or mat.node_tree is None:
            return False
        return material_tree.find_group_node(mat.node_tree) is not None

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
            col.label(text="Pores fill (Drying: empty) from Liquid Arrives At over Pores Fill In", icon="TIME")
        if specialise.is_specialised(gn):
            col.label(text="Constant wetness: the group is built for it (faster)", icon="INFO")
        elif specialise.is_film_free(gn):
            col.label(text="Wetness stays below the film: the group leaves it out", icon="INFO")


def panel(where, body, idname, parent=""):
    """A panel class: the body (label, poll, draw) in one editor (where:
    _MaterialPanel or _ShaderSidebar). The sidebar's poll asks the body's."""
    attrs = {"bl_idname": idname, "_base": body}
    if parent:
        attrs["bl_parent_id"] = parent
    return type(idname, (where, body, bpy.types.Panel), attrs)


def both_editors(body, name, parent=""):
    """(Properties > Material panel, Shader Editor sidebar panel) of a body:
    SOAK_PT_<name> and SOAK_PT_node_<name>."""
    return (panel(_MaterialPanel, body, "SOAK_PT_" + name, parent and "SOAK_PT_" + parent),
            panel(_ShaderSidebar, body, "SOAK_PT_node_" + name, parent and "SOAK_PT_node_" + parent))


class NODE_MT_soak_add(bpy.types.Menu):
    """Add > Soak in the Shader Editor"""
    bl_idname = "NODE_MT_soak_add"
    bl_label = "Soak"

    def draw(self, context):
        layout = self.layout
        layout.operator("soak.make_wet", text="Make Wet (Soak Wet group)", icon="MOD_FLUIDSIM")
        layout.operator("soak.make_dry", text="Make Dry", icon="CANCEL")


def _switch_note(layout, context):
    """Under Make Wet: the EEVEE settings it will turn on (eevee_settings)."""
    names = []
    switch = compat.eevee_reflection_switch(context.scene)
    if switch is not None and not getattr(switch[0], switch[1]):
        names.append("EEVEE's " + switch[0].bl_rna.properties[switch[1]].name)
    mat = _material(context)
    if (mat is not None and compat.is_eevee(context.scene.render.engine) and not mat.soak.exact_lookups
            and not compat.exact_lookups_required()):
        names.append("Exact lookups")
    if names:
        layout.label(text=f"Make Wet also turns on {' and '.join(names)} (Ctrl-Z undoes)", icon="INFO")


def _slot_header(self, context):
    """A Soak row under the material slots (the top of the Material tab,
    on screen whatever the Surface panel's height): the preset and Make
    Wet, or the wet material's preset and Make Dry; its settings are in
    the Soak panel."""
    mat = _material(context)
    if mat is None:
        return
    gn = material_tree.find_group_node(mat.node_tree) if mat.node_tree is not None else None
    row = self.layout.row(align=True)
    if mat.library is not None and gn is None:     # an Asset Browser material, linked
        row.label(text="Soak", icon="MOD_FLUIDSIM")
        row.operator("soak.make_wet", text="Make Local and Wet")
    elif gn is None:
        row.prop(mat.soak, "preset", text="Soak", icon="MOD_FLUIDSIM")
        row.operator("soak.make_wet", text="Make Wet")
        if compat.is_eevee(context.scene.render.engine):
            _switch_note(self.layout, context)
    else:
        row.label(text=f"Soak: wet ({mat.soak.preset}), settings in the Soak panel", icon="MOD_FLUIDSIM")
        row.operator("soak.make_dry", text="", icon="CANCEL")


def _slot_panels():
    """The engines' material-slot panels (EEVEE_MATERIAL_PT_context_material,
    CYCLES_PT_context_material, ...: the names differ between versions)."""
    return [getattr(bpy.types, n) for n in dir(bpy.types) if n.endswith("_PT_context_material")]


def _add_menu(self, context):
    if getattr(context.space_data, "tree_type", "") == "ShaderNodeTree":
        self.layout.separator()
        self.layout.menu(NODE_MT_soak_add.bl_idname, icon="MOD_FLUIDSIM")


classes = (both_editors(_Main, "wetness") + both_editors(_Source, "wetness_source", "wetness")
           + both_editors(_Controls, "wetness_controls", "wetness") + (NODE_MT_soak_add,))


_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()
    bpy.types.NODE_MT_add.append(_add_menu)
    for pt in _slot_panels():
        pt.append(_slot_header)


def unregister():
    for pt in _slot_panels():
        pt.remove(_slot_header)
    bpy.types.NODE_MT_add.remove(_add_menu)
    _unregister_classes()
