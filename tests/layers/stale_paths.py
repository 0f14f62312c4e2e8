#!/usr/bin/env python3
"""Every repository path a tracked text file names must exist.

usage: stale_paths.py REPO

Scans the files git tracks (sources, comments, READMEs, generated headers
and the preset data; not binary files, not the fuzz corpora, which hold
mutated bytes on purpose, nor this script, whose self-test plants stale
paths) for words that start with a top-level folder of
the project (c_core/, tests/, povray/, ...) and checks that each names a
file or folder of the working tree. A word followed by a pattern character
(`*`, `<`, `{`, `$`, `%`) or ending in `_`/`-`/`.` is a pattern or a
prefix (e.g. `gallery_*.png`) and counts when some path starts with it.
Paths under out/, build folders and the system's /tmp are outputs, not
references, and are not checked.

Markdown files are also checked for their relative links and pictures,
`[text](target)` and `![alt](target)`, resolved against the file's folder
(web addresses and anchors are not checked).

Before the scan, a self-test plants stale paths in a line of text and checks
that they are reported, so the test is known to be able to fail.
"""
import bisect
import glob
import os
import re
import subprocess
import sys

TOP = ("c_core", "tests", "povray", "blender_addon", "osl", "scripts", "docs", "scenes", "farm")
WORD = re.compile(r"(?<![A-Za-z0-9_./~-])((?:%s)/[A-Za-z0-9_./-]*)(.?)" % "|".join(TOP))
SKIP_DIRS = ("tests/fuzz/corpus", "tests/fuzz/corpora", "tests/fuzz/crashes")
BINARY_EXT = (".png", ".exr", ".jpg", ".jpeg", ".tif", ".tiff", ".hdr", ".bin", ".ply", ".stl", ".vdb", ".df3",
              ".blend", ".zip", ".gz", ".xwd")
PATTERN_NEXT = set("*<{$%")
# Names a file writes or a user chooses (outputs), named in prose on purpose.
OUTPUT_HINTS = ("/out/", "out/", "results/YYYY")


def tracked(repo):
    out = subprocess.run(["git", "-C", repo, "ls-files", "-z"], capture_output=True, check=True).stdout
    return [p for p in out.decode().split("\0") if p]


def scan_text(text, exists, prefix_exists):
    stale = []
    for lineno, line in enumerate(text.splitlines(), 1):
        for m in WORD.finditer(line):
            word, nxt = m.group(1).rstrip("."), m.group(2)
            if any(h in word for h in OUTPUT_HINTS):
                continue
            if nxt in PATTERN_NEXT or word.endswith(("_", "-")):
                if not prefix_exists(word):
                    stale.append((lineno, word))
                continue
            word = word.rstrip("/")
            if not exists(word):
                stale.append((lineno, word))
    return stale


MD_LINK = re.compile(r"\]\(([^)\s]+)\)")


def scan_markdown(path, text, exists):
    """Relative link targets of a markdown file that do not exist."""
    stale = []
    for lineno, line in enumerate(text.splitlines(), 1):
        for m in MD_LINK.finditer(line):
            target = m.group(1).split("#")[0]
            if not target or re.match(r"^[a-z]+:", target) or target.startswith("/"):
                continue
            resolved = os.path.normpath(os.path.join(os.path.dirname(path), target))
            if not exists(resolved):
                stale.append((lineno, resolved))
    return stale


def main():
    repo = os.path.abspath(sys.argv[1])
    files = tracked(repo)
    tree = set(files)
    for f in files:
        d = os.path.dirname(f)
        while d:
            tree.add(d)
            d = os.path.dirname(d)

    def exists(p):
        return p in tree or os.path.exists(os.path.join(repo, p))

    ordered = sorted(tree)

    def prefix_exists(p):
        i = bisect.bisect_left(ordered, p)
        return (i < len(ordered) and ordered[i].startswith(p)) or bool(glob.glob(os.path.join(repo, p) + "*"))

    planted = scan_text("see c_core/include/soak/nothing_here.h, c_core/render/src/render.c and docs/nope_*.png\n",
                        exists, prefix_exists)
    want = [(1, "c_core/include/soak/nothing_here.h"), (1, "docs/nope_")]
    if planted != want:
        print("FAIL self-test: planted stale paths %s reported as %s" % (want, planted))
        return 1
    planted_md = scan_markdown("docs/x.md", "![a](images/nope.png) [b](../README.md) [c](https://x.org/y)\n", exists)
    if planted_md != [(1, "docs/images/nope.png")]:
        print("FAIL self-test: planted stale markdown link reported as %s" % planted_md)
        return 1
    print("ok   self-test: planted stale paths are reported")

    n_files = n_refs = 0
    stale = []
    for f in files:
        if f.startswith(SKIP_DIRS) or f.lower().endswith(BINARY_EXT) or f == "tests/layers/stale_paths.py":
            continue
        try:
            with open(os.path.join(repo, f), encoding="utf-8") as fh:
                text = fh.read()
        except (UnicodeDecodeError, FileNotFoundError, IsADirectoryError):
            continue
        n_files += 1
        n_refs += len(WORD.findall(text))
        stale += [(f, ln, w) for ln, w in scan_text(text, exists, prefix_exists)]
        if f.endswith(".md"):
            stale += [(f, ln, w) for ln, w in scan_markdown(f, text, exists)]
    for f, ln, w in stale:
        print("FAIL %s:%d names %s, which does not exist" % (f, ln, w))
    print("%d files, %d path references, %d stale" % (n_files, n_refs, len(stale)))
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
