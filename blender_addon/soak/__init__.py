# SPDX-License-Identifier: GPL-3.0-or-later
"""Soak: physically based wet materials for Blender (Cycles and EEVEE).

Every number the node groups use comes from the Soak C core through
`soak export --target blender` (soak_data.json next to this file)."""

bl_info = {
    "name": "Soak wet materials",
    "author": "Soak project",
    "version": (1, 0, 0),
    "blender": (3, 4, 0),
    "location": "Properties > Material > Soak; Shader Editor > Sidebar > Soak; Add > Soak",
    "description": "Make any Principled BSDF material wet (presets from the Soak core), bake wet maps",
    "category": "Material",
}

from . import handlers, operators, preferences, properties, rain_ui, ui

_modules = (preferences, properties, operators, ui, rain_ui, handlers)


def register():
    for m in _modules:
        m.register()


def unregister():
    for m in reversed(_modules):
        m.unregister()
