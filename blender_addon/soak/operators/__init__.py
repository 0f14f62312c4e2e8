import bpy

from . import wet, bake

classes = wet.classes + bake.classes


def register():
    for c in classes:
        bpy.utils.register_class(c)


def unregister():
    for c in reversed(classes):
        bpy.utils.unregister_class(c)
