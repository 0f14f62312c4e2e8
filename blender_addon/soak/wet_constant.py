"""The Soak Wet group specialised to a constant liquid amount.

When nothing that sets the liquid L varies (Wetness, Wet Map, Puddle Level
and the schedule's inputs unlinked, unkeyed, undriven), L is one number for
the whole material, and every table the group reads is one row of the
core's table at L. Then:
  colour = one RGB Curves node on the dry colour: channel c's curve runs
           through the row's columns (dry albedo a_j, wet albedo), the row
           interpolated linearly at L as the bilinear lookup does;
  view   = one RGB Curves node on Layer Weight's Facing: the view-factor
           row at L over the view's cosine (view_factor.curve);
  params = numbers (Value nodes, which Cycles folds).
Image lookups cost Cycles as much at a constant coordinate as at any other;
the curves are a short table in the shader itself. Only interpolation of
what the core exported happens here; the numbers are the export's.

The colour curve's input is the column coordinate s = column_program(a),
as the lookups', not the dry albedo: Blender samples a curve at 256 points
uniform in its input, and in a the function bends like sqrt(1 - a) near
a = 1 (sampled in a: up to 0.002 off the tables; in s: 2e-4, the bound
tests/blender/test_specialise.py computes from the tables)."""

import math

from . import data
from .node_program import run_program_vector

# the group inputs that set the liquid amount L (wet_group._liquid_schedule)
LIQUID_INPUTS = ("Wetness", "Wet Map", "Puddle Level", "Schedule", "Drying", "Time", "Start Time", "Fill Time")


def _math(op, a, b=0.0, c=0.0):
    """One Math node of Blender's on numbers (its safe division and power)."""
    if op == "ADD":
        return a + b
    if op == "SUBTRACT":
        return a - b
    if op == "MULTIPLY":
        return a * b
    if op == "DIVIDE":
        return a / b if b != 0.0 else 0.0
    if op == "MULTIPLY_ADD":
        return a * b + c
    if op == "MINIMUM":
        return min(a, b)
    if op == "MAXIMUM":
        return max(a, b)
    if op == "SQRT":
        return math.sqrt(a) if a > 0.0 else 0.0
    if op == "POWER":
        if a >= 0.0:
            return a ** b
        return a ** b if float(b).is_integer() else 0.0
    raise data.SoakDataError(f"soak_data.json: node program operation '{op}' is unknown to the add-on")


def run_numbers(ops, env):
    """An exported node program (soak_data.json "layout") on numbers."""
    results = []
    for op in ops:
        args = [a if isinstance(a, (int, float)) else (results[int(a[1:])] if a.startswith("#") else env[a])
                for a in op[1:-1]]
        v = _math(op[0], *[float(x) for x in args])
        results.append(min(max(v, 0.0), 1.0) if op[-1] else v)
    return results[-1]


def liquid(values):
    """L for constant group inputs {name: value}, as _liquid_schedule's
    nodes compute it."""
    p = run_numbers(data.load()["schedule_program"], {"time": values["Time"], "start_time": values["Start Time"],
                                                      "fill_time": values["Fill Time"]})
    p = _math("MULTIPLY_ADD", p * -2.0 + 1.0, values["Drying"], p)
    p = _math("MULTIPLY_ADD", 1.0 - p, 1.0 - values["Schedule"], p)
    level = max(values["Puddle Level"], 1e-3)
    wet_map = min(max(_math("DIVIDE", values["Wet Map"], level), 0.0), 1.0)
    w = min(max(values["Wetness"] * wet_map, 0.0), 1.0)
    return min(max(w * p, 0.0), 1.0)


class Row:
    """A table's rows at liquid L: the bracketing rows and the fraction
    between them (the Linear lookup's texel-space row)."""

    def __init__(self, t, L):
        rows = t["rows_below"] + t["rows_above"] + 1
        y = min(max(run_numbers(t["row_program"], {"x": L}), 0.0), 1.0) * (rows - 1)
        self.r0 = min(int(math.floor(y)), rows - 2)
        self.f = y - self.r0

    def mix(self, table, i):
        """Entry i of a table's rows at L."""
        a, b = table[self.r0][i], table[self.r0 + 1][i]
        return a + (b - a) * self.f


def curves(b, socket, xs, ys_by_channel):
    """An RGB Curves node on `socket`: channel c piecewise linear through
    (xs[i], ys_by_channel[c][i]) (Vector handles), held flat beyond the
    ends as the tables' EXTEND is; its output socket."""
    n = b.node("ShaderNodeRGBCurve")
    m = n.mapping
    m.use_clip = False
    m.extend = "HORIZONTAL"
    order = sorted(range(len(xs)), key=lambda i: xs[i])
    for c in range(3):
        pts = m.curves[c].points
        first, last = order[0], order[-1]
        pts[0].location = (xs[first], ys_by_channel[c][first])
        pts[1].location = (xs[last], ys_by_channel[c][last])
        for i in order[1:-1]:
            pts.new(xs[i], ys_by_channel[c][i])
        for p in pts:
            p.handle_type = "VECTOR"
    m.update()
    b.link(socket, n.inputs["Color"])
    return n.outputs["Color"]


def value(b, x):
    n = b.node("ShaderNodeValue")
    n.outputs[0].default_value = float(x)
    return n.outputs[0]


def colour_value(b, rgb):
    n = b.node("ShaderNodeRGB")
    n.outputs[0].default_value = (float(rgb[0]), float(rgb[1]), float(rgb[2]), 1.0)
    return n.outputs[0]


def wet_colour(b, colour, t, row):
    """The wet colour at L of a dry colour socket: the column program on
    the colour (Vector Math nodes) into one RGB Curves node through the
    row's columns."""
    na = t["columns"]
    ys = [[row.mix(t["albedo"], 3 * j + c) for j in range(na)] for c in range(3)]
    s = run_program_vector(b, t["column_program"], colour)
    return curves(b, s, [j / (na - 1) for j in range(na)], ys)


def param(t, row, pixel):
    """Parameter pixel `pixel` at L: (x, y, z) numbers."""
    return tuple(row.mix(t["params"], 3 * pixel + c) for c in range(3))
