/* Porous BRDF (Merillou), wet porous model (Hnat) and the GGX variant on
 * bad and random inputs: every out-of-range parameter refused with an error
 * code, and a million random in-range parameter sets and directions give
 * finite values (split from test_porous.c). */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "porous_cases.h"
#include "testutil.h"
#include "soak/porous.h"

static void test_validation(void)
{
    const double bad[] = {NAN, INFINITY, -INFINITY};
    double v;
    soak_vec3 up = soak_v3(0, 0, 1);
    for (int i = 0; i < 3; ++i) {
        double b = bad[i];
        check_status("Gp bad m", soak_porous_Gp(b, 0.5, 0.5, &v), SOAK_ERR_ARG);
        check_status("Gp bad cos", soak_porous_Gp(0.1, b, 0.5, &v), SOAK_ERR_ARG);
        check_status("nb bad sp", soak_porous_nb(b, 0.1, 0.1, &v), SOAK_ERR_ARG);
        check_status("nb bad theta", soak_porous_nb(1.0, 0.1, b, &v), SOAK_ERR_ARG);
        check_status("Ap bad ka", soak_porous_Ap(b, 2.0, &v), SOAK_ERR_ARG);
        check_status("Ap bad nb", soak_porous_Ap(0.2, b, &v), SOAK_ERR_ARG);
        check_status("fill bad t", soak_fill_fraction(b, 0.0, 0.1, &v), SOAK_ERR_ARG);
        check_status("fill bad t0", soak_fill_fraction(0.5, b, 0.1, &v), SOAK_ERR_ARG);
        check_status("fill bad t_fill", soak_fill_fraction(0.5, 0.0, b, &v), SOAK_ERR_ARG);
        check_status("wetmap bad", soak_wetmap_t0(b, &v), SOAK_ERR_ARG);
        for (int field = 0; field < 8; ++field) {
            soak_porous_params p = porous_paper_params(0.3, 1.3);
            double *fp[] = {&p.kd, &p.ks, &p.m, &p.spec_power, &p.porosity, &p.sp, &p.ks_water, &p.water_power};
            *fp[field] = b;
            check_status("BP param NaN/Inf", soak_porous_eval(&p, 0.5, up, up, &v), SOAK_ERR_ARG);
        }
        soak_porous_params p = porous_paper_params(0.3, 1.3);
        check_status("BP fill NaN/Inf", soak_porous_eval(&p, b, up, up, &v), SOAK_ERR_ARG);
        check_status("BP wi NaN/Inf", soak_porous_eval(&p, 0.5, soak_v3(b, 0, 1), up, &v), SOAK_ERR_ARG);
        check_status("BP albedo fill NaN", soak_porous_albedo_factor(&p, b, &v, NULL), SOAK_ERR_ARG);
        for (int field = 0; field < 7; ++field) {
            soak_porous_ggx_params g = {0.5, 0.3, 1.5, 0.3, 1.3, 0.02, 1.33};
            double *fp[] = {&g.albedo, &g.roughness, &g.eta, &g.porosity, &g.sp, &g.water_roughness, &g.eta_water};
            *fp[field] = b;
            soak_porous_ggx c;
            check_status("GGX param NaN/Inf", soak_porous_ggx_setup(&g, &c), SOAK_ERR_ARG);
        }
        soak_porous_ggx_params g = {0.5, 0.3, 1.5, 0.3, 1.3, 0.02, 1.33};
        soak_porous_ggx c;
        soak_porous_ggx_setup(&g, &c);
        check_status("GGX fill NaN/Inf", soak_porous_ggx_eval(&c, b, up, up, &v), SOAK_ERR_ARG);
        check_status("GGX wo NaN/Inf", soak_porous_ggx_eval(&c, 0.5, up, soak_v3(0, b, 1), &v), SOAK_ERR_ARG);
    }
    soak_porous_params p = porous_paper_params(0.3, 1.3);
    p.ks = 0.31;
    p.kd = 0.7;
    check_status("k_s + k_d > 1 rejected", soak_porous_validate(&p), SOAK_ERR_ARG);
    p = porous_paper_params(0.3, 1.3);
    check_status("non-unit direction rejected", soak_porous_eval(&p, 0.5, soak_v3(0, 0, 1.1), up, &v), SOAK_ERR_ARG);
    check_status("fill > 1 rejected", soak_porous_eval(&p, 1.5, up, up, &v), SOAK_ERR_ARG);
    check_status("t_fill < 0 rejected", soak_fill_fraction(0.5, 0.0, -0.1, &v), SOAK_ERR_ARG);
    check_status("NULL output", soak_porous_eval(&p, 0.5, up, up, NULL), SOAK_ERR_NULL);
    v = 7.0;
    check_status("below horizon OK", soak_porous_eval(&p, 0.5, up, soak_v3(0, 0.6, -0.8), &v), SOAK_OK);
    check_close("below horizon gives 0", v, 0.0, 0.0);
    soak_porous_eval(&p, 0.5, up, soak_v3(1, 0, 0), &v);
    check_close("horizon (z = 0) gives 0", v, 0.0, 0.0);
    soak_porous_ggx_params g = {0.5, 0.3, 1.5, 0.3, 1.3, 0.02, 1.33};
    soak_porous_ggx c;
    soak_porous_ggx_setup(&g, &c);
    v = 7.0;
    soak_porous_ggx_eval(&c, 0.5, soak_v3(0, 0.6, -0.8), up, &v);
    check_close("GGX below horizon gives 0", v, 0.0, 0.0);
    soak_vec3 wo;
    double pdf;
    check_status("GGX sample NaN u", soak_porous_ggx_sample(&c, 0.5, up, NAN, 0.5, 0.5, &wo, &v, &pdf), SOAK_ERR_ARG);
    check_status("GGX sample u > 1", soak_porous_ggx_sample(&c, 0.5, up, 0.5, 1.5, 0.5, &wo, &v, &pdf), SOAK_ERR_ARG);
    check_status("GGX pdf NaN wo", soak_porous_ggx_pdf(&c, 0.5, up, soak_v3(NAN, 0, 1), &pdf), SOAK_ERR_ARG);
    check_status("BP sample NaN u", soak_porous_sample(&p, 0.5, up, 0.5, NAN, 0.5, &wo, &v, &pdf), SOAK_ERR_ARG);
    check_status("BP pdf Inf fill", soak_porous_pdf(&p, INFINITY, up, up, &pdf), SOAK_ERR_ARG);
    g.roughness = 0.0;
    check_status("GGX roughness 0 rejected (below SOAK_GGX_ALPHA_MIN)", soak_porous_ggx_setup(&g, &c), SOAK_ERR_ARG);
}

static int finite(double x) { return x == x && fabs(x) <= 1.7976931348623157e308; }

static void test_random_finite(tu_rng *rng)
{
    long bad = 0, notok = 0;
    for (long s = 0; s < 1000000; ++s) {
        double u = tu_uniform(rng);
        soak_porous_params p = {u < 0.05 ? 0.0 : tu_uniform(rng),
                                0.0,
                                u < 0.1 ? 0.0 : tu_uniform(rng),
                                1e4 * tu_uniform(rng) * tu_uniform(rng),
                                tu_uniform(rng),
                                50.0 * tu_uniform(rng),
                                SOAK_POROUS_KS_WATER_MAX * tu_uniform(rng),
                                1e4 * tu_uniform(rng) * tu_uniform(rng),
                                (soak_blinn_norm)(s & 1)};
        p.ks = u > 0.95 ? 1.0 - p.kd : (1.0 - p.kd) * tu_uniform(rng);
        soak_vec3 wi = tu_upper_dir(rng, 1e-6), wo = tu_upper_dir(rng, 1e-6);
        if (s % 7 == 0) wi = soak_v3(sqrt(1.0 - 1e-300), 0.0, 1e-150); /* extreme grazing */
        double f = NAN;
        if (soak_porous_eval(&p, tu_uniform(rng), wi, wo, &f) != SOAK_OK) ++notok;
        else if (!finite(f) || f < 0.0) ++bad;
        double a = NAN;
        if (soak_porous_Ap(s % 11 == 0 ? 1.0 : pow(tu_uniform(rng), 40.0), 1e4 * tu_uniform(rng) * tu_uniform(rng),
                           &a) != SOAK_OK)
            ++notok;
        else if (!finite(a) || a < 0.0 || a > 1.0) ++bad;
        double fr = NAN;
        if (soak_fill_fraction(1e6 * (tu_uniform(rng) - 0.5), 1e6 * (tu_uniform(rng) - 0.5),
                               s % 5 == 0 ? 0.0 : 1e3 * tu_uniform(rng) * tu_uniform(rng), &fr) != SOAK_OK)
            ++notok;
        else if (!(fr >= 0.0 && fr <= 1.0)) ++bad;
        if (s % 10 == 0) {
            soak_vec3 wo;
            double fs, ps;
            double u1 = s % 20 == 0 ? (s % 40 == 0 ? 0.0 : 1.0) : tu_uniform(rng);
            if (soak_porous_sample(&p, tu_uniform(rng), wi, tu_uniform(rng), u1, tu_uniform(rng), &wo, &fs, &ps) !=
                SOAK_OK)
                ++notok;
            else if (!finite(fs) || !finite(ps) || fs < 0.0 || ps < 0.0) ++bad;
        }
    }
    check_true("10^6 random valid Blinn-Phong/A_p/fill inputs: all SOAK_OK", notok == 0);
    check_true("... and all finite, in range", bad == 0);

    long bad_g = 0, notok_g = 0;
    for (int m = 0; m < 20; ++m) {
        soak_porous_ggx_params g = {tu_uniform(rng),
                                    m == 0 ? 1e-4 : fmin(1.0, 1e-4 + tu_uniform(rng)),
                                    1.0 + 2.0 * tu_uniform(rng),
                                    tu_uniform(rng),
                                    50.0 * tu_uniform(rng),
                                    m == 1 ? 1e-4 : fmin(1.0, 1e-4 + tu_uniform(rng)),
                                    1.0 + 2.0 * tu_uniform(rng)};
        soak_porous_ggx c;
        if (soak_porous_ggx_setup(&g, &c) != SOAK_OK) {
            ++notok_g;
            continue;
        }
        for (int k = 0; k < 50000; ++k) {
            soak_vec3 wi = tu_upper_dir(rng, 1e-6), wo = k % 3 ? tu_upper_dir(rng, 1e-6) : soak_v3(-wi.x, -wi.y, wi.z);
            double f = NAN;
            if (soak_porous_ggx_eval(&c, tu_uniform(rng), wi, wo, &f) != SOAK_OK) ++notok_g;
            else if (!finite(f) || f < 0.0) ++bad_g;
            if (k % 10 == 0) {
                double fs, ps, u1 = k % 20 == 0 ? (k % 40 == 0 ? 0.0 : 1.0) : tu_uniform(rng);
                if (soak_porous_ggx_sample(&c, tu_uniform(rng), wi, tu_uniform(rng), u1, tu_uniform(rng), &wo, &fs,
                                           &ps) != SOAK_OK)
                    ++notok_g;
                else if (!finite(fs) || !finite(ps) || fs < 0.0 || ps < 0.0) ++bad_g;
            }
        }
    }
    check_true("10^6 random valid GGX-variant inputs: all SOAK_OK", notok_g == 0);
    check_true("... and all finite, non-negative", bad_g == 0);
}

int main(void)
{
    tu_rng rng = tu_splitmix64(0x2545F4914F6CDD1Dull);
    test_validation();
    test_random_finite(&rng);
    return check_finish();
}
