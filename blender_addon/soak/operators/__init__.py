import bpy

from . import bake, rain, volume, wet

classes = wet.classes + bake.classes + volume.classes + rain.classes

register, unregister = bpy.utils.register_classes_factory(classes)
