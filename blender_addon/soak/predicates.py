"""Predicates the operators and the panels share: may an operator run on
the active material (and why not, through poll_message_set), is OSL
available, is a group input keyed on this frame."""

from . import compat, material_tree


def osl_available(context):
    scene = context.scene
    return scene.render.engine == "CYCLES" and bool(getattr(scene.cycles, "shading_system", False))


def poll_message(cls, text):
    """poll_message_set exists in Blender 3.0+; older ones just grey the button."""
    fn = getattr(cls, "poll_message_set", None)
    if fn is not None:
        fn(text)
    return False


def poll_editable(cls, context):
    """The reason an operator on the active material cannot run, or None."""
    ob = context.object
    if ob is None:
        return poll_message(cls, "No active object")
    mat = ob.active_material
    if mat is None:
        return poll_message(cls, f"'{ob.name}' has no material: add one in the Material tab")
    if mat.library is not None:
        return poll_message(cls, f"Material '{mat.name}' is linked from a library: make it local first "
                                 "(Object > Relations > Make Local)")
    if not compat.material_uses_nodes(mat):
        return poll_message(cls, f"Material '{mat.name}' does not use nodes: click Use Nodes first")
    return True


def wet_poll(cls, context):
    if not poll_editable(cls, context):
        return False
    if material_tree.find_group_node(context.object.active_material.node_tree) is None:
        return poll_message(cls, "Make the material wet first")
    return True


def control_fcurve(tree, gn, name):
    """The F-curve animating the group node's input `name`, or None."""
    sock = gn.inputs.get(name)
    if sock is None:
        return None
    index = list(gn.inputs).index(sock)
    return compat.find_fcurve(tree, f'nodes["{gn.name}"].inputs[{index}].default_value')


def key_icon(context, tree, gn, name):
    """The decorator icon Blender draws for a keyable property: key on this
    frame, animated, or not animated."""
    fc = control_fcurve(tree, gn, name)
    if fc is None:
        return "DECORATE"
    f = context.scene.frame_current
    if any(abs(k.co[0] - f) < 0.5 for k in fc.keyframe_points):
        return "DECORATE_KEYFRAME"
    return "DECORATE_ANIMATE"
