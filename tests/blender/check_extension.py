"""Run by test_extension_repo.sh: the extension of repository REPO is
enabled in the saved preferences, imports, registers Make Wet, and Blender
reports VERSION for it.  blender -b --python check_extension.py -- REPO VERSION"""
import sys

import addon_utils
import bpy

repo, version = sys.argv[sys.argv.index("--") + 1:][:2]
name = f"bl_ext.{repo}.soak"
if name not in bpy.context.preferences.addons:
    print(f"FAIL: {name} is not enabled (enabled: {sorted(bpy.context.preferences.addons.keys())})")
    raise SystemExit(1)
mod = sys.modules.get(name)
if mod is None or not hasattr(bpy.types, "SOAK_OT_make_wet"):
    print(f"FAIL: {name} enabled but not loaded (Make Wet registered: {hasattr(bpy.types, 'SOAK_OT_make_wet')})")
    raise SystemExit(1)
got = ".".join(str(x) for x in addon_utils.module_bl_info(mod)["version"])
if got != version:
    print(f"FAIL: Blender reports {name} {got}, expected {version}")
    raise SystemExit(1)
print(f"ok: {name} {got} enabled, Make Wet registered")
