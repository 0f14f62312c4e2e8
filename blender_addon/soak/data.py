"""The data the C core exports for this add-on (soak_data.json, written by
`soak export --target blender`), and the lookup images made from it.

Python only copies the core's pixels into float images; it computes no
physics. Layout: see the file's "layout" entry."""

import json
import os

import bpy

DATA_FILE = os.path.join(os.path.dirname(__file__), "soak_data.json")
FORMAT = "soak-blender"
FORMAT_VERSION = 2

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


def preset_items(_self=None, _context=None):
    return [(m["name"], m["display_name"], m["kind"].replace("_", " ")) for m in load()["materials"]]


def liquid_items(_self=None, _context=None):
    return [(l["name"], l["display_name"], "") for l in load()["liquids"]]


def _image(name, width, height, rows, per_pixel, tag):
    img = bpy.data.images.get(name)
    if img is not None and img.get("soak_tag") == tag and tuple(img.size) == (width, height):
        return img
    if img is not None:
        bpy.data.images.remove(img)
    img = bpy.data.images.new(name, width=width, height=height, alpha=False, float_buffer=True)
    img.colorspace_settings.name = "Non-Color"
    px = []
    for row in rows:  # row 0 is the bottom row of a Blender image
        if len(row) != width * per_pixel:
            raise SoakDataError(f"{name}: row of {len(row)} values, expected {width * per_pixel}")
        for j in range(width):
            px.extend(row[per_pixel * j: per_pixel * j + 3])
            px.append(1.0)
    img.pixels.foreach_set(px)
    img.pack()
    img["soak_tag"] = tag
    img.use_fake_user = False
    return img


def lookup_images(preset, liquid_name):
    """(albedo image, params image) for a preset and liquid."""
    t = table(preset, liquid_name)
    d = load()
    rows = t["rows_below"] + t["rows_above"] + 1
    tag = f"{d['materials_hash']}:{preset}:{liquid_name}"
    alb = _image(f"Soak LUT {preset} {liquid_name}", t["columns"], rows, t["albedo"], 3, tag)
    par = _image(f"Soak Params {preset} {liquid_name}", len(t["params"][0]) // 3, rows, t["params"], 3, tag)
    return alb, par
