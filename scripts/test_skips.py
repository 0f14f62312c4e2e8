#!/usr/bin/env python3
"""After a ctest run: list every skipped test and skipped check with its reason,
and fail when

  - a test skipped (wholly or in part) for want of a tool that the README's
    set-up installs (povray, blender): CI must never pass without them;
  - in a CI run (CI=true in the environment), a test skipped for want of an
    OSL tool (oslc, oslinfo, testshade, testrender): OSL has no Debian
    package, so CI's set-up (.ci/run) provides them; on a user's machine
    without OSL those tests skip with their reason and this does not fail;
  - a test exited 77 without printing "SKIPPED: <reason>".

Tests registered without SKIP_RETURN_CODE 77 are listed (a test that never
skips, e.g. one that fails when povray is missing, needs none: exit 77 then
counts as a failure, never as a pass).

usage: test_skips.py BUILD_DIR JUNIT_XML   (ctest --output-junit JUNIT_XML)
"""
import json
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

INSTALLED_TOOLS = ("povray", "blender")
CI_TOOLS = ("oslc", "oslinfo", "testshade", "testrender")  # provided by .ci/run, not by Debian
MISSING = re.compile(r"not on PATH|not found|not installed|missing|unavailable", re.I)


def skip_reasons(text):
    return [l[len("SKIPPED:"):].strip() for l in (text or "").splitlines() if l.startswith("SKIPPED:")]


def in_ci():
    return os.environ.get("CI", "").strip().lower() in ("true", "1", "yes")


def for_installed_tool(reason, tools=INSTALLED_TOOLS):
    words = set(re.findall(r"[a-z0-9_]+", reason.lower()))
    return any(t in words for t in tools) and MISSING.search(reason)


def registered_without_skip_code(build):
    out = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, capture_output=True, text=True, check=True)
    bad = []
    for t in json.loads(out.stdout)["tests"]:
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        if props.get("SKIP_RETURN_CODE") != 77:
            bad.append(t["name"])
    return bad


def main(build, junit):
    errors = []
    skipped, partial = [], []
    ci = in_ci()
    for case in ET.parse(junit).getroot().iter("testcase"):
        name = case.get("name")
        reasons = skip_reasons(case.findtext("system-out"))
        if case.find("skipped") is not None and case.get("status") == "notrun":
            msg = case.find("skipped").get("message", "")
            if "SKIP_RETURN_CODE" not in msg:
                continue  # disabled or not built: ctest already reports it
            skipped.append((name, reasons))
            if not reasons:
                errors.append(f"{name} exited 77 without printing 'SKIPPED: <reason>'")
        elif reasons:
            partial.append((name, reasons))
        for r in reasons:
            if for_installed_tool(r):
                errors.append(f"{name} skipped for a tool the set-up installs: {r}")
            elif ci and for_installed_tool(r, CI_TOOLS):
                errors.append(f"{name} skipped in CI (CI=true) for an OSL tool that .ci/run provides: {r}")
    unregistered = registered_without_skip_code(build)

    print(f"Skipped tests: {len(skipped)}")
    for name, reasons in skipped:
        print(f"  {name}: {'; '.join(reasons) or '(no reason printed)'}")
    if partial:
        print(f"Tests that ran with some checks skipped: {len(partial)}")
        for name, reasons in partial:
            print(f"  {name}: {'; '.join(reasons)}")
    if unregistered:
        print(f"Tests that cannot report a skip (no SKIP_RETURN_CODE 77; exit 77 fails them): {', '.join(unregistered)}")
    for e in errors:
        print(f"ERROR {e}")
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
