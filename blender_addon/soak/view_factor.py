"""The preset's view factor in a Soak Wet group, built in one place for
both kinds of group: the liquid interface's transmission towards the viewer
(the export's view_factor table over the view's cosine and the liquid
amount). A base colour cannot follow the light's angle through the
interface, but it can follow the viewer's.

The view's cosine is Layer Weight's Facing at blend 0.5, 1 - |cos| (both
engines; backfaces included). A varying liquid reads the table (`lookup`:
one Linear lookup, or for exact lookups four Closest reads of the cell's
corners and their bilinear mix: EEVEE Next's Linear lookup fails where a
coordinate is constant over the screen); a constant one gets the table's
row at L as an RGB Curves node over Facing (`curve`, wet_constant)."""

from . import data
from .node_program import EDGE, lerp, lookup as image_lookup


def is_unity(t):
    """True where the table's view factor is 1 throughout (dry tables,
    conductors): the group then builds none."""
    return all(v == 1.0 for row in t["view_factor"] for v in row)


def facing(b, normal):
    """1 - |cos| of the view to `normal` (Layer Weight's Facing)."""
    lw = b.node("ShaderNodeLayerWeight", label="View: 1 - |cos|")
    lw.inputs["Blend"].default_value = 0.5
    b.link(normal, lw.inputs["Normal"])
    return lw.outputs["Facing"]


def lookup(b, t, image, rows, normal):
    """The view factor at the liquid's rows (wet_group._Rows) read from the
    exported image; None where it is 1 throughout."""
    if is_unity(t):
        return None
    n = data.load()["view_columns"]
    f = facing(b, normal)
    if not rows.exact:
        u = b.math("MULTIPLY_ADD", f, -(n - 1) / n, (n - 0.5) / n)
        return image_lookup(b, image, u, rows.v, "Linear").outputs["Color"]
    x = b.math("MULTIPLY_ADD", f, -(n - 1) * EDGE, (n - 1) * EDGE)
    i0 = b.math("FLOOR", x)
    fx = b.math("SUBTRACT", x, i0)
    u0 = b.math("MULTIPLY_ADD", i0, 1.0 / n, 0.5 / n)
    u1 = b.math("ADD", u0, 1.0 / n)

    def row(v):
        a = image_lookup(b, image, u0, v, "Closest").outputs["Color"]
        return lerp(b, a, image_lookup(b, image, u1, v, "Closest").outputs["Color"], fx)
    return lerp(b, row(rows.v0), row(rows.v1), rows.fy)


def curve(b, t, row, normal, curves):
    """The view factor at a constant liquid (wet_constant.Row `row`): the
    table's row at L over Facing as an RGB Curves node (`curves`:
    wet_constant.curves); None where it is 1 throughout."""
    if is_unity(t):
        return None
    n = data.load()["view_columns"]
    xs = [1.0 - i / (n - 1) for i in range(n)]
    ys = [[row.mix(t["view_factor"], 3 * i + c) for i in range(n)] for c in range(3)]
    return curves(b, facing(b, normal), xs, ys)
