"""The Blender add-on's price table (blender_addon/soak/price.json: what the
panel shows beside Quality) from a published benchmark file of
c_core/bench/results/: its tables headed "Cycles overhead" (rows
| Blender | wetness | Draft | Balanced | Exact | ... |, cells "min (median)"),
"Colour error" (| quality | 3.4 | 4.3 | 5.2 |) and "EEVEE colour error"
(| lookups | error |). Copies numbers, computes none.

usage: python3 c_core/bench/blender_price.py RESULTS.md OUT.json"""
import json
import os
import re
import sys

QUALITIES = ("DRAFT", "BALANCED", "EXACT")
TARGETS = {"DRAFT": 1.15, "BALANCED": 1.35, "EXACT": 1.6}


def tables(text):
    """{heading: [rows of cells]} of every markdown table under a ## / ### heading."""
    out, heading = {}, None
    for line in text.splitlines():
        m = re.match(r"#+\s+(.*)", line)
        if m:
            heading = m.group(1).strip()
            continue
        if line.startswith("|") and heading is not None and not re.match(r"\|\s*-", line):
            out.setdefault(heading, []).append([c.strip() for c in line.strip().strip("|").split("|")])
    return out


def find(tabs, prefix):
    for k, v in tabs.items():
        if k.startswith(prefix):
            return v[1:]          # the header row off
    raise SystemExit(f"blender_price.py: no table headed '{prefix}...'")


def pair(cell):
    m = re.match(r"([0-9.]+)\s*\(([0-9.]+)\)", cell)
    if not m:
        raise SystemExit(f"blender_price.py: '{cell}' is not 'min (median)'")
    return [float(m.group(1)), float(m.group(2))]


def build(path):
    text = open(path, encoding="utf-8").read()
    tabs = tables(text)
    over = {}
    for row in find(tabs, "Cycles overhead"):
        version = ".".join(row[0].split(".")[:2])
        over.setdefault(version, {})[row[1]] = {q: pair(c) for q, c in zip(QUALITIES, row[2:5])}
    err = {q: {} for q in QUALITIES}
    rows = find(tabs, "Colour error")
    for row in rows:
        q = row[0].upper()
        for v, c in zip(("3.4", "4.3", "5.2"), row[1:4]):
            err[q][v] = float(c)
    eevee = {row[0].split()[0].lower(): float(row[1]) for row in find(tabs, "EEVEE colour error")}
    return {"benchmark": "c_core/bench/results/" + os.path.basename(path), "targets": TARGETS,
            "cycles_overhead": over, "cycles_colour_error": err, "eevee_colour_error": eevee}


def main(src, out):
    price = build(src)
    tmp = out + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(price, f, indent=1, sort_keys=True)
        f.write("\n")
    os.replace(tmp, out)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2])
