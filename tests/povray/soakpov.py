"""Shared helpers of the POV-Ray front-end tests (run with /usr/bin/python3)."""
import json
import os
import re
import subprocess
import sys

import numpy as np

PIXEL = re.compile(r"Pixel \((\d+), (\d+)\):\s+(.*)")


def read_image(path):
    """Linear float pixels of an EXR through `oiiotool --dumpdata` (no Python OIIO here)."""
    out = subprocess.run(["oiiotool", "--dumpdata", path], check=True, capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        m = PIXEL.search(line)
        if m:
            rows.append((int(m.group(1)), int(m.group(2)), [float(v) for v in m.group(3).split()]))
    if not rows:
        raise RuntimeError(f"{path}: no pixels read")
    w = max(r[0] for r in rows) + 1
    h = max(r[1] for r in rows) + 1
    img = np.zeros((h, w, len(rows[0][2])))
    for x, y, v in rows:
        img[y, x] = v
    return img[:, :, :3]


def povray(pov, out_exr, width, height, lib, extra=(), cwd=None):
    """Renders pov headless into a linear EXR; returns (exit code, combined output)."""
    cmd = ["povray", f"+I{pov}", f"+O{out_exr}", "+FE", f"+W{width}", f"+H{height}", "-D", "-V", "+WT1",
           f"+L{lib}", "-P", "+Q9", "Output_Alpha=off"] + list(extra)
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=cwd)
    return r.returncode, r.stdout + r.stderr


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def need_tool(name):
    from shutil import which
    if which(name) is None:
        fail(f"{name} not found on PATH (installed by the README's set-up; a front-end test never passes without it)")


def setup_args(usage):
    """The arguments SOAK ROOT TMPDIR (absolute), povray and oiiotool checked, TMPDIR made; also the
    folder of soak.inc. Returns (soak, root, tmp, lib)."""
    if len(sys.argv) < 4:
        fail(usage)
    soak, root, tmp = (os.path.abspath(a) for a in sys.argv[1:4])
    need_tool("povray")
    need_tool("oiiotool")
    os.makedirs(tmp, exist_ok=True)
    return soak, root, tmp, os.path.join(root, "povray")


def export_json(soak, tmp):
    """`soak export --target json` into tmp, parsed (the core's tables: the references' data)."""
    path = os.path.join(tmp, "export.json")
    r = subprocess.run([soak, "export", "--target", "json", "-o", path], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"soak export --target json: exit {r.returncode}: {r.stderr}")
    with open(path) as f:
        return json.load(f)
