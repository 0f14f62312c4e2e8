#!/usr/bin/env python3
"""No circle of files in libsoak (issue 44): the include and call graph of
c_core, drawn from the build's object files and the sources' #includes,
has no strongly connected component of more than one unit.

A unit is a source file with the header of the same name (x.c + x.h, the
header public in <layer>/include/soak or private in <layer>/src); a header
without a source of its name (a layer's shared context, such as
render/src/rt_ctx.h) is a unit of its own. Unit A depends on unit B when
A's object file takes a symbol B's object file defines (`nm`: a call or a
datum), or A (source or header) #includes B's private header (in
<layer>/src). A public header (<layer>/include/soak) is the layer's
contract, often types only: who uses what it declares shows as a call. A circle is a set of
units each reaching every other (Tarjan's strongly connected components).

Usage: circles.py SOURCE_DIR BUILD_DIR [--list]   (--list: every edge)
       circles.py --self-test                      (a planted circle is found)
Exit 0: no circle but the ALLOWED ones; 1: circles (each printed with the
edges that close it).
"""
import os
import re
import subprocess
import sys
from collections import defaultdict

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)

# Circles still allowed, with the reason: a circle passes when each of its
# units starts with one of an entry's prefixes (so a branch merged later that
# adds or removes a file of the same module does not fail). An entry whose
# circle is gone is reported: delete it.
ALLOWED = {}


def unit_of(path):
    """The unit a source or header belongs to: layer/stem (cli/stem)."""
    parts = path.split(os.sep)
    stem = os.path.splitext(parts[-1])[0]
    if "c_core" in parts:
        i = parts.index("c_core")
        return parts[i + 1] + "/" + stem
    return stem


def sources(src_root):
    """Every .c and .h of the library and the CLI, as paths under SOURCE_DIR."""
    out = []
    base = os.path.join(src_root, "c_core")
    for layer in sorted(os.listdir(base)):
        for sub in ("src", "include/soak", ""):
            d = os.path.join(base, layer, sub)
            if layer in ("bench", "data") or not os.path.isdir(d):
                continue
            if sub == "" and layer != "cli":
                continue
            for f in sorted(os.listdir(d)):
                if f.endswith((".c", ".h")):
                    out.append(os.path.join(d, f))
    return out


def include_edges(files):
    """unit -> set of units, from #include "..." resolved by file name."""
    by_name = defaultdict(list)
    for f in files:
        by_name[os.path.basename(f)].append(f)
    edges = defaultdict(set)
    for f in files:
        with open(f, encoding="utf-8", errors="replace") as fh:
            text = fh.read()
        layer = unit_of(f).split("/")[0]
        for inc in INCLUDE.findall(text):
            cands = by_name.get(os.path.basename(inc), [])
            # a private header of the same name lives in the includer's layer
            same = [c for c in cands if unit_of(c).split("/")[0] == layer]
            for c in same or cands[:1]:
                # a public header (<layer>/include/soak) is the layer's
                # contract: who calls what it declares shows as a call edge
                if "/include/" not in c and unit_of(c) != unit_of(f):
                    edges[unit_of(f)].add(unit_of(c))
    return edges


def objects(build_dir):
    """(unit, object path) for every object file of libsoak and the CLI."""
    out = []
    root = os.path.join(build_dir, "c_core", "CMakeFiles")
    for target in sorted(os.listdir(root)):
        if not (target.startswith("soak_") and target.endswith(".dir")) or "plugin" in target:
            continue
        for dirpath, _, names in os.walk(os.path.join(root, target)):
            for n in names:
                if n.endswith(".c.o"):
                    rel = os.path.relpath(os.path.join(dirpath, n[:-2]), os.path.join(root, target))
                    out.append((unit_of(os.path.join("c_core", rel)), os.path.join(dirpath, n)))
    return out


def nm_symbols(obj):
    res = subprocess.run(["nm", "-P", obj], capture_output=True, text=True, check=True)
    defined, used = set(), set()
    for line in res.stdout.splitlines():
        f = line.split()
        if len(f) < 2:
            continue
        (used if f[1] == "U" else defined).add(f[0]) if f[1] in "UTDBRC" else None
    return defined, used


def symbol_edges(objs):
    owner, uses = {}, {}
    for unit, obj in objs:
        d, u = nm_symbols(obj)
        for s in d:
            owner[s] = unit
        uses[unit] = uses.get(unit, set()) | u
    edges = defaultdict(set)
    for unit, u in uses.items():
        for s in u:
            if s in owner and owner[s] != unit:
                edges[unit].add(owner[s])
    return edges


def circles(edges):
    """Strongly connected components of more than one node (Tarjan, iterative)."""
    nodes = set(edges) | {v for vs in edges.values() for v in vs}
    index, low, on, stack, out, counter = {}, {}, set(), [], [], [0]
    for root in sorted(nodes):
        if root in index:
            continue
        work = [(root, iter(sorted(edges.get(root, ()))))]
        index[root] = low[root] = counter[0]
        counter[0] += 1
        stack.append(root)
        on.add(root)
        while work:
            v, it = work[-1]
            nxt = next(it, None)
            if nxt is not None:
                if nxt not in index:
                    index[nxt] = low[nxt] = counter[0]
                    counter[0] += 1
                    stack.append(nxt)
                    on.add(nxt)
                    work.append((nxt, iter(sorted(edges.get(nxt, ())))))
                elif nxt in on:
                    low[v] = min(low[v], index[nxt])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                if len(comp) > 1:
                    out.append(sorted(comp))
    return out


def merge(*graphs):
    out = defaultdict(set)
    for g in graphs:
        for k, vs in g.items():
            out[k] |= vs
    return out


def allowed(comp):
    for prefixes, why in ALLOWED.items():
        if all(any(u.startswith(p) for p in prefixes) for u in comp):
            return why
    return None


def report(edges, inc, sym):
    found = []
    for comp in circles(edges):
        why = allowed(comp)
        if why:
            print(f"allowed circle of {len(comp)} units ({why}): {', '.join(comp)}")
            continue
        found.append(comp)
        print(f"circle of {len(comp)} units: {', '.join(comp)}")
        for a in comp:
            for b in sorted(edges[a] & set(comp)):
                how = "+".join(w for w, g in (("include", inc), ("call", sym)) if b in g.get(a, ()))
                print(f"  {a} -> {b} ({how})")
    return found


def self_test():
    g = {"render/a": {"render/b"}, "render/b": {"render/c"}, "render/c": {"render/a"}, "render/d": {"render/a"}}
    ok = circles(g) == [["render/a", "render/b", "render/c"]]
    ok = ok and circles({"x": {"y"}, "y": set()}) == []
    # the scene reader's circle before issue 44 (material -> preset -> levels -> preset, preset -> material)
    before = {"render/scene_material": {"render/scene_preset", "render/scene_levels"},
              "render/scene_preset": {"render/scene_material", "render/scene_levels"},
              "render/scene_levels": {"render/scene_preset"}}
    ok = ok and circles(before) == [["render/scene_levels", "render/scene_material", "render/scene_preset"]]
    print("self-test:", "a planted 3-circle found, a chain passes" if ok else "FAILED")
    return 0 if ok else 1


def main(argv):
    if argv[1:2] == ["--self-test"]:
        return self_test()
    if len(argv) < 3:
        print(__doc__)
        return 2
    src, build = argv[1], argv[2]
    objs = objects(build)
    if not objs:
        print(f"circles: no object files of libsoak under {build}/c_core/CMakeFiles (build first)")
        return 2
    inc = include_edges(sources(src))
    sym = symbol_edges(objs)
    edges = merge(inc, sym)
    if "--list" in argv:
        for a in sorted(edges):
            for b in sorted(edges[a]):
                print(a, "->", b)
    found = report(edges, inc, sym)
    n_units = len(set(edges) | {v for vs in edges.values() for v in vs})
    all_found = circles(edges)
    for k in ALLOWED:
        if not any(all(any(u.startswith(p) for p in k) for u in c) for c in all_found):
            print(f"note: the allowed circle of {', '.join(k)} is gone: delete its entry in ALLOWED")
    print(f"circles: {len(objs)} object files, {n_units} units, "
          f"{sum(len(v) for v in edges.values())} edges, {len(found)} circle(s) not allowed")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
