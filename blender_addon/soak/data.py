"""The data the C core exports for this add-on (soak_data.json, written by
`soak export --target blender`), and the lookup images made from it.

Python only copies the core's pixels into float images; it computes no
physics. Layout: see the file's "layout" entry."""

import json
import os

import bpy

DATA_FILE = os.path.join(os.path.dirname(__file__), "soak_data.json")
FORMAT = "soak-blender"
FORMAT_VERSION = 4

_cache = {}


class SoakDataError(RuntimeError):
    pass


def load(path=DATA_FILE):
    if path in _cache:
        return _cache[path]
    try:
        with open(path, "r", encoding="utf-8") as f:
            d = json.load(f)
    except (OSError, ValueError) as e:
        raise SoakDataError(f"{path}: cannot read the Soak data ({e})") from e
    if d.get("format") != FORMAT or d.get("format_version") != FORMAT_VERSION:
        raise SoakDataError(f"{path}: not a {FORMAT} v{FORMAT_VERSION} file")
    _cache[path] = d
    return d


def material(name):
    for m in load()["materials"]:
        if m["name"] == name:
            return m
    raise SoakDataError(f"unknown Soak preset '{name}'")


def liquid(name):
    for l in load()["liquids"]:
        if l["name"] == name:
            return l
    raise SoakDataError(f"unknown Soak liquid '{name}'")


def table(preset, liquid_name):
    m = material(preset)
    try:
        return m["liquids"][liquid_name]
    except KeyError:
        raise SoakDataError(f"preset '{preset}' has no table for liquid '{liquid_name}'") from None


def normal_reflectance(ior):
    """Fresnel's normal-incidence reflectance of a dielectric of index ior,
    read from the core's table (soak_data.json "normal_reflectance", linear
    between its indices; clamped to its range, 1 to 3)."""
    t = load()["normal_reflectance"]
    values = t["values"]
    x = (ior - t["ior_first"]) / t["ior_step"]
    x = min(max(x, 0.0), len(values) - 1.0)
    i = min(int(x), len(values) - 2)
    return values[i] + (values[i + 1] - values[i]) * (x - i)


def preset_items(_self=None, _context=None):
    return [(m["name"], m["display_name"], m["kind"].replace("_", " ")) for m in load()["materials"]]


def liquid_items(_self=None, _context=None):
    return [(l["name"], l["display_name"], "") for l in load()["liquids"]]


def _image(name, width, height, pixels, tag, alpha=False):
    """A packed float image of RGB(A) pixels (row 0 at the bottom, as
    Blender stores images); reused when its tag and size match."""
    img = bpy.data.images.get(name)
    if img is not None and img.get("soak_tag") == tag and tuple(img.size) == (width, height):
        return img
    if img is not None:
        bpy.data.images.remove(img)
    img = bpy.data.images.new(name, width=width, height=height, alpha=alpha, float_buffer=True)
    img.colorspace_settings.name = "Non-Color"
    if alpha:
        img.alpha_mode = "CHANNEL_PACKED"      # four data channels, never premultiplied
    img.pixels.foreach_set(pixels)
    img.pack()
    img["soak_tag"] = tag
    img.use_fake_user = False
    return img


def _rgb_rows(name, rows, width, per_pixel):
    for row in rows:
        if len(row) != width * per_pixel:
            raise SoakDataError(f"{name}: row of {len(row)} values, expected {width * per_pixel}")
    return [[row[per_pixel * j: per_pixel * j + 3] for j in range(width)] for row in rows]


class LookupImages:
    """The images a group reads for one preset and liquid:
    params  the per-row parameters (RGB pixels as exported);
    view    the preset's view factor per row (columns: the view cosines);
    linear  per channel c, the albedo table with channel c's function in
            channel c and zeros in the others (Linear lookups, summed), and
            in alpha params pixel 3's channel c of the row (the same in every
            column): the three colour reads also give the base specular
            factor, the mirror area and the roughness ratio, so no
            parameter read is needed (one image lookup fewer per point);
    cells   per channel c, one texel per table cell holding its corners
            (f01, f10, f11) in RGB and f00 in alpha (f01 the next column,
            f10 the next row; EEVEE Next keeps alpha within [0, 1], as the
            table values are), read once with Closest and summed with the
            bilinear weights: a convex sum, so a half-precision GPU copy errs
            by at most 2^-11 of the value (exact lookups)."""

    def __init__(self, params, view, linear, cells):
        self.params, self.view, self.linear, self.cells = params, view, linear, cells


def lookup_images(preset, liquid_name, exact=False):
    t = table(preset, liquid_name)
    d = load()
    rows = t["rows_below"] + t["rows_above"] + 1
    na = t["columns"]
    tag = f"{d['materials_hash']}:{preset}:{liquid_name}"
    base = f"{preset} {liquid_name}"
    npar = len(t["params"][0]) // 3
    par = _image(f"Soak Params {base}", npar, rows,
                 [v for row in _rgb_rows("params", t["params"], npar, 3) for p in row for v in (*p, 1.0)], tag)
    nv = d["view_columns"]
    view = _image(f"Soak View {base}", nv, rows,
                  [v for row in _rgb_rows("view_factor", t["view_factor"], nv, 3) for p in row for v in (*p, 1.0)], tag)
    alb = _rgb_rows("albedo", t["albedo"], na, 3)
    linear, cells = [], []
    shared = [row[9:12] for row in t["params"]]      # params pixel 3, one value per row
    for c in range(3):
        if not exact:
            px = [v for row, sh in zip(alb, shared) for p in row
                  for v in [p[c] if k == c else 0.0 for k in range(3)] + [sh[c]]]
            linear.append(_image(f"Soak LUT {base} {'RGB'[c]}", na, rows, px, tag + ":p3", alpha=True))
            continue
        px = []
        for r in range(rows - 1):
            for j in range(na - 1):
                f00, f01, f10, f11 = alb[r][j][c], alb[r][j + 1][c], alb[r + 1][j][c], alb[r + 1][j + 1][c]
                px += [f01, f10, f11, f00]   # corners: bilinear weights make a convex sum
        cells.append(_image(f"Soak Cells {base} {'RGB'[c]}", na - 1, rows - 1, px, tag, alpha=True))
    return LookupImages(par, view, linear, cells)
