import bpy

from . import bake, beads, rain, volume, wet

classes = wet.classes + bake.classes + volume.classes + rain.classes + beads.classes

register, unregister = bpy.utils.register_classes_factory(classes)
