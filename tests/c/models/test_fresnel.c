/* Fresnel: analytic values, the closed-form hemispherical average of a
 * dielectric, identities (reciprocity, 1 - R_int = (1 - R_ext)/n^2), hard
 * cases (grazing, critical angle +-eps, equal indices) and a random sweep. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "testutil.h"
#include "soak/fresnel.h"

/* Closed form of 2 int_0^1 R(mu) mu dmu for a dielectric with n > 1 and
 * unpolarised light (Walsh 1926; as tabulated e.g. by Egan & Hilgeman,
 * Optical Properties of Inhomogeneous Materials, 1979). */
static double avg_closed_form(double n)
{
    double n2 = n * n, n4 = n2 * n2;
    return 0.5 + (n - 1) * (3 * n + 1) / (6 * (n + 1) * (n + 1)) +
           n2 * (n2 - 1) * (n2 - 1) / pow(n2 + 1, 3) * log((n - 1) / (n + 1)) -
           2 * n2 * n * (n2 + 2 * n - 1) / ((n2 + 1) * (n4 - 1)) +
           8 * n4 * (n4 + 1) / ((n2 + 1) * (n4 - 1) * (n4 - 1)) * log(n);
}

/* Independent brute force: midpoint rule in mu with many cells. */
static double avg_midpoint(double eta, int cells)
{
    double sum = 0;
    for (int i = 0; i < cells; ++i) {
        double mu = (i + 0.5) / cells, R;
        soak_fresnel_dielectric(mu, eta, &R, NULL);
        sum += R * mu;
    }
    return 2.0 * sum / cells;
}

int main(void)
{
    tu_rng rng = tu_xorshift64(0x9E3779B97F4A7C15ull);
    double R, ct;
    /* Normal incidence: ((n-1)/(n+1))^2. */
    soak_fresnel_dielectric(1.0, 1.333, &R, NULL);
    check_close("water R0", R, pow(0.333 / 2.333, 2), 1e-15);
    soak_fresnel_dielectric(1.0, 1.0 / 1.5, &R, NULL);
    check_close("glass->air R0", R, 0.04, 1e-15);
    /* Brewster angle: R_p = 0, so R = R_s / 2 with R_s analytic. */
    double n = 1.5, tb = atan(n), ci = cos(tb), st = sin(tb) / n, ctb = sqrt(1 - st * st);
    double rs = (ci - n * ctb) / (ci + n * ctb);
    soak_fresnel_dielectric(ci, n, &R, NULL);
    check_close("Brewster angle R = Rs/2", R, 0.5 * rs * rs, 1e-15);

    /* Equal indices: no interface at any angle, including grazing. */
    int equal_ok = 1;
    for (int i = 0; i <= 100; ++i) {
        soak_fresnel_dielectric(i / 100.0, 1.0, &R, &ct);
        equal_ok &= R == 0.0 && fabs(ct - i / 100.0) < 1e-15;
        equal_ok &= soak_fresnel_conductor_raw(i / 100.0, 1.0, 0.0) == 0.0;
    }
    check_true("equal indices give R = 0 everywhere", equal_ok);
    soak_fresnel_dielectric_avg(1.0, &R);
    check_close("equal indices average", R, 0.0, 0.0);

    /* Grazing: R -> 1 from both sides. */
    soak_fresnel_dielectric(0.0, 1.33, &R, NULL);
    check_close("grazing external", R, 1.0, 1e-15);
    soak_fresnel_dielectric(1e-12, 1.33, &R, NULL);
    check_close("near-grazing external", R, 1.0, 1e-10);
    soak_fresnel_dielectric(0.0, 1 / 1.33, &R, NULL);
    check_close("grazing internal", R, 1.0, 0.0);

    /* Critical angle of water->air, +-1e-9 in cos. */
    double eta = 1.0 / 1.33, mu_c = sqrt(1 - eta * eta);
    soak_fresnel_dielectric(mu_c - 1e-9, eta, &R, &ct);
    check_true("below critical cos: TIR", R == 1.0 && ct == 0.0);
    soak_fresnel_dielectric(mu_c + 1e-9, eta, &R, &ct);
    check_true("just above critical cos: R < 1 and transmits", R < 1.0 && R > 0.99 && ct > 0.0);
    /* Transmitted cos just past the critical angle: sqrt(1 - (1-mu^2)/eta^2). */
    double mu = mu_c + 1e-9;
    check_rel("cos_t at critical + eps", ct, sqrt(1 - (1 - mu * mu) / (eta * eta)), 1e-6);

    /* Reciprocity of Fresnel: R(cos_i, eta) = R(cos_t, 1/eta). */
    double worst = 0;
    for (int i = 1; i < 200; ++i) {
        double c = i / 200.0, R1, R2, t;
        soak_fresnel_dielectric(c, 1.33, &R1, &t);
        soak_fresnel_dielectric(t, 1 / 1.33, &R2, NULL);
        worst = fmax(worst, fabs(R1 - R2));
    }
    check_close("reciprocity R(i,n) = R(t,1/n)", worst, 0.0, 1e-12);

    /* Hemispherical averages: closed form, brute force, identity. */
    const double ns[] = {1.05, 1.333, 1.5, 2.0, 2.5, 1.0001};
    for (int i = 0; i < 6; ++i) {
        double ext, in;
        soak_fresnel_dielectric_avg(ns[i], &ext);
        soak_fresnel_dielectric_avg(1.0 / ns[i], &in);
        char what[96];
        snprintf(what, sizeof what, "R_avg(%.4f) vs closed form", ns[i]);
        /* In double the closed form cancels catastrophically as n -> 1; for
         * n = 1.0001 the reference is the same formula evaluated in 50-digit
         * decimal arithmetic (Python's decimal module): 3.32917312462127e-05. */
        check_close(what, ext, ns[i] < 1.01 ? 3.32917312462127e-05 : avg_closed_form(ns[i]), 1e-12);
        snprintf(what, sizeof what, "R_avg(%.4f) vs 2e5-cell midpoint", ns[i]);
        check_close(what, ext, avg_midpoint(ns[i], 200000), 1e-8);
        snprintf(what, sizeof what, "1 - R_int = (1 - R_ext)/n^2 at n=%.4f", ns[i]);
        check_close(what, 1 - in, (1 - ext) / (ns[i] * ns[i]), 1e-12);
    }

    /* Conductor: k = 0 equals the dielectric; normal incidence equals r0. */
    worst = 0;
    for (int i = 0; i <= 100; ++i) {
        double c = i / 100.0, Rd, Rc;
        soak_fresnel_dielectric(c, 1.5, &Rd, NULL);
        soak_fresnel_conductor(c, 1.5, 0.0, &Rc);
        worst = fmax(worst, fabs(Rd - Rc));
    }
    check_close("conductor(k=0) = dielectric", worst, 0.0, 1e-14);
    double r0;
    soak_fresnel_conductor(1.0, 3.406149 / 1.33, 5.225178 / 1.33, &R);
    soak_fresnel_r0(3.406149 / 1.33, 5.225178 / 1.33, &r0);
    check_close("copper under water, normal incidence = r0", R, r0, 1e-14);
    soak_fresnel_conductor(0.0, 1.65, 9.22, &R);
    check_close("conductor grazing = 1", R, 1.0, 0.0);

    /* Schlick end points. */
    soak_fresnel_schlick(1.0, 0.04, &R);
    check_close("Schlick at normal = R0", R, 0.04, 1e-16);
    soak_fresnel_schlick(0.0, 0.04, &R);
    check_close("Schlick at grazing = 1", R, 1.0, 1e-16);

    /* Invalid inputs are rejected, outputs untouched. */
    R = 7.0;
    check_status("NaN cos", soak_fresnel_dielectric(NAN, 1.33, &R, NULL), SOAK_ERR_ARG);
    check_status("Inf eta", soak_fresnel_dielectric(0.5, INFINITY, &R, NULL), SOAK_ERR_ARG);
    check_status("cos > 1", soak_fresnel_dielectric(1.0000001, 1.33, &R, NULL), SOAK_ERR_ARG);
    check_status("eta 0", soak_fresnel_dielectric(0.5, 0.0, &R, NULL), SOAK_ERR_ARG);
    check_status("negative k", soak_fresnel_conductor(0.5, 1.0, -1.0, &R), SOAK_ERR_ARG);
    check_status("NaN R0", soak_fresnel_schlick(0.5, NAN, &R), SOAK_ERR_ARG);
    check_status("NULL out", soak_fresnel_dielectric(0.5, 1.33, NULL, NULL), SOAK_ERR_NULL);
    check_true("output untouched on error", R == 7.0);

    /* 10^6 random valid inputs: every result finite and in [0,1]. */
    long bad = 0;
    for (int i = 0; i < 1000000; ++i) {
        double c = tu_uniform(&rng), e = exp((tu_uniform(&rng) * 2 - 1) * log(50.0)),
               k = tu_uniform(&rng) < 0.5 ? 0.0 : tu_uniform(&rng) * 20, Rd, Rc;
        if (i % 7 == 0) c = 0.0;
        if (i % 11 == 0) e = 1.0;
        soak_fresnel_dielectric(c, e, &Rd, NULL);
        soak_fresnel_conductor(c, e, k, &Rc);
        if (!(Rd >= 0 && Rd <= 1) || !(Rc >= 0 && Rc <= 1)) ++bad;
    }
    check_close("random sweep: non-finite or out-of-range results", (double)bad, 0.0, 0.0);
    return check_finish();
}
