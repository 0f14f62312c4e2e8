/* Henyey-Greenstein: normalisation and mean cosine by quadrature (this is
 * what proves the correction of [JLD99] Eq. 5: the printed "- g1^2" in the
 * first denominator and the missing 1/(4 pi) both break normalisation),
 * sampling vs the analytic CDF (chi-square), inverse-CDF accuracy for
 * g -> 0 and |g| -> 1, and invalid inputs. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "testutil.h"
#include "soak/hg.h"

/* int_{-1}^{1} f(c) dc with panels graded toward both ends, where lobes with
 * |g| -> 1 have widths ~ (1-|g|)^2. */
static double integrate(double (*f)(double, const void *), const void *ctx)
{
    static const double x[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
                                0.9739065285171717};
    static const double w[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                                0.0666713443086881};
    double edges[64];
    int m = 0;
    edges[m++] = -1.0;
    for (int e = -15; e <= -1; ++e) edges[m++] = -1.0 + pow(10.0, e);
    edges[m++] = 0.0;
    for (int e = -1; e >= -15; --e) edges[m++] = 1.0 - pow(10.0, e);
    edges[m++] = 1.0;
    double sum = 0;
    for (int p = 0; p + 1 < m; ++p) {
        /* subdivide each panel 8x for accuracy within the panel */
        for (int s = 0; s < 8; ++s) {
            double a = edges[p] + (edges[p + 1] - edges[p]) * s / 8, b = edges[p] + (edges[p + 1] - edges[p]) * (s + 1) / 8;
            double h = 0.5 * (b - a), mid = 0.5 * (a + b);
            for (int i = 0; i < 5; ++i) sum += h * w[i] * (f(mid - h * x[i], ctx) + f(mid + h * x[i], ctx));
        }
    }
    return sum;
}

static double hg2_value(double c, const void *ctx)
{
    double v;
    soak_hg2_eval((const soak_hg2 *)ctx, c, &v);
    return 2 * SOAK_PI * v;
}
static double hg2_moment(double c, const void *ctx) { return c * hg2_value(c, ctx); }

/* [JLD99]'s printed form of the first lobe, for the record: not normalised. */
static double seed_typo_lobe(double c, const void *ctx)
{
    double g = *(const double *)ctx;
    return 2 * SOAK_PI * (1 - g * g) / pow(1 - 2 * g * c - g * g, 1.5);
}

/* Analytic CDF of one lobe, P(cos <= c) = (1-g^2)/(2g) (q^-1/2 - 1/(1+g))
 * with q = 1 + g^2 - 2gc, rearranged to have no 1/g:
 * (1-g)(1+c) / (sqrt(q) (1 + g + sqrt(q))). */
static double hg_cdf(double g, double c)
{
    double q = g >= 0 ? (1 - g) * (1 - g) + 2 * g * (1 - c) : (1 + g) * (1 + g) - 2 * g * (1 + c);
    double sq = sqrt(q);
    return (1 - g) * (1 + c) / (sq * (1 + g + sq));
}

/* chi-square of N samples in B equal-probability bins of the analytic CDF */
static double chi_square(const soak_hg2 *p, int N, int B, tu_rng *rng)
{
    int counts[64] = {0};
    soak_vec3 in = soak_v3(0, 0, 1);
    for (int i = 0; i < N; ++i) {
        soak_vec3 out;
        double pdf;
        soak_hg2_sample(p, in, tu_uniform(rng), tu_uniform(rng), tu_uniform(rng), &out, &pdf);
        double c = out.z;
        double F = p->w * hg_cdf(p->g1, c) + (1 - p->w) * hg_cdf(p->g2, c);
        int b = (int)(F * B);
        if (b < 0) b = 0;
        if (b >= B) b = B - 1;
        counts[b]++;
    }
    double chi = 0, e = (double)N / B;
    for (int b = 0; b < B; ++b) chi += (counts[b] - e) * (counts[b] - e) / e;
    return chi;
}

int main(void)
{
    tu_rng rng = tu_xorshift64(88172645463325252ull);
    const double gs[] = {0.0, 1e-9, 0.3, -0.3, 0.9, -0.9, 0.999, -0.999, 0.999999, -0.999999};
    for (int i = 0; i < 10; ++i) {
        soak_hg2 p = {gs[i], 0.0, 1.0};
        char what[80];
        snprintf(what, sizeof what, "HG g=%g integrates to 1", gs[i]);
        /* For |g| = 0.999999 the lobe is (1-|g|)^2 = 1e-12 wide in cos, where
         * doubles near +-1 are spaced 1.1e-16: quadrature nodes in cos cannot
         * resolve it better than ~1e-4 relative. */
        double tol = fabs(gs[i]) > 0.9999 ? 1e-4 : 1e-9;
        check_close(what, integrate(hg2_value, &p), 1.0, tol);
        snprintf(what, sizeof what, "HG g=%g mean cosine = g", gs[i]);
        check_close(what, integrate(hg2_moment, &p), gs[i], tol);
    }
    /* Two-term sets of [JLD99] (paper dry/wet, Fig. 4 b/c). */
    const soak_hg2 sets[] = {{0.05, -0.05, 0.8}, {0.8, -0.1, 0.9}, {0.5, 0.2, 0.5}, {0.8, 0.1, 0.8}};
    for (int i = 0; i < 4; ++i) {
        char what[80];
        snprintf(what, sizeof what, "HG2 set %d normalised", i);
        check_close(what, integrate(hg2_value, &sets[i]), 1.0, 1e-10);
        snprintf(what, sizeof what, "HG2 set %d mean cosine = w g1 + (1-w) g2", i);
        check_close(what, integrate(hg2_moment, &sets[i]), sets[i].w * sets[i].g1 + (1 - sets[i].w) * sets[i].g2, 1e-10);
        check_close("soak_hg2_mean_cosine", soak_hg2_mean_cosine(&sets[i]),
                    sets[i].w * sets[i].g1 + (1 - sets[i].w) * sets[i].g2, 1e-15);
    }
    double g05 = 0.5;
    double typo = integrate(seed_typo_lobe, &g05);
    /* The printed denominator 1 - 2gc - g^2 turns negative for c > 0.75 at
     * g = 0.5, so the integral is undefined (NaN) or far from 1. */
    check_true("seed's printed lobe (g=0.5) is not a normalised phase function", !(fabs(typo - 1.0) <= 0.1));

    /* Sampling: chi-square against the analytic CDF, 50 bins, 2e5 samples.
     * Critical value for 49 dof at p = 0.001 is 85.35. */
    const soak_hg2 ssets[] = {{0.0, 0.0, 1.0}, {0.5, 0.0, 1.0}, {-0.7, 0.0, 1.0}, {0.95, 0.0, 1.0},
                              {0.05, -0.05, 0.8}, {0.8, -0.1, 0.9}};
    for (int i = 0; i < 6; ++i) {
        char what[80];
        double chi = chi_square(&ssets[i], 200000, 50, &rng);
        snprintf(what, sizeof what, "sampling chi-square set %d (< 85.35)", i);
        check_true(what, chi < 85.35);
        printf("     chi-square = %.2f\n", chi);
    }

    /* Inverse CDF accuracy: F(sample(u)) = u, including extreme g. */
    const double hard[] = {0.0, 1e-12, 1e-6, 0.5, 0.999999, -0.999999, -1e-12};
    for (int i = 0; i < 7; ++i) {
        double worst = 0;
        int finite = 1;
        for (int k = 0; k <= 1000; ++k) {
            double u = k / 1000.0, c;
            soak_hg_sample_cos(hard[i], u, &c);
            finite &= c >= -1.0 && c <= 1.0;
            double F = hg_cdf(hard[i], c);
            /* Compare in probability; the analytic CDF itself loses ~1e-10
             * absolute for |g| -> 1, so the bound is set accordingly. */
            worst = fmax(worst, fabs(F - u));
        }
        char what[80];
        snprintf(what, sizeof what, "inverse CDF g=%g: |F(c(u)) - u|", hard[i]);
        /* Same double-spacing limit as above for |g| -> 1: an error of one
         * ulp in cos is ~1e-4 of the lobe width; in angle it is < 1e-9 rad. */
        check_close(what, worst, 0.0, fabs(hard[i]) > 0.99 ? 2e-3 : 1e-12);
        check_true("samples within [-1,1] and finite", finite);
    }
    /* Sampled direction: unit length, cos to dir_in = sampled cosine, pdf = eval. */
    soak_hg2 p = {0.8, -0.1, 0.9};
    soak_vec3 in = soak_v3_norm(soak_v3(0.3, -0.5, 0.8)), out;
    double pdf, worst_len = 0, worst_pdf = 0;
    for (int i = 0; i < 10000; ++i) {
        soak_hg2_sample(&p, in, tu_uniform(&rng), tu_uniform(&rng), tu_uniform(&rng), &out, &pdf);
        double v;
        soak_hg2_eval(&p, fmax(-1, fmin(1, soak_v3_dot(in, out))), &v);
        worst_len = fmax(worst_len, fabs(soak_v3_len(out) - 1));
        worst_pdf = fmax(worst_pdf, fabs(v - pdf) / v);
    }
    check_close("sampled directions are unit", worst_len, 0.0, 1e-14);
    check_close("pdf equals eval of realised cosine", worst_pdf, 0.0, 1e-6);

    /* Peak of a near-delta lobe is finite and equals (1+g)/(4 pi (1-g)^2). */
    double v, g = 0.999999;
    soak_hg_eval(g, 1.0, &v);
    check_rel("peak g=0.999999", v, (1 + g) / (4 * SOAK_PI * (1 - g) * (1 - g)), 1e-9);

    /* Invalid inputs. */
    soak_hg2 bad = {1.0, 0.0, 0.5};
    check_status("g = 1 rejected", soak_hg2_eval(&bad, 0.5, &v), SOAK_ERR_ARG);
    bad.g1 = NAN;
    check_status("g NaN rejected", soak_hg2_validate(&bad), SOAK_ERR_ARG);
    soak_hg2 okp = {0.5, -0.5, 1.5};
    check_status("w > 1 rejected", soak_hg2_validate(&okp), SOAK_ERR_ARG);
    check_status("cos NaN rejected", soak_hg_eval(0.5, NAN, &v), SOAK_ERR_ARG);
    check_status("u > 1 rejected", soak_hg_sample_cos(0.5, 1.5, &v), SOAK_ERR_ARG);
    okp.w = 0.5;
    check_status("zero dir rejected", soak_hg2_sample(&okp, soak_v3(0, 0, 0), 0.5, 0.5, 0.5, &out, &pdf), SOAK_ERR_ARG);
    check_status("NaN dir rejected", soak_hg2_sample(&okp, soak_v3(NAN, 0, 1), 0.5, 0.5, 0.5, &out, &pdf), SOAK_ERR_ARG);

    /* 10^6 random valid inputs: finite values and samples. */
    long nonfinite = 0;
    for (int i = 0; i < 1000000; ++i) {
        double gg = (tu_uniform(&rng) * 2 - 1) * SOAK_HG_G_MAX, c = tu_uniform(&rng) * 2 - 1, val, cs;
        if (i % 5 == 0) gg = (i % 10 == 0 ? 1 : -1) * SOAK_HG_G_MAX;
        soak_hg_eval(gg, c, &val);
        soak_hg_sample_cos(gg, tu_uniform(&rng), &cs);
        if (!soak_is_finite(val) || !(cs >= -1 && cs <= 1)) ++nonfinite;
    }
    check_close("random sweep non-finite", (double)nonfinite, 0.0, 0.0);
    return check_finish();
}
