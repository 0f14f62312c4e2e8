#!/usr/bin/env python3
"""No front end writes its own copy of the pore-filling schedule or of a
Fresnel formula (issue 25: one home per idea).

usage: second_formula.py REPO

The schedule (soak_fill_fraction, c_core/models/src/porous.c) and the
Fresnel reflectance (c_core/models/src/fresnel.c) live in the core; a front
end gets them from `soak export` (the OSL arithmetic, the POV-Ray macros and
the Blender node programs it writes). This test reads the front ends' hand-
written files -- povray/*.inc, blender_addon/soak/**/*.py, osl/*.osl and
osl/*.h -- minus the files scripts/regenerate-exports.sh writes (each has
its own stale test), drops their comments (and Python's docstrings: prose
may state a formula) and fails on code that looks like one of the formulas
as they would be written: (t - t0) / t_fill, * (1 / t_fill), clamp of an
elapsed time, the step select(time - t0, 0, 1); Schlick's pow(1 - c, 5), a
fifth power, (a - b) / (a + b) (normal-incidence F0, the s and p
amplitudes), rs*rs + rp*rp.

Before the scan a self-test copies the front-end files into a temporary
tree, plants one copy of each formula in a hand-written file (SDL, Python
and OSL spellings) and checks that each is reported, and that the same line
is not reported inside a comment or inside a generated file.
"""
import io
import os
import re
import shutil
import sys
import tempfile
import tokenize

PATTERNS = [
    # the pore-filling schedule
    ("schedule: division by the fill time", r"/\s*\(?\s*[\w.\[\]'\"]*(?:t_?fill|fill_?time)"),
    ("schedule: elapsed time scaled", r"\(\s*(?:[\w.]*(?:time|clock)\w*|t)\s*-[^()]*(?:\([^()]*\)[^()]*)?\)\s*[*/]"),
    ("schedule: step at the start time", r"select\s*\(\s*[\w.]*(?:time|clock)\w*\s*-"),
    ("schedule: Math node dividing by the fill time", r"['\"]DIVIDE['\"][^\n]*fill"),
    # Fresnel
    ("Fresnel: Schlick's pow(1 - c, 5)", r"pow\s*\(\s*\(?\s*1(?:\.0*)?\s*-[^,;]*,\s*5(?:\.0*)?\s*\)"),
    ("Fresnel: a fifth power", r"(?:\*\*|\^)\s*5(?:\.0*)?\b"),
    ("Fresnel: Math node POWER 5", r"['\"]POWER['\"][^\n]*,\s*5(?:\.0*)?\s*\)"),
    ("Fresnel: (a - b) / (a + b)", r"\(\s*([^()+\-,/]+?)\s*-\s*([^()+\-,]+?)\s*\)\s*/\s*\(\s*\1\s*\+\s*\2\s*\)"),
    ("Fresnel: rs*rs + rp*rp", r"\b(r_?s\w*)\s*(?:\*\s*\1|\*\*\s*2)\s*\+\s*(r_?p\w*)\s*(?:\*\s*\2|\*\*\s*2)"),
]
COMPILED = [(name, re.compile(p, re.IGNORECASE)) for name, p in PATTERNS]

# A hand-written OSL shader of the self-test's temporary tree (the shipped
# ones are all generated).
CUSTOM_OSL = os.path.join("osl", "custom.osl")

# One planted copy per pattern: (file it goes into, line, pattern it must trip).
PLANTS = [
    ("povray/soak.inc", "#local Soak__X = min(max((Time - T0) * Soak__L_Inv, 0), 1);", 1),
    ("povray/soak.inc", "#local Soak__Y = function { min(max(Time - T0_Fn(x, y, z), 0) / T_Fill, 1) }", 0),
    ("povray/soak.inc", "#local Soak__Z = function { select(Time - T0_Fn(x, y, z), 0, 1) }", 2),
    ("blender_addon/soak/wet_group.py", "p = b.math(\"DIVIDE\", elapsed, gin.outputs[\"Fill Time\"])", 3),
    ("povray/soak.inc", "#local Soak__F = function(C) { F0 + (1 - F0) * pow(1 - C, 5) }", 4),
    ("blender_addon/soak/wet_group.py", "f = f0 + (1.0 - f0) * (1.0 - cos_t) ** 5", 5),
    ("blender_addon/soak/wet_group.py", "f = b.math(\"POWER\", b.math(\"SUBTRACT\", 1.0, cos_t), 5.0)", 6),
    (CUSTOM_OSL, "float rs = (c - eta * ct) / (c + eta * ct);", 7),
    ("povray/soak.inc", "#local Soak__R0 = pow((N - 1) / (N + 1), 2);", 7),
    (CUSTOM_OSL, "float f = 0.5 * (rs * rs + rp * rp);", 8),
    ("blender_addon/soak/wet_group.py", "p = min(max((t - t0) / t_fill, 0.0), 1.0)", 1),
]


def generated_files(repo):
    """The outputs of scripts/regenerate-exports.sh (`-o PATH`)."""
    with open(os.path.join(repo, "scripts", "regenerate-exports.sh"), encoding="utf-8") as f:
        return set(re.findall(r"-o\s+(\S+)", f.read()))


def front_end_files(repo):
    out = []
    for folder, exts, recurse in (("povray", (".inc",), False), ("blender_addon/soak", (".py",), True),
                                  ("osl", (".osl", ".h"), False)):
        top = os.path.join(repo, folder)
        for d, subdirs, names in os.walk(top):
            if not recurse:
                subdirs[:] = []
            subdirs[:] = [s for s in subdirs if s != "__pycache__"]
            out += [os.path.relpath(os.path.join(d, n), repo) for n in sorted(names) if n.endswith(exts)]
    return sorted(out)


def strip_c_comments(text):
    """// and /* */ comments blanked (strings kept, newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if c == '"':
            j = i + 1
            while j < n and text[j] != '"' and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1])
            i = j + 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def strip_py_comments(text):
    """Comments and docstrings (string statements) blanked."""
    lines = text.splitlines(True)
    blank = []
    prev = tokenize.NEWLINE
    try:
        for tok in tokenize.generate_tokens(io.StringIO(text).readline):
            if tok.type == tokenize.COMMENT or (
                    tok.type == tokenize.STRING and prev in (tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT,
                                                             tokenize.NL)):
                blank.append((tok.start, tok.end))
            if tok.type not in (tokenize.COMMENT, tokenize.NL):
                prev = tok.type
    except (tokenize.TokenError, IndentationError):
        pass
    for (r0, c0), (r1, c1) in reversed(blank):
        for r in range(r0, r1 + 1):
            line = lines[r - 1]
            a = c0 if r == r0 else 0
            b = c1 if r == r1 else len(line.rstrip("\n"))
            lines[r - 1] = line[:a] + " " * (b - a) + line[b:]
    return "".join(lines)


def findings(repo):
    gen = generated_files(repo)
    found = []
    for rel in front_end_files(repo):
        if rel in gen:
            continue
        with open(os.path.join(repo, rel), encoding="utf-8") as f:
            text = f.read()
        code = strip_py_comments(text) if rel.endswith(".py") else strip_c_comments(text)
        for lineno, line in enumerate(code.splitlines(), 1):
            for k, (name, rx) in enumerate(COMPILED):
                if rx.search(line):
                    found.append((rel, lineno, k, text.splitlines()[lineno - 1].strip()))
    return found


def plant(repo, tmp, rel, line, comment):
    """A copy of the front ends in tmp with line appended to rel."""
    shutil.rmtree(tmp, ignore_errors=True)
    for f in front_end_files(repo) + ["scripts/regenerate-exports.sh"]:
        os.makedirs(os.path.dirname(os.path.join(tmp, f)), exist_ok=True)
        shutil.copy(os.path.join(repo, f), os.path.join(tmp, f))
    path = os.path.join(tmp, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    if comment:
        line = ("# " if rel.endswith(".py") else "// ") + line
    with open(path, "a", encoding="utf-8") as f:
        f.write("\n" + line + "\n")


def self_test(repo):
    fails = 0
    hit = set()
    gen_target = sorted(set(front_end_files(repo)) & generated_files(repo))[0]
    with tempfile.TemporaryDirectory() as base:
        tmp = os.path.join(base, "repo")
        for rel, line, want in PLANTS:
            plant(repo, tmp, rel, line, comment=False)
            got = [k for r, _, k, text in findings(tmp) if r == rel and text == line.strip()]
            if want not in got:
                print("FAIL self-test: planted %r in %s not reported as %s (got %s)"
                      % (line, rel, PATTERNS[want][0], [PATTERNS[k][0] for k in got]))
                fails += 1
            hit.add(want)
            plant(repo, tmp, rel, line, comment=True)
            if any(r == rel and line.strip() in text for r, _, _, text in findings(tmp)):
                print("FAIL self-test: %r inside a comment of %s was reported" % (line, rel))
                fails += 1
        plant(repo, tmp, gen_target, PLANTS[0][1], comment=False)
        if any(r == gen_target for r, _, _, _ in findings(tmp)):
            print("FAIL self-test: a formula in the generated %s was reported" % gen_target)
            fails += 1
    missing = set(range(len(PATTERNS))) - hit
    for k in sorted(missing):
        print("FAIL self-test: no planted copy exercises %s" % PATTERNS[k][0])
        fails += 1
    if not fails:
        print("ok   self-test: %d planted copies reported (all %d patterns), none in comments or in %s"
              % (len(PLANTS), len(PATTERNS), gen_target))
    return fails


def main():
    repo = os.path.abspath(sys.argv[1])
    fails = self_test(repo)
    files = [f for f in front_end_files(repo) if f not in generated_files(repo)]
    found = findings(repo)
    for rel, lineno, k, text in found:
        print("FAIL %s:%d: %s: %s" % (rel, lineno, PATTERNS[k][0], text))
    print("%d hand-written front-end files (%s), %d copies of a core formula"
          % (len(files), ", ".join(files), len(found)))
    return 1 if fails or found else 0


if __name__ == "__main__":
    sys.exit(main())
