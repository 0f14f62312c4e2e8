"""Keeps specialised groups true to their node (wet_constant, wet_bounds):
after any change Blender evaluates (a link drawn into Wetness, a value typed
on the node, a key added in the node editor, a wet map saved, an undo), a
group built for a liquid amount, or for bounds of it, that its inputs no
longer give is rebuilt (specialise.specialise, all or nothing; a failure is
printed and the material left as it was). The panel,
its key buttons and the operators rebuild at once; this catches edits made
elsewhere."""

import bpy
from bpy.app.handlers import persistent

from . import data, material_tree, specialise

_busy = []


def _soak_materials():
    for mat in bpy.data.materials:
        if (mat.library is None and getattr(mat, "override_library", None) is None and mat.node_tree is not None
                and material_tree.find_group_node(mat.node_tree) is not None):
            yield mat


@persistent
def respecialise(_scene=None, _depsgraph=None):
    if _busy:
        return
    _busy.append(True)
    try:
        for mat in _soak_materials():
            try:
                specialise.specialise(mat)
            except (RuntimeError, data.SoakDataError) as e:
                print(f"soak: {mat.name}: the Soak Wet group was not rebuilt: {e}")
    finally:
        _busy.clear()


def register():
    bpy.app.handlers.depsgraph_update_post.append(respecialise)
    bpy.app.handlers.load_post.append(respecialise)


def unregister():
    for h in (bpy.app.handlers.depsgraph_update_post, bpy.app.handlers.load_post):
        if respecialise in h:
            h.remove(respecialise)
