#!/bin/bash
# soak measure: output format, agreement with the Lekner-Dorf film albedo
# (computed here with awk by midpoint quadrature of the Fresnel equations),
# determinism across thread counts, and argument errors (exit 2, argument named).
set -u
: "${SOAK:?SOAK must point at the soak binary}"
mkdir -p "$SOAK_TMP"
fail=0
err="$SOAK_TMP/measure_err.txt"

# ---- format and value ------------------------------------------------------
out=$("$SOAK" measure --config film --base-albedo 0.5 --ior 1.33 --incidence normal --paths 200000 2>"$err")
rc=$?
if [ $rc -ne 0 ]; then echo "FAIL film run exited $rc: $(cat "$err")"; fail=1; fi
last=$(printf '%s\n' "$out" | tail -n 1)
re='^([0-9]+\.[0-9]+) ± ([0-9]+\.[0-9]+)$'
if [[ "$last" =~ $re ]]; then
    value=${BASH_REMATCH[1]}
    sigma=${BASH_REMATCH[2]}
    echo "ok   last line parses: value $value, stderr $sigma"
    # Lekner & Dorf: R = r0 + (1-r0) A (1-ri)/(1-A ri), ri = 2 int R_int(mu) mu dmu.
    verdict=$(awk -v v="$value" -v s="$sigma" 'BEGIN {
        n = 1.33; A = 0.5; N = 200000; ri = 0;
        for (k = 0; k < N; ++k) {
            mu = (k + 0.5) / N; st2 = n * n * (1 - mu * mu);
            if (st2 >= 1) R = 1;
            else { ct = sqrt(1 - st2);
                   rs = (n * mu - ct) / (n * mu + ct); rp = (mu - n * ct) / (mu + n * ct);
                   R = 0.5 * (rs * rs + rp * rp); }
            ri += 2 * R * mu / N;
        }
        r0 = ((n - 1) / (n + 1)) ^ 2;
        ref = r0 + (1 - r0) * A * (1 - ri) / (1 - A * ri);
        d = v - ref; if (d < 0) d = -d;
        printf "%s ref %.6f diff %.6f", (d <= 3 * s + 1e-5 && s > 0 ? "ok" : "FAIL"), ref, d }')
    echo "${verdict%% *}   film value vs Lekner-Dorf: ${verdict#* }"
    case "$verdict" in FAIL*) fail=1 ;; esac
else
    echo "FAIL last line does not parse as 'value ± err': '$last'"
    fail=1
fi

# ---- determinism -------------------------------------------------------------
a=$("$SOAK" measure --config slab --tau 1 --albedo 0.9 --g 0.5 --ior 1.4 --paths 20000 --seed 3 --threads 1 2>/dev/null | tail -n 1)
b=$("$SOAK" measure --config slab --tau 1 --albedo 0.9 --g 0.5 --ior 1.4 --paths 20000 --seed 3 --threads 2 2>/dev/null | tail -n 1)
if [ -n "$a" ] && [ "$a" = "$b" ]; then echo "ok   same seed, 1 and 2 threads: $a"; else echo "FAIL thread-count dependence: '$a' vs '$b'"; fail=1; fi
t=$("$SOAK" measure --config slab --tau 2 --albedo 1 --quantity T --paths 20000 2>/dev/null | tail -n 1)
if [[ "$t" =~ $re ]]; then echo "ok   slab transmittance: $t"; else echo "FAIL slab T output '$t'"; fail=1; fi

# ---- help ------------------------------------------------------------------------
if "$SOAK" measure --help | grep -q "soak measure --config film"; then echo "ok   --help has an example"; else echo "FAIL --help"; fail=1; fi

# ---- bad arguments: exit 2 and the message names the argument -------------------
expect_usage() { # name-to-find args...
    local name=$1; shift
    "$SOAK" measure "$@" >/dev/null 2>"$err"
    local rc=$?
    if [ $rc -eq 2 ] && grep -q -- "$name" "$err"; then
        echo "ok   exit 2 naming $name: $*"
    else
        echo "FAIL '$*': exit $rc, stderr: $(cat "$err")"
        fail=1
    fi
}
expect_usage --config --config foam --albedo 0.5
expect_usage --config --albedo 0.5
expect_usage --albedo --config halfspace --albedo nan
expect_usage --albedo --config halfspace --albedo 1.5
expect_usage --albedo --config halfspace
expect_usage --tau --config slab --albedo 0.5 --tau -1
expect_usage --tau --config slab --albedo 0.5 --tau 0
expect_usage --tau --config slab --albedo 0.5
expect_usage --base-albedo --config film
expect_usage --ior --config film --base-albedo 0.5 --ior NaN
expect_usage --paths --config film --base-albedo 0.5 --paths
expect_usage --paths --config film --base-albedo 0.5 --paths 0
expect_usage --seed --config film --base-albedo 0.5 --seed
expect_usage --incidence --config film --base-albedo 0.5 --incidence sideways
expect_usage --incidence --config film --base-albedo 0.5 --incidence 90
expect_usage --quantity --config halfspace --albedo 0.5 --quantity T
expect_usage --g1 --config halfspace --albedo 0.5 --g1 0.5
expect_usage --g --config halfspace --albedo 0.5 --g 1
expect_usage --threads --config film --base-albedo 0.5 --threads 0
expect_usage --bogus --config film --base-albedo 0.5 --bogus

exit $fail
