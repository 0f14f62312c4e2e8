"""What the testshade checks of the OSL shaders share: skip with ctest's 77,
run a tool or fail with its message, and read an image's pixels through
oiiotool (osl_beads.py, osl_ripples.py)."""
import re
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
