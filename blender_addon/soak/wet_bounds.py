"""What a Soak Wet group's liquid amount can be, and the node programs
folded to it (issue 33: model only what a material needs).

The liquid L is one exported program (liquid_program: the core's fill
schedule, then Drying, Schedule, Puddle Level, Wet Map and Wetness as
wet_group builds them) over the group's inputs. Each input is bounded
(input_bounds): a value (unlinked, unkeyed), the range of its keys (the
convex hull of a Bezier segment's keys and handles holds the curve), the
range of the pixels of an image read straight into it; anything else
(a driver, a modifier, extrapolation, any other node) is unbounded. Interval
arithmetic on the program then bounds L; fold_program replaces every
operation whose interval is one number by that number (the schedule a
material does not use disappears), and drops the operations that pass a
value through unchanged. Where L provably never exceeds the table's
`saturation` (the export's level where the film starts: soak_data.json
"layout"), the row program's film branch is constant and folds away.

Only the core's exported programs are evaluated here, on intervals."""

import math
import os

from . import data
from .wet_constant import _math

INF = float("inf")
UNKNOWN = (-INF, INF)
# an interval narrower than this is one number (the film branch at exactly
# the saturation level rounds to 1e-10 and below; a row coordinate)
POINT = 1e-7

# group input -> the program's name for it
NAMES = {"Wetness": "wetness", "Wet Map": "wet_map", "Puddle Level": "puddle_level", "Schedule": "schedule",
         "Drying": "drying", "Time": "time", "Start Time": "start_time", "Fill Time": "fill_time"}


def liquid_program():
    """L as one program over NAMES' values: the export's schedule program P,
    then L = Wetness * min(Wet Map / max(Puddle Level, 1e-3), 1) *
    mix(1, P or 1 - P by Drying, Schedule), clamped as the group's nodes."""
    ops = [list(op) for op in data.load()["schedule_program"]]
    n = len(ops)
    p = f"#{n - 1}"
    ops += [["MULTIPLY_ADD", p, -2.0, 1.0, False],                    # n:   1 - 2P
            ["MULTIPLY_ADD", f"#{n}", "drying", p, False],            # n+1: P + D (1 - 2P)
            ["SUBTRACT", 1.0, f"#{n + 1}", False],                    # n+2
            ["SUBTRACT", 1.0, "schedule", False],                     # n+3
            ["MULTIPLY_ADD", f"#{n + 2}", f"#{n + 3}", f"#{n + 1}", False],
            ["MAXIMUM", "puddle_level", 1e-3, False],                 # n+5
            ["DIVIDE", "wet_map", f"#{n + 5}", True],
            ["MULTIPLY", "wetness", f"#{n + 6}", True],
            ["MULTIPLY", f"#{n + 7}", f"#{n + 4}", True]]
    return ops


def _is_num(a):
    return isinstance(a, (int, float)) and not isinstance(a, bool)


def _products(a, b):
    vals = [x * y for x in a for y in b]
    return UNKNOWN if any(math.isnan(v) for v in vals) else (min(vals), max(vals))


def _interval(op, args):
    """An operation of Blender's Math node on intervals (lo, hi)."""
    if all(lo == hi for lo, hi in args):
        v = _math(op, *[lo for lo, _ in args])
        return (v, v)
    a, b = args[0], args[1] if len(args) > 1 else (0.0, 0.0)
    if op == "ADD":
        return (a[0] + b[0], a[1] + b[1])
    if op == "SUBTRACT":
        return (a[0] - b[1], a[1] - b[0])
    if op == "MULTIPLY":
        return _products(a, b)
    if op == "MULTIPLY_ADD":
        m = _products(a, b)
        return (m[0] + args[2][0], m[1] + args[2][1])
    if op == "DIVIDE":
        if not (b[0] > 0.0 or b[1] < 0.0):      # a divisor that may be 0 (Blender's gives 0 there)
            return UNKNOWN
        return _products(a, (1.0 / b[1], 1.0 / b[0]))
    if op == "MINIMUM":
        return (min(a[0], b[0]), min(a[1], b[1]))
    if op == "MAXIMUM":
        return (max(a[0], b[0]), max(a[1], b[1]))
    if op == "SQRT":
        return (_math("SQRT", a[0]), _math("SQRT", a[1]))
    return UNKNOWN


def _clamp(iv):
    return (min(max(iv[0], 0.0), 1.0), min(max(iv[1], 0.0), 1.0))


def intervals(ops, env):
    """Each operation's interval for env {name: (lo, hi)}."""
    out = []
    for op in ops:
        args = [(a, a) if _is_num(a) else (out[int(a[1:])] if a.startswith("#") else env[a]) for a in op[1:-1]]
        iv = _interval(op[0], args)
        out.append(_clamp(iv) if op[-1] else iv)
    return out


def _passes_through(op, ivs_of_args):
    """The index of the argument the operation returns unchanged, or None:
    x * 1, x / 1, x + 0, x - 0, max(x, c) with x >= c, min(x, c) with x <= c,
    clamped only where x lies in [0, 1] already."""
    name, args, clamp = op[0], op[1:-1], op[-1]
    if clamp and not all(0.0 <= v <= 1.0 for v in ivs_of_args[0]):
        return None
    x, c = ivs_of_args[0], ivs_of_args[1] if len(args) > 1 else None
    if c is None or c[0] != c[1] or len(args) != 2:
        return None
    if (name in ("MULTIPLY", "DIVIDE") and c[0] == 1.0) or (name in ("ADD", "SUBTRACT") and c[0] == 0.0):
        return 0
    if (name == "MAXIMUM" and x[0] >= c[0]) or (name == "MINIMUM" and x[1] <= c[0]):
        return 0
    return None


def fold_program(ops, env):
    """The program with every operation whose interval is one number
    replaced by that number, and pass-through operations dropped (env:
    {name: (lo, hi)}). Returns a program whose last operation is its
    result (at least one operation)."""
    ivs = intervals(ops, env)
    ref, kept, kept_ivs = {}, [], []
    for i, op in enumerate(ops):
        lo, hi = ivs[i]
        if hi - lo <= POINT:
            ref[i] = lo
            continue
        args = []
        for a in op[1:-1]:
            if _is_num(a):
                args.append(float(a))
            elif a.startswith("#"):
                args.append(ref[int(a[1:])])
            else:
                e = env[a]
                args.append(e[0] if e[0] == e[1] else a)
        arg_ivs = [(a, a) if _is_num(a) else (kept_ivs[int(a[1:])] if a.startswith("#") else env[a]) for a in args]
        j = _passes_through([op[0]] + args + [op[-1]], arg_ivs)
        if j is not None:
            ref[i] = args[j]
            continue
        ref[i] = f"#{len(kept)}"
        kept.append([op[0]] + args + [op[-1]])
        kept_ivs.append(ivs[i])
    last = ref[len(ops) - 1]
    if _is_num(last):
        return [["ADD", float(last), 0.0, False]]
    if not last.startswith("#"):                     # an input passed through
        return kept + [["MULTIPLY_ADD", last, 1.0, 0.0, False]]
    if int(last[1:]) != len(kept) - 1:
        kept.append(["MULTIPLY_ADD", last, 1.0, 0.0, False])
    return kept


def liquid_bounds(bounds):
    """(lo, hi) of L for input bounds {group input name: (lo, hi)}."""
    return intervals(liquid_program(), {NAMES[k]: v for k, v in bounds.items()})[-1]


def film_free(table, bounds):
    """True when the liquid never exceeds the table's saturation (the
    export's level where the film starts)."""
    return liquid_bounds(bounds)[1] <= table["saturation"]


def row_program(table, film):
    """The table's row program; without the film, folded to L in
    [0, saturation] (its film branch is then constant)."""
    if film:
        return table["row_program"]
    return fold_program(table["row_program"], {"x": (0.0, table["saturation"])})


# ---- the inputs' bounds ---------------------------------------------------------

def _fcurve_bounds(fc, value):
    """The hull of the keys (and Bezier handles) with the current value, or
    None where the curve may leave it (modifiers, linear extrapolation,
    overshooting easings)."""
    if fc.mute:
        return (value, value)
    if len(fc.modifiers) or fc.extrapolation != "CONSTANT" or not len(fc.keyframe_points):
        return None
    ys = [value]
    for k in fc.keyframe_points:
        if k.interpolation not in ("BEZIER", "LINEAR", "CONSTANT"):
            return None
        ys += [k.co[1], k.handle_left[1], k.handle_right[1]] if k.interpolation == "BEZIER" else [k.co[1]]
    return (min(ys), max(ys))


_IMAGE_CACHE = {}


def _image_key(img):
    import bpy
    path = img.filepath_raw
    try:
        mtime = os.path.getmtime(bpy.path.abspath(path)) if path and img.source == "FILE" else None
    except OSError:
        mtime = None
    return (img.as_pointer(), img.name, tuple(img.size), path, mtime, img.source)


def image_bounds(img):
    """(lo, hi) over every colour channel of a data image's pixels (a
    Color output to a float input is a weighted mean of its channels with
    weights summing to 1: inside that range; Linear, Cubic and Closest
    filters mix texels with convex weights). None: a colour-managed,
    tiled, moving or unsaved (being painted) image, or one with no pixels
    (a missing file)."""
    if (img is None or img.source not in ("FILE", "GENERATED") or img.is_dirty
            or img.colorspace_settings.name not in ("Non-Color", "Raw")):
        if img is not None:
            _IMAGE_CACHE.pop(img.as_pointer(), None)
        return None
    # cached for a file's pixels by the file's date; a generated image (a
    # script may set its pixels without marking it) is read every time
    key = _image_key(img) if img.source == "FILE" else None
    hit = _IMAGE_CACHE.get(img.as_pointer())
    if key is not None and hit is not None and hit[0] == key:
        return hit[1]
    w, h = img.size
    n = w * h * img.channels
    if n == 0:
        return None
    try:
        import numpy as np
        px = np.empty(n, dtype=np.float32)
        img.pixels.foreach_get(px)
        px = px.reshape(-1, img.channels)[:, :min(3, img.channels)]
        lo, hi = float(px.min()), float(px.max())
    except ImportError:
        px = list(img.pixels)
        c = img.channels
        vals = [px[i] for i in range(len(px)) if i % c < 3]
        lo, hi = min(vals), max(vals)
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return None
    if key is not None:
        _IMAGE_CACHE[key[0]] = (key, (lo, hi))
    return (lo, hi)


def _link_bounds(sock):
    link = sock.links[0]
    if getattr(link, "is_muted", False):
        return None                                   # the socket's value: the caller's point
    node = link.from_node
    if node.bl_idname == "ShaderNodeTexImage" and link.from_socket.name == "Color" and not node.mute:
        return image_bounds(node.image) or UNKNOWN
    return UNKNOWN


def input_bounds(gn, fcurve_of):
    """({name: (lo, hi)}, {names set by the node's value alone}) for the
    inputs that set L; fcurve_of(name) -> the F-curve keying that input,
    the string "driver" or None."""
    out, fixed = {}, set()
    for name in NAMES:
        s = gn.inputs[name]
        v = float(s.default_value)
        iv = (v, v)
        if s.is_linked:
            iv = _link_bounds(s) or iv
        else:
            fc = fcurve_of(name)
            if fc == "driver":
                iv = UNKNOWN
            elif fc is not None:
                iv = _fcurve_bounds(fc, v) or UNKNOWN
            else:
                fixed.add(name)
        out[name] = iv
    return out, fixed
