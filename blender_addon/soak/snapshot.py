"""All-or-nothing changes: a material's tree (nodes, links, input values)
and the node-group list, put back after a failed change."""

import bpy

from .material_tree import REF_KEY, socket_value, out_socket, in_socket


def _link_key(link):
    return (link.from_node.name, link.from_socket.identifier, link.to_node.name, link.to_socket.identifier)


class Snapshot:
    """The state of a material's tree (nodes, links, input values) and of the
    node-group list, to put back after a failed change."""

    def __init__(self, tree):
        self.tree = tree
        self.names = {n.name for n in tree.nodes}
        self.links = {_link_key(l) for l in tree.links}
        self.values = {(n.name, s.identifier): socket_value(s) for n in tree.nodes for s in n.inputs}
        self.groups = {g.name for g in bpy.data.node_groups}
        self.refs = {n.name: n.get(REF_KEY) for n in tree.nodes}
        self.shown = {n.name: (n.label, [s.hide for s in n.inputs]) for n in tree.nodes if n.type == "GROUP"}

    def restore(self):
        t = self.tree
        for n in [n for n in t.nodes if n.name not in self.names]:
            t.nodes.remove(n)
        for l in [l for l in t.links if _link_key(l) not in self.links]:
            t.links.remove(l)
        have = {_link_key(l) for l in t.links}
        for fn, fs, tn, ts in self.links - have:
            a, b = t.nodes.get(fn), t.nodes.get(tn)
            src, dst = a and out_socket(a, fs), b and in_socket(b, ts)
            if src is not None and dst is not None:
                t.links.new(src, dst)
        for (name, ident), v in self.values.items():
            n = t.nodes.get(name)
            s = n and in_socket(n, ident)
            if s is not None and v is not None and socket_value(s) != v:
                s.default_value = v
        for name, ref in self.refs.items():
            n = t.nodes.get(name)
            if n is not None and n.get(REF_KEY) != ref:
                if ref is None:
                    del n[REF_KEY]
                else:
                    n[REF_KEY] = ref
        for name, (label, hidden) in self.shown.items():
            n = t.nodes.get(name)
            if n is not None and len(n.inputs) == len(hidden):
                n.label = label
                for s, h in zip(n.inputs, hidden):
                    s.hide = h and not s.is_linked
        for g in [g for g in bpy.data.node_groups if g.name not in self.groups and g.users == 0]:
            bpy.data.node_groups.remove(g)


def atomic(tree, fn, *args):
    snap = Snapshot(tree)
    try:
        return fn(*args)
    except BaseException:
        snap.restore()
        raise
