import bpy

from . import bake, volume, wet

classes = wet.classes + bake.classes + volume.classes

register, unregister = bpy.utils.register_classes_factory(classes)
