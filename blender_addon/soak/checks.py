"""What Make Wet and the other changes check before a tree is touched."""


from . import compat, data
from .material_tree import principled_nodes, find_group_node

_REQUIRED_ROLES = ("base_color", "roughness", "coat_weight", "coat_roughness", "normal")


def check_editable(mat):
    """Raises RuntimeError for a material whose node tree may not be edited."""
    if mat.library is not None:
        raise RuntimeError(f"material '{mat.name}' is linked from the library '{mat.library.filepath}': "
                           "its changes would be lost on reload; make it local first "
                           "(Object > Relations > Make Local)")
    if getattr(mat, "override_library", None) is not None:
        raise RuntimeError(f"material '{mat.name}' is a library override: its node tree cannot be edited; "
                           "make it local first (Object > Relations > Make Local)")
    if not compat.material_uses_nodes(mat):
        raise RuntimeError(f"material '{mat.name}' does not use nodes")


def check_source(settings):
    src = settings.wetness_source
    if src == "IMAGE" and settings.wet_map is None:
        raise RuntimeError("wetness source 'Image' needs an image (choose one or bake a wet map)")
    if src == "ATTRIBUTE" and not settings.attribute_name.strip():
        raise RuntimeError("wetness source 'Attribute' needs an attribute name (e.g. dp_wetmap)")


def check_data(settings):
    """The core's data for the settings (raises SoakDataError)."""
    data.material(settings.preset)
    data.table(settings.preset, settings.liquid)
    data.liquid(settings.liquid)


def _check_inputs(bsdfs):
    for bsdf in bsdfs:
        missing = [compat.principled_name(r) for r in _REQUIRED_ROLES if compat.principled_input(bsdf, r) is None]
        if missing:
            raise RuntimeError(f"'{bsdf.name}' lacks the inputs {', '.join(missing)}")


def check_principled(mat):
    """The material's Principled BSDFs once its groups are opened (raises
    RuntimeError when there is none)."""
    bsdfs = principled_nodes(mat.node_tree)
    if not bsdfs:
        raise RuntimeError(f"material '{mat.name}' has no Principled BSDF")
    _check_inputs(bsdfs)
    return bsdfs


def check_wettable(mat, settings, grouped=False):
    """Everything Make Wet needs, checked before the tree is touched.
    Returns the Principled BSDFs to wet: every one in the material (none
    yet where grouped: those inside node groups, ungroup.open_groups makes
    them the material's own)."""
    check_editable(mat)
    tree = mat.node_tree
    if find_group_node(tree) is not None:
        raise RuntimeError(f"material '{mat.name}' is already wet (Make Dry first)")
    bsdfs = principled_nodes(tree)
    if not bsdfs and not grouped:
        raise RuntimeError(f"material '{mat.name}' has no Principled BSDF (nor a node group holding one)")
    _check_inputs(bsdfs)
    check_data(settings)
    check_source(settings)
    return bsdfs
