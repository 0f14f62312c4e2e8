/* POV-Ray's subsurface conventions (soak/povray_subsurface.h):
 *  - alpha' at POV-Ray's table nodes Rd = i/100 reproduces Rd through Jensen
 *    et al. 2001's closed form, written out again here with POV-Ray's Fdr
 *    fit (a second implementation; POV-Ray's own inversion is replicated
 *    independently in tests/povray/subsurface.py and checked by rendering);
 *  - between nodes alpha' is the linear interpolation (POV-Ray's), within
 *    the interpolation error of the exact inverse;
 *  - the translucency T gives, through POV-Ray's reading (sigma'_s = 1/T,
 *    sigma'_t = sigma'_s/alpha'), sigma_tr = sqrt(3 sigma_a sigma'_t) equal
 *    to the requested one (an identity) unless clamped;
 *  - edges: Rd 0 and 1, eta 1, sigma_tr 0, NaN, out of range. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "soak/povray_subsurface.h"

static double closed_form_rd(double ap, double eta)
{
    double x = 1.0 - 1.0 / eta;
    double fdr = 0.25 * (x + 3.0 * pow(x, 4.5));
    double A = (1.0 + fdr) / (1.0 - fdr);
    double s = sqrt(3.0 * (1.0 - ap));
    return 0.5 * ap * (1.0 + exp(-4.0 / 3.0 * A * s)) * exp(-s);
}

static void test_nodes(void)
{
    const double etas[] = {1.0, 1.333, 1.5, 2.0};
    for (int e = 0; e < 4; ++e) {
        double worst = 0.0;
        for (int i = 0; i <= 100; ++i) {
            double ap = -1.0;
            soak_povray_alpha_prime(i / 100.0, etas[e], &ap);
            double err = fabs(closed_form_rd(ap, etas[e]) - i / 100.0);
            if (err > worst) worst = err;
        }
        char what[96];
        snprintf(what, sizeof what, "eta %.3f: Rd(alpha'(Rd)) at the 101 nodes, worst |error|", etas[e]);
        check_close(what, worst, 0.0, 1e-12);
    }
}

static void test_between_nodes(void)
{
    /* Rd = 0.655 halfway between nodes 0.65 and 0.66: the mean of the nodes' alpha' */
    double a0 = 0, a1 = 0, am = 0;
    soak_povray_alpha_prime(0.65, 1.333, &a0);
    soak_povray_alpha_prime(0.66, 1.333, &a1);
    soak_povray_alpha_prime(0.655, 1.333, &am);
    check_close("alpha' halfway between two nodes is their mean (linear, as POV-Ray)", am, 0.5 * (a0 + a1), 1e-15);
    check_close("...and within 1e-3 of the exact inverse", closed_form_rd(am, 1.333), 0.655, 1e-3);
    double prev = -1.0;
    int monotone = 1;
    for (int i = 0; i <= 1000; ++i) {
        double ap = 0;
        soak_povray_alpha_prime(i / 1000.0, 1.333, &ap);
        monotone &= ap >= prev && ap >= 0.0 && ap <= 1.0;
        prev = ap;
    }
    check_true("alpha' increases with Rd and stays in [0, 1]", monotone);
}

static void test_translucency_identity(void)
{
    const double rds[] = {0.02, 0.3, 0.655, 0.9, 0.995};
    const double trs[] = {0.05, 1.0, 30.0}; /* 1/mm: POV-Ray's T is in mm, the argument in 1/m */
    double worst = 0.0;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 3; ++j) {
            double T = 0, ap = 0;
            soak_povray_translucency(rds[i], 1.333, 1000.0 * trs[j], &T);
            soak_povray_alpha_prime(rds[i], 1.333, &ap);
            if (T <= SOAK_POVRAY_TRANSLUCENCY_MIN || T >= SOAK_POVRAY_TRANSLUCENCY_MAX) continue;
            double sps = 1.0 / T, spt = sps / ap, sa = spt - sps;
            double err = fabs(sqrt(3.0 * sa * spt) / trs[j] - 1.0);
            if (err > worst) worst = err;
        }
    check_close("POV-Ray's sigma_tr from (pigment, T) vs the requested one, worst relative error", worst, 0.0, 1e-10);
}

static void test_edges(void)
{
    double T = -1, ap = -1;
    check_status("Rd 0", soak_povray_translucency(0.0, 1.333, 1.0, &T), SOAK_OK);
    check_close("Rd 0 (alpha' 0): clamped to the largest translucency", T, SOAK_POVRAY_TRANSLUCENCY_MAX, 0.0);
    check_status("Rd 1", soak_povray_translucency(1.0, 1.333, 1.0, &T), SOAK_OK);
    check_close("Rd 1 (alpha' 1): clamped to the smallest translucency", T, SOAK_POVRAY_TRANSLUCENCY_MIN, 0.0);
    check_status("sigma_tr 0", soak_povray_translucency(0.5, 1.333, 0.0, &T), SOAK_OK);
    check_close("sigma_tr 0 (no absorption): the largest translucency", T, SOAK_POVRAY_TRANSLUCENCY_MAX, 0.0);
    check_status("eta 1 (index matched)", soak_povray_alpha_prime(0.5, 1.0, &ap), SOAK_OK);
    check_true("eta 1: alpha' finite in (0, 1)", ap > 0.0 && ap < 1.0);
    check_status("Rd NaN", soak_povray_translucency(NAN, 1.333, 1.0, &T), SOAK_ERR_ARG);
    check_status("Rd 1.01", soak_povray_alpha_prime(1.01, 1.333, &ap), SOAK_ERR_ARG);
    check_status("eta 0.9", soak_povray_alpha_prime(0.5, 0.9, &ap), SOAK_ERR_ARG);
    check_status("sigma_tr -1", soak_povray_translucency(0.5, 1.333, -1.0, &T), SOAK_ERR_ARG);
    check_status("sigma_tr Inf", soak_povray_translucency(0.5, 1.333, INFINITY, &T), SOAK_ERR_ARG);
    check_status("NULL output", soak_povray_translucency(0.5, 1.333, 1.0, NULL), SOAK_ERR_NULL);
}

int main(void)
{
    test_nodes();
    test_between_nodes();
    test_translucency_identity();
    test_edges();
    return check_finish();
}
