"""What the testshade checks of the OSL shaders share: skip with ctest's 77,
run a tool or fail with its message, and read an image's pixels through
oiiotool (osl_beads.py, osl_ripples.py)."""
import math
import os
import re
import shutil
import subprocess
import sys


def skip(reason):
    print("SKIPPED: " + reason)
    sys.exit(77)


def run(cmd, cwd):
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=cwd)
    if r.returncode != 0:
        print("FAIL: %s: %s" % (" ".join(cmd), (r.stderr or r.stdout).strip()[-400:]))
        sys.exit(1)
    return r.stdout


def dump(path, tmp, count):
    """Pixels of an image as {(x, y): [channels]} (oiiotool --dumpdata);
    fails unless it holds count pixels."""
    out = run(["oiiotool", "--dumpdata", path], tmp)
    px = {}
    for m in re.finditer(r"Pixel \((\d+), (\d+)\):\s*([-0-9.e+ ]+)", out):
        px[(int(m.group(1)), int(m.group(2)))] = [float(v) for v in m.group(3).split()]
    if len(px) != count:
        print("FAIL: %s: %d pixels read, expected %d" % (path, len(px), count))
        sys.exit(1)
    return px


def prepare(tmp, root, shader):
    """Skips without the OSL tools, empties tmp and compiles the named shader
    into it (osl/<shader>.osl)."""
    missing = [t for t in ("oslc", "testshade", "oiiotool") if not shutil.which(t)]
    if missing:
        skip("OSL tools not on PATH: " + ", ".join(missing))
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    run(["oslc", "-o", os.path.join(tmp, shader + ".oso"), os.path.join(root, "osl", shader + ".osl")], tmp)


def decode_normal(c):
    """A normal map texel (RGB in [0, 1]) as the unit vector normalize(2 c - 1)."""
    n = [2.0 * c[i] - 1.0 for i in range(3)]
    ln = math.sqrt(sum(a * a for a in n))
    return [a / ln for a in n]
