"""Shared helpers of the Blender tests (run inside Blender)."""
import json
import os
import sys

import bpy


def args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    out = {}
    i = 0
    while i < len(argv):
        out[argv[i].lstrip("-")] = argv[i + 1]
        i += 2
    return out


def install_addon(zip_path):
    """Installs and enables the add-on from the built zip (like a user)."""
    if not os.path.isfile(zip_path):
        raise SystemExit(f"add-on zip not found: {zip_path} (make addon)")
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="soak")
    import soak  # noqa: F401
    assert hasattr(bpy.types.Material, "soak"), "add-on registered no Material.soak"
    return sys.modules["soak"]


def tree_state(tree):
    """A canonical description of a node tree: nodes, input values, links."""
    nodes = {}
    for n in tree.nodes:
        vals = {}
        for s in n.inputs:
            v = getattr(s, "default_value", None)
            if v is None:
                continue
            try:
                v = [round(float(x), 7) for x in v]
            except TypeError:
                v = round(float(v), 7) if isinstance(v, (int, float)) else str(v)
            vals[s.identifier] = v
        nodes[n.name] = {"type": n.bl_idname, "inputs": vals}
    links = sorted((l.from_node.name, l.from_socket.identifier, l.to_node.name, l.to_socket.identifier)
                   for l in tree.links)
    return json.dumps({"nodes": nodes, "links": links}, sort_keys=True)


def fail(msg):
    print("FAIL:", msg)
    raise SystemExit(1)
