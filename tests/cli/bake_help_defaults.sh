#!/usr/bin/env bash
# Every default that `soak bake rain`, `bake drops`, `bake ripples` and `bake beads` state in
# --help is the code's: for each option whose help says "(default X)" with X
# a value, the bake without the option and the bake with "--option X" write
# the same bytes (every output, 32-bit EXR). The options of one kind are
# checked together (one pair of bakes), and one by one where that pair
# differs, to name the culprit. The help is parsed here, so an
# option added later is checked too; defaults given in words ("every core",
# "above") are listed, not checked, except the few translated below.
. "$(dirname "$0")/lib.bash"

D="$SOAK_TMP/help_defaults"
rm -rf "$D"
mkdir -p "$D"
command -v python3 >/dev/null || { skip "python3 not on PATH" "parsing --help"; finish; }
uv_plane_obj "$D/plane.obj"

python3 - "$SOAK" "$D" >"$D/report" <<'PY'
import filecmp, math, os, re, subprocess, sys

soak, tmp = sys.argv[1], sys.argv[2]
plane = os.path.join(tmp, "plane.obj")
# Small, fast bakes; each option's own value is dropped from these before its check.
BASES = {
    "rain": ["bake", "rain", plane, "--rays", "2", "--duration", "60", "--steps", "2", "--width", "24",
             "--height", "16", "--float", "-o", "{d}/o.exr", "--exposure", "{d}/e.exr", "--water", "{d}/w.exr",
             "--film", "{d}/f.exr"],
    "rain --frames": ["bake", "rain", plane, "--rays", "2", "--duration", "60", "--steps", "2", "--width", "16",
                      "--height", "16", "--float", "--frames", "2-2", "-o", "{d}/o.%04d.exr", "--film",
                      "{d}/f.%04d.exr"],
    "drops": ["bake", "drops", "--width", "128", "--height", "96", "--texel", "0.01", "--duration", "2", "--time",
              "1", "--float", "-o", "{d}/o.exr"],
    "drops --frames": ["bake", "drops", "--width", "32", "--height", "24", "--texel", "0.01", "--duration", "2",
                       "--float", "--frames", "30-30", "-o", "{d}/o.%04d.exr"],
    "ripples": ["bake", "ripples", "--width", "32", "--loop-frames", "4", "--period", "0.4", "--rate", "20",
                "--float", "--frames", "1-1", "-o", "{d}/o.%04d.exr", "--far", "{d}/f.%04d.exr"],
    "beads": ["bake", "beads", "--width", "64", "--height", "48", "--duration", "60", "--float", "-o", "{d}/o.exr"],
}
# Which base checks which options (the sequence options need --frames).
SEQUENCE_ONLY = {"--fps", "--frame-origin", "--frame-time", "--time"}
# Defaults stated in words that name a value.
# The slowest capillary-gravity wave, 2 pi sqrt(sigma / (rho g)), water at 20 C
# (CRC Handbook: sigma 0.0728 N/m, rho 998.2 kg/m^3) and standard gravity, in
# the bake's order of operations so the double is the same.
LAMBDA = 2 * math.pi / math.sqrt(998.2 * 9.80665 / 0.0728)
WORDS = {("rain", "--rain-dir"): "0,1,0",                # "up", and --up defaults to y
         ("ripples", "--wavelength"): repr(LAMBDA),       # the help rounds it to 0.01713
         ("ripples", "--ring-width"): repr(0.5 * LAMBDA),  # "half a wavelength"
         ("beads", "--contact-angle"): "90"}               # "90 without --preset"
# Options that do not apply (refused) or change nothing in the bytes.
NOT_APPLICABLE = {("ripples", "--time"), ("ripples", "--frame-time"), ("ripples", "--frame-origin"),
                  ("drops", "--time"), ("rain", "--time")}  # drops/rain: --time is given in a base or "above"

def options(cmd):
    text = subprocess.run([soak, "bake", cmd, "--help"], capture_output=True, text=True).stdout
    opts, cur = [], None
    for line in text.splitlines():
        m = re.match(r"^  (?:-\w, )?(--[\w-]+)(?: (\S+))?\s{2,}(.*)$", line)
        if m:
            cur = [m.group(1), m.group(2), m.group(3)]
            opts.append(cur)
        elif cur and re.match(r"^\s{6,}\S", line):
            cur[2] += " " + line.strip()
        else:
            cur = None
    return opts

def stated_default(cmd, name, meta, help_text):
    if (cmd, name) in WORDS:
        return WORDS[(cmd, name)]
    m = re.search(r"\(default:? ([^)]*)\)", help_text)
    if not m or meta is None:
        return None
    tok = m.group(1).split()[0].rstrip(",;:")
    if re.fullmatch(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?", tok):
        return tok
    if "|" in meta and tok in meta.split("|"):
        return tok
    if name == "--frame-origin" and tok == "A":  # the first frame of --frames A-B
        return "A"
    return None

def without(args, name):
    out, skip = [], False
    for a in args:
        if skip:
            skip = False
            continue
        if a == name:
            skip = True
            continue
        out.append(a)
    return out

runs = {}
def run(args):
    key = tuple(args)
    if key in runs:
        return runs[key]
    d = os.path.join(tmp, "run%d" % len(runs))
    os.makedirs(d)
    r = subprocess.run([soak] + [a.format(d=d) for a in args], capture_output=True, text=True)
    runs[key] = (d, r.returncode, r.stderr.strip()[:200])
    return runs[key]

def same_outputs(a, b):
    fa, fb = sorted(os.listdir(a)), sorted(os.listdir(b))
    return fa and fa == fb and all(filecmp.cmp(os.path.join(a, f), os.path.join(b, f), shallow=False) for f in fa)

def check(base, items):
    """One bake without any of items' options, one with all at their stated
    defaults; where they differ, each option on its own names the culprit."""
    plain = base
    for name, _ in items:
        plain = without(plain, name)
    given = plain + [a for name, value in items for a in (name, value)]
    (da, ra, ea), (db, rb, eb) = run(plain), run(given)
    if ra == 0 and rb == 0 and same_outputs(da, db):
        return [(name, value, None) for name, value in items]
    if len(items) == 1:
        return [(items[0][0], items[0][1], "exit %d / %d: %s %s" % (ra, rb, ea, eb) if ra or rb else "the outputs differ")]
    return [r for item in items for r in check(base, [item])]

for cmd in ("rain", "drops", "ripples", "beads"):
    groups = {}
    for name, meta, help_text in options(cmd):
        value = stated_default(cmd, name, meta, help_text)
        if value is None or (cmd, name) in NOT_APPLICABLE:
            print("note %s %s: not checked (%s)" % (cmd, name, help_text))
            continue
        key = cmd + " --frames" if name in SEQUENCE_ONLY and cmd + " --frames" in BASES else cmd
        if value == "A":
            value = BASES[key][BASES[key].index("--frames") + 1].split("-")[0]
        # The size alone: with every other default as well it would be the full 1024^2 bake.
        groups.setdefault((key, name) if name in ("--width", "--height") else (key,), []).append((name, value))
    for key, items in groups.items():
        for name, value, why in check(BASES[key[0]], items):
            what = "bake %s: %s default %s (help) is the code's" % (cmd, name, value)
            print("FAIL %s: %s" % (what, why) if why else "ok   %s: same bytes with and without it" % what)
PY
cat "$D/report"
n_ok=$(grep -c '^ok' "$D/report")
n_bad=$(grep -c '^FAIL' "$D/report")
[ "$n_bad" -eq 0 ] && ok "every stated default checked is the code's ($n_ok options)" || bad "$n_bad stated defaults differ from the code's"
[ "$n_ok" -ge 40 ] && ok "at least 40 defaults checked ($n_ok)" || bad "only $n_ok defaults checked: the help parser missed options"
finish
