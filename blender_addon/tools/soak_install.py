"""Installs the add-on zip the way users of the running Blender install it
(for the project's scripts: tests, gallery, screenshots, benchmarks; not
part of the zip):

- Blender 3.x-4.1: Preferences > Add-ons > Install (addon_install +
  addon_enable); the module is `soak`.
- Blender 4.2+: Get Extensions > Install from Disk
  (extensions.package_install_files into the user repository); the module
  is `bl_ext.user_default.soak`.

install(zip) returns (module, the name Blender knows it by: the key of
bpy.context.preferences.addons). The module is also reachable as `soak`
(sys.modules aliases), so scripts import it one way in every version."""
import os
import sys

import bpy

EXTENSION_REPO = "user_default"


def _alias(name):
    """sys.modules['soak'...] for the extension's modules (bl_ext....soak...)."""
    for key in [k for k in sys.modules if k == name or k.startswith(name + ".")]:
        sys.modules["soak" + key[len(name):]] = sys.modules[key]


def install(zip_path):
    if not os.path.isfile(zip_path):
        raise SystemExit(f"add-on zip not found: {zip_path} (make addon)")
    zip_path = os.path.abspath(zip_path)
    if bpy.app.version >= (4, 2, 0):
        name = f"bl_ext.{EXTENSION_REPO}.soak"
        r = bpy.ops.extensions.package_install_files(filepath=zip_path, repo=EXTENSION_REPO,
                                                     enable_on_install=True, overwrite=True)
        if r != {"FINISHED"} or name not in sys.modules:
            raise SystemExit(f"the extension did not install from {zip_path}: {r}")
        _alias(name)
    else:
        name = "soak"
        bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
        bpy.ops.preferences.addon_enable(module=name)
        import soak  # noqa: F401
    if not hasattr(bpy.types.Material, "soak"):
        raise SystemExit("the add-on registered no Material.soak")
    mod = sys.modules[name]
    source = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "soak")
    if os.path.abspath(mod.__file__).startswith(source + os.sep):
        raise SystemExit(f"the add-on was imported from the source tree ({mod.__file__}), not from {zip_path}")
    return mod, name


def preferences():
    """The installed add-on's preferences (soak_path, ...)."""
    return bpy.context.preferences.addons[sys.modules["soak"].__name__].preferences
