#!/usr/bin/env python3
"""Bakes every model of a corpus (default: Debian's assimp-testmodels) with
`soak bake rain` at a small size and classifies each outcome by format.

usage: mesh_corpus.py SOAK [--root DIR] [--size 128] [--rays 16] [--jobs 2]
                       [--timeout 120] [--tsv OUT.tsv]

Classes: baked (exit 0, a texel of the wetness or exposure map above 0),
warned-empty (exit 0, both maps 0, a warning on stderr), silent-empty (exit 0,
both maps 0, no warning), unsupported (format refused), no-uvs, refused
(another clear refusal, exit 1/2 naming the file), crash (a signal or a
message about the reader crashing), timeout. The map maximum is read with
oiiotool --stats, not with soak."""
import argparse
import collections
import concurrent.futures as cf
import os
import re
import subprocess
import tempfile

AUX = {"png", "jpg", "jpeg", "tga", "bmp", "dds", "txt", "bin", "mtl", "glsl", "vert", "frag", "material",
       "md", "program", "skeleton", "uc", "mesh", "pk3", "shader", "ppm", "gif"}


def corpus(root):
    for d, _, files in os.walk(root):
        if "ReferenceImages" in d or "SourceFiles" in d:
            continue
        for f in files:
            ext = f.rsplit(".", 1)[-1].lower() if "." in f else ""
            if ext and ext not in AUX:
                yield os.path.join(d, f), ext


def map_max(path):
    r = subprocess.run(["oiiotool", "--stats", path], capture_output=True, text=True)
    m = re.search(r"Stats Max:\s*([-0-9.e+naif]+)", r.stdout)
    return float(m.group(1)) if m else float("nan")


def classify(soak, path, size, rays, timeout, tmp):
    wet, exp = os.path.join(tmp, "w.exr"), os.path.join(tmp, "e.exr")
    for p in (wet, exp):
        if os.path.exists(p):
            os.remove(p)
    cmd = [soak, "bake", "rain", path, "--width", str(size), "--height", str(size), "--rays", str(rays),
           "--duration", "60", "--steps", "4", "-o", wet, "--exposure", exp]
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, errors="replace")
    except subprocess.TimeoutExpired:
        return "timeout", ""
    err = r.stderr.strip().splitlines()
    msg = err[-1] if err else ""
    if r.returncode < 0 or "crashed" in r.stderr:
        return "crash", msg
    if "did not finish within" in r.stderr:
        return "timeout", msg
    if r.returncode == 0:
        top = max(map_max(wet), map_max(exp))
        if top > 0:
            return "baked", msg
        return ("warned-empty" if "warning" in r.stderr.lower() else "silent-empty"), msg
    if "unsupported mesh format" in r.stderr or "not supported" in r.stderr:
        return "unsupported", msg
    if "no UVs" in r.stderr or "no texture coordinates" in r.stderr:
        return "no-uvs", msg
    return "refused", msg


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("soak")
    ap.add_argument("--root", default="/usr/share/assimp/models")
    ap.add_argument("--size", type=int, default=128)
    ap.add_argument("--rays", type=int, default=16)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--tsv")
    a = ap.parse_args()
    files = sorted(corpus(a.root))
    tmps = [tempfile.mkdtemp(prefix="soak-corpus-") for _ in range(len(files))]

    def one(i):
        path, ext = files[i]
        cls, msg = classify(a.soak, path, a.size, a.rays, a.timeout, tmps[i])
        return os.path.relpath(path, a.root), ext, cls, msg

    with cf.ThreadPoolExecutor(a.jobs) as ex:
        rows = list(ex.map(one, range(len(files))))
    by = collections.defaultdict(collections.Counter)
    total = collections.Counter()
    for rel, ext, cls, _ in rows:
        by[ext][cls] += 1
        total[cls] += 1
    if a.tsv:
        with open(a.tsv, "w") as f:
            for row in rows:
                f.write("\t".join(x.replace("\t", " ") for x in row) + "\n")
    classes = ["baked", "warned-empty", "silent-empty", "unsupported", "no-uvs", "refused", "crash", "timeout"]
    print("format\tfiles\t" + "\t".join(classes))
    for ext in sorted(by):
        print(f"{ext}\t{sum(by[ext].values())}\t" + "\t".join(str(by[ext][c]) for c in classes))
    print(f"ALL\t{len(rows)}\t" + "\t".join(str(total[c]) for c in classes))


if __name__ == "__main__":
    main()
