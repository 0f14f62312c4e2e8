import bpy

from . import wet, bake, volume

classes = wet.classes + bake.classes + volume.classes


def register():
    for c in classes:
        bpy.utils.register_class(c)


def unregister():
    for c in reversed(classes):
        bpy.utils.unregister_class(c)
