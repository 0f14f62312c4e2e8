#!/usr/bin/python3
"""Plots of docs/calibration.md: per porous preset, the chain's wet/dry ratio
(green channel) against wetness, under uniform diffuse light and under the
measurement's sun, over the measured points (c_core/data/measured/, the
"measured" groups of c_core/data/materials.json). Every model number comes
from `soak albedo` (the core); this script only plots.

usage: scripts/calibration_plots.py SOAK OUT_DIR   (writes OUT_DIR/calib_*.png)"""
import csv
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
SUN_DEFAULT = 35.0  # the sun of the plots for presets without a measurement (docs/calibration.md)
SOIL_POROSITY = 0.485  # Clapp & Hornberger 1978, silt loam (the Riese et al. soil, docs/calibration.md)


def albedo(soak, material, wetness, sun=None, grey=None):
    cmd = [soak, "albedo", "--material", material, "--wetness", "%.6f" % wetness]
    if sun is not None:
        cmd += ["--sun-zenith", "%.3f" % sun]
    if grey is not None:
        cmd += ["--base-colour", "%.6f" % grey]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    vals = {}
    for line in out.splitlines():
        for key in ("dry albedo", "wet albedo total", "wet albedo", "sun albedo total", "sun wet albedo"):
            if line.startswith(key + " ") and not line[len(key):].split()[0][0].isalpha():
                vals.setdefault(key, [float(x) for x in line[len(key):].split()[:3]])
                break
    return vals


def ratios(soak, material, wetness, sun, grey):
    """wet/dry (green) for one state: {(light, total): ratio}, light 'diffuse' or 'sun'."""
    v = albedo(soak, material, wetness, sun, grey)
    dry = v["dry albedo"][1]
    return {("diffuse", True): v["wet albedo total"][1] / dry, ("diffuse", False): v["wet albedo"][1] / dry,
            ("sun", True): v["sun albedo total"][1] / dry, ("sun", False): v["sun wet albedo"][1] / dry}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    soak, out = sys.argv[1], sys.argv[2]
    data = json.load(open(os.path.join(ROOT, "c_core/data/materials.json")))
    riese = list(csv.DictReader(open(os.path.join(ROOT, "c_core/data/measured/riese2018_rgb.csv"))))
    porous = [m for m in data["materials"] if m["kind"] in ("porous_dielectric", "thin_sheet")]
    for m in porous:
        name, phi = m["name"], m["porosity"]["alpha"]
        meas = m.get("measured")
        sun = meas["sun_zenith_deg"] if meas else SUN_DEFAULT
        grey = meas["dry_albedo"] if meas else None
        ws = sorted(set([i / 20.0 for i in range(21)] + [phi * i / 8.0 for i in range(1, 8)] + [phi]))
        curve = [ratios(soak, name, w, sun, grey) for w in ws]
        fig, ax = plt.subplots(figsize=(5.5, 3.6), dpi=100)
        for total, style in ((True, "-"), (False, "--")):
            what = "total" if total else "diffuse part (no mirror)"
            ax.plot(ws, [c[("diffuse", total)] for c in curve], style, color="0.55",
                    label="uniform diffuse light, %s" % what)
            ax.plot(ws, [c[("sun", total)] for c in curve], style, color="C0",
                    label="sun at %.0f deg, %s" % (sun, what))
        if meas:
            ax.errorbar([meas["wetness"]], [meas["wet_dry_ratio"]], yerr=[meas["spread"]], fmt="o", color="C3",
                        capsize=3, label="measured (field albedo, sun)")
        if name == "sand":
            # Riese & Keller 2018 drying curve, relative to its driest bin,
            # mapped by pore fill = moisture / soil porosity onto sand's wetness.
            d0 = riese[0]
            w0 = phi * float(d0["moisture_mean_pct"]) / 100.0 / SOIL_POROSITY
            m0 = ratios(soak, name, w0, float(d0["sun_zenith_mean_deg"]), 0.26)[("sun", False)]
            xs, ys, es, mod = [], [], [], []
            for r in riese:
                w = min(1.0, phi * float(r["moisture_mean_pct"]) / 100.0 / SOIL_POROSITY)
                g0 = float(d0["g"])
                xs.append(w)
                ys.append(float(r["g"]) / g0)
                es.append(float(r["g_sd"]) / g0)
                mod.append(ratios(soak, name, w, float(r["sun_zenith_mean_deg"]), 0.26)[("sun", False)] / m0)
            ax.errorbar(xs, ys, yerr=es, fmt="s", ms=3, color="C2", capsize=2,
                        label="Riese & Keller 2018, relative to driest bin")
            ax.plot(xs, mod, "x", color="C2", label="model, same light, relative to driest bin")
        ax.axvline(phi, color="0.8", lw=0.8)
        ax.set_xlabel("wetness w (liquid volume fraction; pores full at w = porosity %.3f)" % phi, fontsize=7)
        ax.set_ylabel("wet / dry (green)")
        ax.set_title("%s: wet/dry ratio against wetness" % name, fontsize=9)
        ax.set_xlim(0, 1)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=5.5, loc="best")
        fig.tight_layout()
        path = os.path.join(out, "calib_%s.png" % name)
        fig.savefig(path + ".tmp.png")
        os.replace(path + ".tmp.png", path)
        plt.close(fig)
        print(path)


if __name__ == "__main__":
    main()
