"""What each Quality costs, for the panel: the Cycles render time over the
dry material's and the worst colour error against the core, for the
material as it is wired (a constant or a varying wetness), and EEVEE's
colour error. The numbers are the published benchmark's and tests'
(price.json, copied from the dated file it names in
c_core/bench/results/; tests/blender/test_price_table.py keeps the two
equal); nothing is measured here."""

import json
import os

import bpy

from . import compat, data, material_tree, specialise

PRICE_FILE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "price.json")
_cache = {}


def load(path=PRICE_FILE):
    if path not in _cache:
        try:
            with open(path, encoding="utf-8") as f:
                _cache[path] = json.load(f)
        except (OSError, ValueError) as e:
            raise data.SoakDataError(f"{path}: {e}") from None
    return _cache[path]


def measured_version(version=None):
    """The benchmarked Blender nearest the running one (3.x: 3.4, 4.x: 4.3,
    5.x and later: 5.2)."""
    major = (version or bpy.app.version)[0]
    return "3.4" if major <= 3 else "4.3" if major == 4 else "5.2"


def wiring(mat):
    """"constant" when the material's wetness is one number (its group is
    built for it, or, before Make Wet, the Constant source), else "varying"."""
    gn = material_tree.find_group_node(mat.node_tree) if mat.node_tree is not None else None
    if gn is not None:
        return "constant" if specialise.is_specialised(gn) else "varying"
    return "constant" if mat.soak.wetness_source == "CONSTANT" else "varying"


def price(quality, wired, exact=False, version=None):
    """(overhead min, overhead median, Cycles colour error, EEVEE's own
    colour error on top of it, target) for a quality, a wiring and this
    Blender; exact: the tables read exactly (EEVEE's error depends on it)."""
    p = load()
    v = measured_version(version)
    lo, med = p["cycles_overhead"][v][wired][quality]
    eevee = p["eevee_colour_error"]["exact" if exact or quality == "EXACT" else "linear"]
    return lo, med, p["cycles_colour_error"][quality][v], eevee, p["targets"][quality]


def lines(mat):
    """The panel's lines under Quality: this quality's price for this
    material as it is wired."""
    s = mat.soak
    wired = wiring(mat)
    lo, med, err, eevee, target = price(s.quality, wired, s.exact_lookups or compat.exact_lookups_required())
    return (f"Cycles {measured_version()}, {wired} wetness: {lo:.2f}x dry (median {med:.2f}x)",
            f"Colour error {err:.4f} (EEVEE adds up to {eevee:.4f})")
