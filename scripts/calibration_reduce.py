#!/usr/bin/python3
"""Reduce the two public soil-moisture reflectance data sets to the RGB numbers
Soak's calibration uses (c_core/data/measured/, described in its README.md).

usage: scripts/calibration_reduce.py RIESE_CSV PROSAIL_SOIL_TXT OUT_DIR

RIESE_CSV: soilmoisture_dataset.csv of felixriese/hyperspectral-soilmoisture-dataset
PROSAIL_SOIL_TXT: prosail/soil_reflectance.txt of jgomezdans/prosail
Band integration: simple averages of the reflectance over R 600-700 nm,
G 500-600 nm, B 400-500 nm (Riese: 454-500 nm, its first band is 454 nm),
every band sample weighted equally. Only the reduced numbers are committed."""
import csv
import math
import os
import sys

import numpy as np

BANDS = {"r": (600.0, 700.0), "g": (500.0, 600.0), "b": (400.0, 500.0)}
LAT, LON = 49.01, 8.40  # Karlsruhe (the lysimeter campaign's site)


def band_mean(wl, spectra, lo, hi):
    m = (wl >= lo) & (wl <= hi)
    return spectra[..., m].mean(axis=-1)


def sun_zenith_deg(stamp):
    """NOAA's low-accuracy solar position (about 0.5 deg); stamp in CEST = UTC+2."""
    day = int(stamp[8:10]) + sum((31, 28, 31, 30)[: int(stamp[5:7]) - 1])
    hour = int(stamp[11:13]) + int(stamp[14:16]) / 60.0 + int(stamp[17:19]) / 3600.0 - 2.0
    g = 2.0 * math.pi / 365.0 * (day - 1 + (hour - 12.0) / 24.0)
    eqt = 229.18 * (0.000075 + 0.001868 * math.cos(g) - 0.032077 * math.sin(g) - 0.014615 * math.cos(2 * g)
                    - 0.040849 * math.sin(2 * g))
    decl = (0.006918 - 0.399912 * math.cos(g) + 0.070257 * math.sin(g) - 0.006758 * math.cos(2 * g)
            + 0.000907 * math.sin(2 * g) - 0.002697 * math.cos(3 * g) + 0.00148 * math.sin(3 * g))
    ha = math.radians((hour * 60.0 + eqt + 4.0 * LON) / 4.0 - 180.0)
    lat = math.radians(LAT)
    c = math.sin(lat) * math.sin(decl) + math.cos(lat) * math.cos(decl) * math.cos(ha)
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def reduce_riese(path, out):
    rows = list(csv.reader(open(path, newline="")))
    head = rows[0]
    wl = np.array([float(h) for h in head[4:]])
    moisture = np.array([float(r[2]) for r in rows[1:]])
    spectra = np.array([[float(v) for v in r[4:]] for r in rows[1:]])
    zen = np.array([sun_zenith_deg(r[1]) for r in rows[1:]])
    rgb = {k: band_mean(wl, spectra, max(lo, wl[0]), hi) for k, (lo, hi) in BANDS.items()}
    with open(out + ".tmp", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["moisture_lo_pct", "moisture_hi_pct", "moisture_mean_pct", "n", "r", "g", "b", "r_sd", "g_sd",
                    "b_sd", "sun_zenith_mean_deg"])
        for lo in range(int(moisture.min()), int(moisture.max()) + 1):
            m = (moisture >= lo) & (moisture < lo + 1)
            if m.sum() < 3:
                continue
            w.writerow([lo, lo + 1, "%.3f" % moisture[m].mean(), int(m.sum())]
                       + ["%.5f" % rgb[k][m].mean() for k in "rgb"]
                       + ["%.5f" % rgb[k][m].std(ddof=1) for k in "rgb"] + ["%.1f" % zen[m].mean()])
    os.replace(out + ".tmp", out)


def reduce_prosail(path, out):
    d = np.loadtxt(path)
    wl = np.arange(400.0, 400.0 + len(d))
    with open(out + ".tmp", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["spectrum", "r", "g", "b"])
        for name, col in (("dry", 0), ("wet", 1)):
            w.writerow([name] + ["%.5f" % band_mean(wl, d[:, col], *BANDS[k]) for k in "rgb"])
    os.replace(out + ".tmp", out)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    reduce_riese(sys.argv[1], os.path.join(sys.argv[3], "riese2018_rgb.csv"))
    reduce_prosail(sys.argv[2], os.path.join(sys.argv[3], "prosail_soil_rgb.csv"))


if __name__ == "__main__":
    main()
