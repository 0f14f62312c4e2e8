/* Jensen two-layer surface (src/jensen.c) against references built here:
 * Fresnel in Fresnel's angle form, Snell's law, and the radiance law checked
 * through a numerical derivative of the refraction map (etendue). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "check.h"
#include "testutil.h"
#include "soak/jensen.h"

/* cos of the refracted angle in n_t for cos_i in n_i (Snell), -1 if none. */
static double ref_snell(double cos_i, double n_i, double n_t)
{
    double s = n_i / n_t * sin(acos(fmin(1.0, cos_i)));
    return s >= 1.0 ? -1.0 : cos(asin(s));
}

static const double cosines[] = {1.0, 0.9, 0.7, 0.5, 0.3, 0.1, 0.02};
#define N_COS (int)(sizeof cosines / sizeof cosines[0])

static void test_energy_single_interfaces(void)
{
    soak_jensen_layer top_only = {1.0, 1.33, 1.33, 1.0}; /* n3 == n2: no lower interface */
    soak_jensen_layer no_film = {1.0, 1.0, 1.5, 1.0};    /* n2 == n1: no film */
    soak_jensen_layer no_film_k2 = {1.0, 1.0, 1.5, 2.0};
    double worst_rt = 0.0, worst_top = 0.0, worst_single = 0.0, worst_k = 0.0, worst_up = 0.0;
    for (int i = 0; i < N_COS; ++i) {
        double c = cosines[i], R = -1.0, T = -1.0, Tk = -1.0, Tup = -1.0, c3 = -1.0;
        soak_jensen_reflect_top(&top_only, c, &R);
        soak_jensen_transmit_down(&top_only, c, &T, NULL);
        worst_rt = fmax(worst_rt, fabs(R + T - 1.0));
        worst_top = fmax(worst_top, fabs(R - tu_fresnel_angle(c, 1.0, 1.33)));
        soak_jensen_transmit_down(&no_film, c, &T, &c3);
        worst_single = fmax(worst_single, fabs(T - (1.0 - tu_fresnel_angle(c, 1.0, 1.5))));
        worst_single = fmax(worst_single, fabs(c3 - ref_snell(c, 1.0, 1.5)));
        soak_jensen_transmit_down(&no_film_k2, c, &Tk, NULL);
        double F = tu_fresnel_angle(c, 1.0, 1.5);
        worst_k = fmax(worst_k, fabs(Tk - (1.0 - F * F)));
        int tir = -1;
        soak_jensen_transmit_up(&top_only, c, &Tup, NULL, &tir);
        double want = ref_snell(c, 1.33, 1.0) < 0.0 ? 0.0 : 1.0 - tu_fresnel_angle(c, 1.33, 1.0);
        worst_up = fmax(worst_up, fabs(Tup - want));
    }
    check_close("top interface alone: R + T = 1", worst_rt, 0.0, 1e-15);
    check_close("top reflectance vs reference Fresnel (air->water)", worst_top, 0.0, 1e-13);
    check_close("n2 == n1: single air->1.5 interface, T = 1 - F, cos3 by Snell", worst_single, 0.0, 1e-13);
    check_close("n2 == n1, k = 2: T = 1 - F^2", worst_k, 0.0, 1e-13);
    check_close("upward through water->air alone: T = 1 - F_internal (0 beyond critical)", worst_up, 0.0, 1e-13);
}

static void test_two_interfaces(void)
{
    soak_jensen_layer l = {1.0, 1.33, 1.5, 1.0};
    double worst = 0.0, worst_recip = 0.0, worst_shadow = 0.0;
    for (int i = 0; i < N_COS; ++i) {
        double c1 = cosines[i], T = -1.0, c3 = -1.0, S = -1.0;
        soak_jensen_transmit_down(&l, c1, &T, &c3);
        double c2 = ref_snell(c1, 1.0, 1.33);
        double F12 = tu_fresnel_angle(c1, 1.0, 1.33), F23 = tu_fresnel_angle(c2, 1.33, 1.5);
        /* energy at each interface: what is not reflected goes through */
        double want = (1.0 - F12) * (1.0 - F23);
        worst = fmax(worst, fabs(T - want));
        worst = fmax(worst, fabs(c3 - ref_snell(c2, 1.33, 1.5)));
        double Tup = -1.0, back = -1.0;
        int tir = -1;
        soak_jensen_transmit_up(&l, c3, &Tup, &back, &tir);
        worst_recip = fmax(worst_recip, fmax(fabs(Tup - T), fabs(back - c1)));
        soak_jensen_shadow(&l, c1, &S);
        worst_shadow = fmax(worst_shadow, fabs(S - T));
    }
    check_close("air/water/1.5: T = (1-F12)(1-F23(cos2)), cos3 by Snell twice", worst, 0.0, 1e-13);
    check_close("reciprocity T_up(cos3) = T_down(cos1), path returns to cos1", worst_recip, 0.0, 1e-12);
    check_close("shadow ray = flux transmittance T_down", worst_shadow, 0.0, 0.0);
}

/* Radiance law from the refraction map alone: flux T L1 cos1 dw1 goes into
 * L3 cos3 dw3 with dw = d(cos) dphi, so L3/L1 = T cos1 / (cos3 dcos3/dcos1). */
static void test_radiance_law(void)
{
    soak_jensen_layer l = {1.0, 1.33, 1.5, 1.0};
    const double h = 1e-6;
    double worst_in = 0.0, worst_out = 0.0, worst_trip = 0.0;
    const double cs[] = {0.95, 0.7, 0.4, 0.2};
    for (int i = 0; i < 4; ++i) {
        double c1 = cs[i], T = 0, c3 = 0, c3p = 0, c3m = 0;
        soak_jensen_transmit_down(&l, c1, &T, &c3);
        soak_jensen_transmit_down(&l, c1 + h, NULL, &c3p);
        soak_jensen_transmit_down(&l, c1 - h, NULL, &c3m);
        double deriv = (c3p - c3m) / (2.0 * h);
        double radiance_in = T * c1 / (c3 * deriv);
        worst_in = fmax(worst_in, fabs(radiance_in / T - (1.5 * 1.5)) / (1.5 * 1.5));

        double u = cs[i], Tup = 0, u1 = 0, u1p = 0, u1m = 0, factor = 0;
        int tir = 0;
        soak_jensen_transmit_up(&l, u, &Tup, &u1, &tir);
        soak_jensen_transmit_up(&l, u + h, NULL, &u1p, NULL);
        soak_jensen_transmit_up(&l, u - h, NULL, &u1m, NULL);
        soak_jensen_radiance_out(&l, u, &factor);
        if (!tir) {
            double radiance_out = Tup * u / (u1 * (u1p - u1m) / (2.0 * h));
            worst_out = fmax(worst_out, fabs(factor - radiance_out) / radiance_out);
        } else {
            worst_out = fmax(worst_out, fabs(factor));
        }
        /* into the material and back out: the (n3/n1)^2 and (n1/n3)^2 cancel */
        double f_back = 0.0;
        soak_jensen_radiance_out(&l, c3, &f_back);
        worst_trip = fmax(worst_trip, fabs(radiance_in * f_back - T * T));
    }
    check_close("radiance entering: L3/L1 = (n3/n1)^2 T (numerical etendue)", worst_in, 0.0, 1e-7);
    check_close("radiance_out = (n1/n3)^2 T_up (numerical etendue)", worst_out, 0.0, 1e-7);
    check_close("in and back out: radiance factor = T_down * T_up", worst_trip, 0.0, 1e-7);
}

static void check_tir_edge(const char *name, soak_jensen_layer l, double n_exit)
{
    /* critical angle where l.n3 sin(theta3) = n_exit */
    double s = n_exit / l.n3, cos_c = sqrt(1.0 - s * s);
    double T = -1.0, c1 = -1.0, f = -1.0;
    int tir = -1;
    char what[160];
    soak_jensen_transmit_up(&l, cos_c + 1e-9, &T, &c1, &tir);
    snprintf(what, sizeof what, "%s: 1e-9 inside the cone, T > 0 and no TIR", name);
    check_true(what, T > 0.0 && tir == 0 && c1 > 0.0);
    printf("     (T just inside the cone = %.3g)\n", T);
    soak_jensen_transmit_up(&l, cos_c - 1e-9, &T, &c1, &tir);
    snprintf(what, sizeof what, "%s: 1e-9 outside the cone, T = 0 and TIR", name);
    check_true(what, T == 0.0 && tir == 1 && c1 == 0.0);
    soak_jensen_radiance_out(&l, cos_c - 1e-9, &f);
    snprintf(what, sizeof what, "%s: radiance_out = 0 under TIR", name);
    check_close(what, f, 0.0, 0.0);
}

static void test_tir(void)
{
    check_tir_edge("water->air (n3 = n2 = 1.33)", (soak_jensen_layer){1.0, 1.33, 1.33, 1.0}, 1.0);
    check_tir_edge("1.5 under water -> air", (soak_jensen_layer){1.0, 1.33, 1.5, 1.0}, 1.0);
    check_tir_edge("TIR at the lower interface (n2 = 1.2 < n1 = 1.5)", (soak_jensen_layer){1.5, 1.2, 1.6, 1.0}, 1.2);
    /* down: light from a denser "outside" can be blocked too */
    soak_jensen_layer dense = {1.5, 1.0, 1.5, 1.0};
    double T = -1.0, c3 = -1.0, cos_c = sqrt(1.0 - 1.0 / (1.5 * 1.5));
    soak_jensen_transmit_down(&dense, cos_c - 1e-9, &T, &c3);
    check_true("down, n1 > n2 beyond critical: T = 0, cos3 = 0", T == 0.0 && c3 == 0.0);
}

static void test_k(void)
{
    soak_jensen_layer k1 = {1.0, 1.33, 1.5, 1.0}, k2 = k1, kh = k1;
    k2.k = 2.0;
    kh.k = 0.5;
    int more = 1, less = 1;
    for (int i = 0; i < N_COS; ++i) {
        double a = 0, b = 0, c = 0;
        soak_jensen_transmit_down(&k1, cosines[i], &a, NULL);
        soak_jensen_transmit_down(&k2, cosines[i], &b, NULL);
        soak_jensen_transmit_down(&kh, cosines[i], &c, NULL);
        more &= b > a;
        less &= c < a;
    }
    check_true("k = 2 transmits more than k = 1 at every tested angle", more);
    check_true("k = 0.5 transmits less than k = 1", less);
    double a0 = 0, b0 = 0, ag = 0, bg = 0;
    soak_jensen_transmit_down(&k1, 1.0, &a0, NULL);
    soak_jensen_transmit_down(&k2, 1.0, &b0, NULL);
    soak_jensen_transmit_down(&k1, 0.05, &ag, NULL);
    soak_jensen_transmit_down(&k2, 0.05, &bg, NULL);
    check_true("seed: the gain from k > 1 is larger at normal than at grazing incidence", b0 - a0 > bg - ag);
    /* the gain at normal incidence is F23 - F23^2 times (1 - F12) */
    double F12 = tu_fresnel_angle(1.0, 1.0, 1.33), F23 = tu_fresnel_angle(1.0, 1.33, 1.5);
    check_close("k gain at normal incidence = (1-F12)(F23 - F23^2)", b0 - a0, (1.0 - F12) * (F23 - F23 * F23), 1e-15);
}

static void test_invalid(void)
{
    const double bad[] = {NAN, INFINITY, -INFINITY, 0.5, 3.5};
    soak_jensen_layer ok = {1.0, 1.33, 1.5, 1.0};
    int all = 1;
    double out = 42.0;
    int tir = 7;
    for (int i = 0; i < 5; ++i) {
        soak_jensen_layer a = ok, b = ok, c = ok, d = ok;
        a.n1 = bad[i];
        b.n2 = bad[i];
        c.n3 = bad[i];
        d.k = i == 3 ? 0.001 : (i == 4 ? 101.0 : bad[i]);
        all &= soak_jensen_validate(&a) == SOAK_ERR_ARG && soak_jensen_validate(&b) == SOAK_ERR_ARG &&
               soak_jensen_validate(&c) == SOAK_ERR_ARG && soak_jensen_validate(&d) == SOAK_ERR_ARG;
        all &= soak_jensen_transmit_down(&a, 0.5, &out, NULL) == SOAK_ERR_ARG;
        all &= soak_jensen_transmit_up(&d, 0.5, &out, NULL, &tir) == SOAK_ERR_ARG;
        double bad_cos = i < 3 ? bad[i] : (i == 3 ? -1e-12 : 1.0 + 1e-12);
        all &= soak_jensen_transmit_down(&ok, bad_cos, &out, NULL) == SOAK_ERR_ARG;
        all &= soak_jensen_transmit_up(&ok, bad_cos, &out, NULL, &tir) == SOAK_ERR_ARG;
        all &= soak_jensen_radiance_out(&ok, bad_cos, &out) == SOAK_ERR_ARG;
        all &= soak_jensen_reflect_top(&ok, bad_cos, &out) == SOAK_ERR_ARG;
        all &= soak_jensen_shadow(&ok, bad_cos, &out) == SOAK_ERR_ARG;
    }
    check_true("NaN/Inf/out-of-range rejected with SOAK_ERR_ARG", all);
    check_true("outputs untouched on error", out == 42.0 && tir == 7);
    check_status("NULL layer", soak_jensen_validate(NULL), SOAK_ERR_NULL);
    check_status("NULL output", soak_jensen_reflect_top(&ok, 0.5, NULL), SOAK_ERR_NULL);
    check_status("both optional outputs NULL", soak_jensen_transmit_down(&ok, 0.5, NULL, NULL), SOAK_OK);
}

static void test_grazing_and_sweep(void)
{
    soak_jensen_layer l = {1.0, 1.33, 1.5, 1.0}, none = {1.2, 1.2, 1.2, 3.0};
    double T = -1.0, R = -1.0;
    soak_jensen_transmit_down(&l, 0.0, &T, NULL);
    soak_jensen_reflect_top(&l, 0.0, &R);
    check_true("grazing from air: R = 1, T = 0", R == 1.0 && T == 0.0);
    soak_jensen_transmit_down(&none, 0.0, &T, NULL);
    soak_jensen_reflect_top(&none, 0.0, &R);
    check_true("all indices equal (no interface) at grazing: R = 0, T = 1", R == 0.0 && T == 1.0);

    uint64_t x = 0x243F6A8885A308D3ull;
    long bad = 0;
    for (int i = 0; i < 200000; ++i) {
        double u[5];
        for (int j = 0; j < 5; ++j) {
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            u[j] = (double)(x >> 11) * 0x1.0p-53;
        }
        soak_jensen_layer r = {1.0 + 2.0 * u[0], 1.0 + 2.0 * u[1], 1.0 + 2.0 * u[2], 0.01 + 99.99 * u[3] * u[3]};
        double td = -1, c3 = -1, tu = -1, c1 = -1, f = -1, rt = -1;
        int tir = -1;
        soak_status s = soak_jensen_transmit_down(&r, u[4], &td, &c3);
        s |= soak_jensen_transmit_up(&r, u[4], &tu, &c1, &tir);
        s |= soak_jensen_radiance_out(&r, u[4], &f);
        s |= soak_jensen_reflect_top(&r, u[4], &rt);
        if (s != SOAK_OK || !(td >= 0 && td <= 1) || !(tu >= 0 && tu <= 1) || !(c3 >= 0 && c3 <= 1) ||
            !(c1 >= 0 && c1 <= 1) || !(f >= 0 && f <= 9) || !(rt >= 0 && rt <= 1) || !(tir == 0 || tir == 1) ||
            rt + td > 1.0 + 1e-15)
            ++bad;
    }
    check_true("2e5 random valid inputs: finite, in range, R_top + T <= 1", bad == 0);
}

int main(void)
{
    test_energy_single_interfaces();
    test_two_interfaces();
    test_radiance_law();
    test_tir();
    test_k();
    test_invalid();
    test_grazing_and_sweep();
    return check_finish();
}
