#!/usr/bin/env python3
"""The shaders' parameters as osl/README.md documents them, against oslinfo.

Compiles the four shipped shaders with oslc (osl_check.compile_all), lists
each one's parameters with oslinfo and compares them with the README's
"Parameters" tables: the same names in both, and per parameter the same type
and default (outputs: the type). A parameter added to the generator but not
documented, a documented one that is gone, or a changed default fails.

usage: osl_params.py ROOT TMPDIR
Without oslc/oslinfo on PATH: SKIPPED (exit 77), never a pass.
"""
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from osl_check import compile_all, skip  # noqa: E402

SHADERS = ("soak_wet_surface", "soak_wet_surface_legacy", "soak_wet_sheet", "soak_wetmap")
# oslinfo prints a closure parameter's type as "pointer"
TYPE_ALIASES = {"closure color": "pointer"}


def readme_tables(text):
    """{shader: {parameter: (type, default)}} from the tables after a line naming
    the shaders in backquotes and ending in a colon (the Parameters section)."""
    section = text.split("## Parameters", 1)[1].split("\n## ", 1)[0]
    tables, names = {}, []
    for line in section.splitlines():
        if line.startswith("`") and line.rstrip().endswith(":"):
            names = [n for n in re.findall(r"`([a-z_]+)`", line) if n in SHADERS]
        elif line.startswith("| ") and names and not line.startswith("| parameter"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            for n in names:
                tables.setdefault(n, {})[cells[0]] = (cells[1], cells[2])
    return tables


def oslinfo_params(oso):
    """{parameter: (type, default text)} from oslinfo's listing."""
    r = subprocess.run(["oslinfo", oso], capture_output=True, text=True)
    if r.returncode != 0:
        return None
    out = {}
    for line in r.stdout.splitlines()[1:]:
        m = re.match(r'\s*((?:output\s+)?\w+)\s+(\w+)\s*(.*)$', line)
        if m:
            out[m.group(2)] = (m.group(1), m.group(3).strip())
    return out


def same_default(doc_type, doc, got):
    if doc_type.startswith("output"):
        return True  # an output's initial value is not a default anyone sets
    if got == "nodefault":  # a global (N, u, v): the README names it
        return doc != "" and not re.fullmatch(r"[-0-9.e]+", doc)
    if doc_type == "string":
        return got == '"%s"' % doc
    values = [float(v) for v in got.strip("[] ").split()]
    try:
        want = float(doc)
    except ValueError:
        return False
    return all(abs(v - want) <= 1e-6 for v in values)


def compare(name, doc, got, failures):
    for p in sorted(set(doc) | set(got)):
        if p not in got:
            failures.append(f"{name}: the README documents {p}, oslinfo does not list it")
            continue
        if p not in doc:
            failures.append(f"{name}: oslinfo lists {p} {got[p]}, the README does not document it")
            continue
        dtype = doc[p][0]
        for alias, real in TYPE_ALIASES.items():
            dtype = dtype.replace(alias, real)
        if dtype != got[p][0]:
            failures.append(f"{name}.{p}: README type '{doc[p][0]}', oslinfo '{got[p][0]}'")
        elif not same_default(dtype, doc[p][1], got[p][1]):
            failures.append(f"{name}.{p}: README default '{doc[p][1]}', oslinfo '{got[p][1]}'")
    print(f"{'ok  ' if not failures else 'FAIL'} {name}: {len(got)} parameters listed by oslinfo, "
          f"{len(doc)} documented")


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    root, tmp = sys.argv[1:]
    missing = [t for t in ("oslc", "oslinfo") if not shutil.which(t)]
    if missing:
        skip("%s not on PATH (OSL has no Debian package); the README's parameter tables are not checked"
             % " and ".join(missing))
    os.makedirs(tmp, exist_ok=True)
    failures = []
    compile_all(root, tmp, failures)
    tables = readme_tables(open(os.path.join(root, "osl", "README.md")).read())
    for name in SHADERS:
        got = oslinfo_params(os.path.join(tmp, name + ".oso"))
        if got is None:
            failures.append(f"oslinfo {name} failed")
        elif name not in tables:
            failures.append(f"osl/README.md has no parameter table for {name}")
        else:
            mine = []
            compare(name, tables[name], got, mine)
            failures += mine
    for f in failures:
        print("FAIL " + f)
    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
