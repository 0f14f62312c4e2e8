"""Finding Soak's nodes in a material's tree: the tags Make Wet leaves on
the nodes it adds, the Principled BSDFs to wet, the Soak Wet group nodes,
socket records, and the marks that let Make Dry find renamed nodes."""

import json

from .wet_group import GROUP_TAG

NODE_TAG = "soak_node"


RESTORE_KEY = "soak_restore"


ROLE_KEY = "soak_role"          # on tagged nodes: "source" | "translucency"


PRIMARY_KEY = "soak_primary"    # on the first group node Make Wet made


REF_KEY = "soak_ref"            # on the user's nodes a restore record names (survives renames)


def _is_principled(n):
    return n.type == "BSDF_PRINCIPLED" and not n.get(NODE_TAG)


def _active_output(tree):
    out = None
    for n in tree.nodes:
        if n.type == "OUTPUT_MATERIAL" and (out is None or n.is_active_output):
            out = n
    return out


def principled_nodes(tree):
    """Every (untagged) Principled BSDF: those feeding the active output first,
    in depth-first order through Mix/Add shaders and groups' inputs, then the
    others."""
    seen, order = set(), []

    def visit(node):
        if node.name in seen:
            return
        seen.add(node.name)
        if _is_principled(node):
            order.append(node)
            return
        for s in node.inputs:
            for link in s.links:
                visit(link.from_node)

    out = _active_output(tree)
    if out is not None:
        visit(out)
    order += [n for n in tree.nodes if _is_principled(n) and n not in order]
    return order


def find_principled(tree):
    nodes_ = principled_nodes(tree)
    return nodes_[0] if nodes_ else None


def group_nodes(tree):
    """Every Soak Wet group node of a material (one per wetted Principled
    BSDF), the first wetted first: the panel reads its controls."""
    gns = [n for n in tree.nodes if n.get(NODE_TAG) and n.type == "GROUP"]
    return sorted(gns, key=lambda n: (not n.get(PRIMARY_KEY), n.name))


def find_group_node(tree):
    gns = group_nodes(tree)
    return gns[0] if gns else None


def group_info(gn):
    ng = gn.node_tree
    return json.loads(ng.get(GROUP_TAG, "{}")) if ng is not None else {}


def socket_value(sock):
    v = getattr(sock, "default_value", None)
    if v is None:
        return None
    try:
        return list(v)
    except TypeError:
        return v


def socket_record(sock):
    return {"links": [[l.from_node.name, l.from_socket.identifier] for l in sock.links], "value": socket_value(sock)}


def out_socket(node, identifier):
    for s in node.outputs:
        if s.identifier == identifier:
            return s
    return None


def in_socket(node, identifier):
    for s in node.inputs:
        if s.identifier == identifier:
            return s
    return None


def tag(n, role=None):
    n[NODE_TAG] = True
    if role:
        n[ROLE_KEY] = role
    return n


def new_node(tree, kind, x, y, label, role):
    """A node of ours with its role and the label the user sees."""
    n = tag(tree.nodes.new(kind), role)
    n.label = label
    n.location = (x, y)
    return n


def role_nodes(tree, role):
    return [n for n in tree.nodes if n.get(NODE_TAG) and n.get(ROLE_KEY) == role]


def record_our_nodes(tree, gns):
    """Rewrites each group node's restore record with the names of every
    node of ours now in the tree (Make Dry removes exactly these)."""
    ours = [n.name for n in tree.nodes if n.get(NODE_TAG) and n.type != "GROUP"]
    for g in gns:
        restore = json.loads(g[RESTORE_KEY])
        restore["nodes"] = ours
        g[RESTORE_KEY] = json.dumps(restore)


def set_ref(n, key):
    n[REF_KEY] = key
    return key


def find_ref(tree, name):
    """A node the restore record names: by name when it still carries its
    soak_ref mark, else by the mark (renamed; a duplicate copies the mark,
    the original keeps the name), else by name."""
    n = tree.nodes.get(name)
    if n is not None and n.get(REF_KEY) == name and not n.get(NODE_TAG):
        return n
    for m in tree.nodes:
        if m.get(REF_KEY) == name and not m.get(NODE_TAG):
            return m
    return n if n is not None and not n.get(NODE_TAG) else None


def clear_refs(tree):
    for n in tree.nodes:
        if REF_KEY in n:
            del n[REF_KEY]
