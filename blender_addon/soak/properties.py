"""The add-on's settings: per material (Material.soak) and the scene's rain
(Scene.soak_rain).

Two kinds of property:
- settings stored on the material (preset, liquid, wetness source, ...);
  after Make Wet, changing one rebuilds the group or re-wires the source in
  place (all or nothing: a failure leaves the material as it was and shows
  the reason in the panel through `status`);
- the group's controls (Wetness ... Spill Edge), which live on the Soak Wet
  node's inputs so that they can be keyframed like any socket. The panel
  draws them through the proxies below (get/set on the node's input) for a
  tooltip, a unit and checkboxes for Schedule and Drying, whose group inputs
  are floats (the schedule blends with them); the keyframe button beside each
  keys the node's input itself."""

import json
import math

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, PointerProperty, StringProperty

from . import data, insertion, material_tree, rain, rebuild, sources, specialise, wet_group


_reverting = set()     # settings being put back after a refused change (no update then)


def _apply(self, fn):
    """Runs a rebuild/re-wire for a changed setting; True when done or not
    needed. On failure the material is unchanged and the reason is shown."""
    mat = self.id_data
    if mat is None or mat.node_tree is None or material_tree.find_group_node(mat.node_tree) is None:
        return True
    if self.as_pointer() in _reverting:
        return True
    try:
        fn(mat, self)
        self.status = ""
        return True
    except (RuntimeError, data.SoakDataError) as e:
        self.status = str(e)          # shown in the panel; the material is unchanged
    except Exception as e:            # a bug of ours: the material was rolled back too
        self.status = f"{type(e).__name__}: {e}"
        print("soak:", self.status)
    return False


def _revert(self, values):
    """Puts the settings back to what the material still has."""
    _reverting.add(self.as_pointer())
    try:
        for k, v in values.items():
            if v is not None and getattr(self, k) != v:
                setattr(self, k, v)
    finally:
        _reverting.discard(self.as_pointer())


def _rebuild(self, context):
    if not _apply(self, rebuild.rebuild):
        gn = material_tree.find_group_node(self.id_data.node_tree)
        info = json.loads(gn.node_tree.get(wet_group.GROUP_TAG, "{}")) if gn.node_tree is not None else {}
        _revert(self, {"preset": info.get("preset"), "liquid": info.get("liquid"),
                       "exact_lookups": info.get("exact"), "quality": info.get("quality", "BALANCED")})


def _source(self, context):
    if not _apply(self, sources.set_source):
        _revert(self, sources.current_source(self.id_data.node_tree))


def _group_inputs(self, name):
    mat = self.id_data
    if mat is None or mat.node_tree is None:
        return []
    return [g.inputs[name] for g in material_tree.group_nodes(mat.node_tree) if name in g.inputs]


def _group_input(self, name):
    mat = self.id_data
    gn = material_tree.find_group_node(mat.node_tree) if mat is not None and mat.node_tree is not None else None
    return gn.inputs.get(name) if gn is not None else None


PENDING = insertion.PENDING


def _set_inputs(self, socks, value):
    """Sets the group nodes' input and rebuilds a group specialised to the
    old value (specialise.specialise); on failure the old values come back."""
    old = [s.default_value for s in socks]
    for s in socks:                 # every wetted BSDF's group node
        s.default_value = value
    if socks and not _apply(self, lambda mat, _s: specialise.specialise(mat)):
        for s, v in zip(socks, old):
            s.default_value = v


def _float_proxy(name, label, description, default, lo, hi, subtype="NONE", soft_max=None):
    def get(self):
        s = _group_input(self, name)
        if s is None:
            return float(self.get(PENDING + name, default))
        return float(s.default_value)

    def put(self, value):
        socks = _group_inputs(self, name)
        _set_inputs(self, socks, value)
        if not socks:
            self[PENDING + name] = float(value)
        if name == "Puddle Level":      # the rain's ripples flood at the same level
            rain.sync_level(self.id_data)

    kw = {"soft_max": soft_max} if soft_max is not None else {}
    return FloatProperty(name=label, description=description, get=get, set=put, min=lo, max=hi,
                         subtype=subtype, options=set(), **kw)


def _bool_proxy(name, label, description):
    def get(self):
        s = _group_input(self, name)
        if s is None:
            return self.get(PENDING + name, 0.0) >= 0.5
        return s.default_value >= 0.5

    def put(self, value):
        socks = _group_inputs(self, name)
        _set_inputs(self, socks, 1.0 if value else 0.0)
        if not socks:
            self[PENDING + name] = 1.0 if value else 0.0

    return BoolProperty(name=label, description=description, get=get, set=put, options=set())


# group input -> panel property (the panel's order)
CONTROLS = (
    ("Wetness", "group_wetness"),
    ("Puddle Level", "puddle_level"),
    ("Schedule", "schedule"),
    ("Drying", "drying"),
    ("Time", "time"),
    ("Start Time", "start_time"),
    ("Fill Time", "fill_time"),
    ("Spill Edge", "spill_edge"),
)


class SoakMaterialSettings(bpy.types.PropertyGroup):
    preset: EnumProperty(
        name="Preset", items=data.preset_items, update=_rebuild,
        description="Material class from the Soak core (porosity, phase change, extinction, film); "
                    "after Make Wet the group is rebuilt in place, keeping its values, links and keys")
    liquid: EnumProperty(
        name="Liquid", items=data.liquid_items, update=_rebuild,
        description="The liquid (refractive index and absorption from the core); after Make Wet the group is "
                    "rebuilt in place")
    colour_source: EnumProperty(
        name="Colours",
        description="Which dry colour, roughness and specular the group wets",
        items=(("MATERIAL", "Material's own", "Darken the material's own base colour and roughness "
                "(textures included) through the preset's wetness function"),
               ("PRESET", "Preset", "Use the preset's dry colour, roughness and specular")),
        default="MATERIAL")
    wetness: FloatProperty(
        name="Wetness", min=0.0, max=1.0, default=1.0, subtype="FACTOR",
        description="Amount of liquid Make Wet starts with, 0 (dry) to 1 (saturated, with a film); "
                    "afterwards it is the group's Wetness input")
    wetness_source: EnumProperty(
        name="Wetness Source", update=_source,
        description="Where the wetness varies over the surface (multiplies Wetness); "
                    "can be changed after Make Wet",
        items=(("CONSTANT", "Constant", "The same wetness everywhere"),
               ("IMAGE", "Image", "A wet map image over the UVs (e.g. from Bake Wet Map)"),
               ("ATTRIBUTE", "Attribute", "A mesh attribute, e.g. Dynamic Paint's dp_wetmap"),
               ("NOISE", "Noise", "Procedural patches")),
        default="CONSTANT")
    wet_map: PointerProperty(
        name="Wet Map", type=bpy.types.Image, update=_source,
        description="Wet map over the mesh's UVs, 0 dry to 1 wet, read as non-colour data "
                    "(Bake Wet Map makes one)")
    attribute_name: StringProperty(
        name="Attribute", default="dp_wetmap", update=_source,
        description="Mesh attribute holding the wetness 0-1 (Dynamic Paint's wet map is dp_wetmap)")
    noise_scale: FloatProperty(
        name="Noise Scale", default=5.0, min=0.0, soft_max=100.0, update=_source,
        description="Scale of the procedural wet patches (patches per object-space unit)")
    exact_lookups: BoolProperty(
        name="Exact lookups (EEVEE)", default=False, update=_rebuild,
        description="Read the core's colour tables without the render engine's texture smoothing, so EEVEE "
                    "gives the same colours as Cycles (EEVEE smooths textures differently); a little slower, "
                    "no change in Cycles. Always on in Blender 4.2-4.5 (EEVEE needs it there)")
    quality: EnumProperty(
        name="Quality", update=_rebuild, default="BALANCED",
        description="What the group models, fastest first (the add-on's README gives each one's render cost "
                    "and colour error); after Make Wet the group is rebuilt in place",
        items=(("DRAFT", "Draft", "Leaves out the view factor (wet colours stay the head-on ones at grazing "
                "views) and the spill-edge bump (Spill Edge does nothing); the fastest"),
               ("BALANCED", "Balanced", "Everything the core models, tables read through the engine's "
                "linear filter"),
               ("EXACT", "Exact", "As Balanced, with the tables read exactly (a Closest read per colour "
                "channel and the core's bilinear blend); the slowest")))
    use_osl: BoolProperty(name="Use OSL shader", default=False,
                          description="Also add the core's OSL shader (Cycles with Open Shading Language only)")
    status: StringProperty(name="Status", default="", options={"SKIP_SAVE"},
                           description="Why the last change of a setting after Make Wet was refused")

    group_wetness: _float_proxy("Wetness", "Wetness", "Amount of liquid, 0 (dry) to 1 (saturated, with a "
                                "film); multiplied by the wetness source", 1.0, 0.0, 1.0, "FACTOR")
    puddle_level: _float_proxy("Puddle Level", "Puddle Level", "Wet-map values at or above this count as "
                               "fully wet (standing water); 1 leaves the map as it is", 1.0, 0.0, 1.0, "FACTOR")
    schedule: _bool_proxy("Schedule", "Schedule", "Follow the core's pore-filling schedule over Time "
                          "(off: the steady state, fully filled)")
    drying: _bool_proxy("Drying", "Drying", "Run the schedule backwards: wet at Start Time, dry after "
                        "Fill Time")
    time: _float_proxy("Time", "Schedule Time (s)", "The wetting schedule's clock, in seconds of the "
                       "liquid's time (not frames): key it, or let Key Drying map it onto the frame range",
                       1.0, -1e9, 1e9)
    start_time: _float_proxy("Start Time", "Liquid Arrives At (s)", "Schedule Time at which the liquid arrives "
                             "(with Drying: at which drying starts), in seconds", 0.0, -1e9, 1e9)
    fill_time: _float_proxy("Fill Time", "Pores Fill In (s)", "Seconds of Schedule Time the liquid takes to "
                            "soak into the pores (with Drying: to leave them), from Liquid Arrives At; the "
                            "preset's value by default", 1.0, 0.0, 1e9)
    spill_edge: _float_proxy("Spill Edge", "Spill Edge", "Strength of the bump where the wet map changes "
                             "(liquid standing at a spill's edge); 0 = off", 0.0, 0.0, 10.0)


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
    runnels: EnumProperty(
        name="Runnels", default="OFF",
        description="Whether the film running down steep faces breaks into runnels: below Hartley & "
                    "Murgatroyd's (1964) minimum wetting rate for the water's contact angle it gathers into "
                    "narrow rivulets about a centimetre apart, placed on the surface's grooves (soak bake rain "
                    "--contact-angle; a texel should be 2 mm or less for them to show)",
        items=(("OFF", "Off", "The film covers steep faces evenly (a perfectly wetting surface)"),
               ("PRESET", "From Preset", "The contact angle of the material's preset (materials.json: brick "
                "30 degrees, concrete 40, oak 60, ...)"),
               ("CUSTOM", "Contact Angle", "The Contact Angle set below")))
    contact_angle: FloatProperty(
        name="Contact Angle", default=math.radians(30.0), min=0.0, max=math.pi / 2, subtype="ANGLE",
        description="Water's contact angle on the surface, 0-90 degrees (clean glass 20-30, brick 30, "
                    "concrete 40, painted metal about 77): the larger, the sooner a thin film breaks into "
                    "runnels; 0 keeps the film")
    splashes: BoolProperty(
        name="Splashes", default=False,
        description="Drops landing on wet texels splash above Cossali et al.'s (1997) crown threshold, "
                    "throwing secondary drops that spot the dry ground 4-17 cm around (soak bake drops "
                    "--splash; the drops then land one after another on one thread)")


classes = (SoakMaterialSettings, SoakRainSettings)


_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()
    bpy.types.Material.soak = PointerProperty(type=SoakMaterialSettings)
    bpy.types.Scene.soak_rain = PointerProperty(type=SoakRainSettings)


def unregister():
    del bpy.types.Scene.soak_rain
    del bpy.types.Material.soak
    _unregister_classes()
