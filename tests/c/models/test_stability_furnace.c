/* Stability sweep, part 2 (split from test_stability.c): Tri-Ace's measured
 * non-reciprocity (soak/ww.h), and a white-furnace directional albedo <=
 * 1 + MC error for every soak_models() entry that claims energy
 * conservation, from the same fixed seed. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "check.h"
#include "soak/ggx.h"
#include "soak/models.h"
#include "soak/porous.h"
#include "soak/rng.h"
#include "soak/ww.h"

static double uni(soak_rng *r) { return soak_rng_uniform(r); }

/* Tri-Ace is not reciprocal: f(i,o) / f(o,i) = S(cos_i) / S(cos_o) with
 * S(c) = 1 - (1 - c)^5, Schlick's T12 at the incident side only (soak/ww.h).
 * Asserts that identity and the documented statistics: over pairs uniform in
 * solid angle with both polar angles <= 85 degrees, the share of pairs more
 * than 1 % off and the largest ratio. */
static void triace_reciprocity(void)
{
    soak_rng rng, *r = &rng;
    soak_rng_seed(r, 20, 7);
    soak_model_params p;
    soak_model_params_default(&p);
    const soak_model *m = soak_model_find("ww-triace");
    soak_model_ctx ctx;
    if (!check_status("ww-triace default set-up", m->setup(&p, &ctx), SOAK_OK)) return;
    const int N = 200000;
    long off = 0;
    double worst_ratio = 1.0, worst_identity = 0.0;
    const double zmin = cos(85.0 * SOAK_PI / 180.0);
    for (int k = 0; k < N; ++k) {
        soak_vec3 d[2];
        for (int j = 0; j < 2; ++j) {
            double z = zmin + (1.0 - zmin) * uni(r), s = sqrt(1.0 - z * z), phi = 2.0 * SOAK_PI * uni(r);
            d[j] = soak_v3(s * cos(phi), s * sin(phi), z);
        }
        double f1, f2;
        if (soak_model_eval(m, &ctx, d[0], d[1], &f1) != SOAK_OK ||
            soak_model_eval(m, &ctx, d[1], d[0], &f2) != SOAK_OK)
            continue;
        if (!(f1 > 0.0 && f2 > 0.0)) continue;
        double ratio = f1 / f2;
        double s0 = 1.0 - pow(1.0 - d[0].z, 5.0), s1 = 1.0 - pow(1.0 - d[1].z, 5.0);
        worst_identity = fmax(worst_identity, fabs(ratio / (s0 / s1) - 1.0));
        if (fabs(ratio - 1.0) > 0.01 && fabs(1.0 / ratio - 1.0) > 0.01) ++off;
        worst_ratio = fmax(worst_ratio, fmax(ratio, 1.0 / ratio));
    }
    double share = (double)off / N;
    /* closed form of the largest ratio at 85 degrees: 1 / S(cos 85) */
    double bound = 1.0 / (1.0 - pow(1.0 - zmin, 5.0));
    printf("     ww-triace reciprocity, %d pairs (theta <= 85 deg): %.1f %% more than 1 %% off, max ratio %.3f "
           "(closed form %.3f)\n",
           N, 100.0 * share, worst_ratio, bound);
    check_close("ww-triace f(i,o)/f(o,i) = S(cos_i)/S(cos_o) (max rel dev)", worst_identity, 0.0, 1e-9);
    check_true("ww-triace largest ratio <= documented 1/S(cos 85 deg) = 2.731",
               worst_ratio <= bound * (1 + 1e-9) && fabs(bound - 2.731) < 5e-4 && worst_ratio > 0.99 * bound);
    check_close("ww-triace share of pairs > 1 % off (documented 78 %)", share, 0.78, 0.005);
}

/* ---- soak_models() ------------------------------------------------------- */

/* ---- white furnace -------------------------------------------------------- */

/* Independent samplers for the estimator (not the library's): cosine,
 * GGX D(h) h.z half vectors (Walter et al. 2007 eq. 35-36) and Blinn-Phong
 * cos^n half vectors, mixed with equal weights; the mixture density is
 * evaluated exactly, so the estimate is unbiased whatever the lobe shapes. */
typedef struct {
    double alpha[2]; /* GGX widths to sample (0: unused) */
    double power[2]; /* Blinn-Phong exponents (< 0: unused) */
} furnace_lobes;

static double ggx_d(double a, double cz)
{
    double a2 = a * a, c2 = cz * cz, t = c2 * (a2 - 1.0) + 1.0;
    return cz > 0.0 ? a2 / (SOAK_PI * t * t) : 0.0;
}

static double mixture_pdf(const furnace_lobes *L, soak_vec3 wi, soak_vec3 wo, int nstrat)
{
    double pdf = wo.z > 0.0 ? wo.z / SOAK_PI : 0.0;
    soak_vec3 h = soak_v3_norm(soak_v3_add(wi, wo));
    double ih = soak_v3_dot(wi, h);
    if (h.z > 0.0 && ih > 0.0) {
        for (int j = 0; j < 2; ++j) {
            if (L->alpha[j] > 0.0) pdf += ggx_d(L->alpha[j], h.z) * h.z / (4.0 * ih);
            if (L->power[j] >= 0.0) pdf += (L->power[j] + 1.0) / (2.0 * SOAK_PI) * pow(h.z, L->power[j]) / (4.0 * ih);
        }
    }
    return pdf / nstrat;
}

static double furnace_albedo(const soak_model *m, const soak_model_ctx *ctx, const furnace_lobes *L, soak_vec3 wi,
                             soak_rng *r, int N, double *stderr_out)
{
    int nstrat = 1;
    for (int j = 0; j < 2; ++j) nstrat += (L->alpha[j] > 0.0) + (L->power[j] >= 0.0);
    double sum = 0.0, sum2 = 0.0;
    for (int k = 0; k < N; ++k) {
        int s = k % nstrat;
        double u1 = uni(r), u2 = uni(r), phi = 2.0 * SOAK_PI * u2;
        soak_vec3 wo;
        if (s == 0) {
            double sr = sqrt(u1);
            wo = soak_v3(sr * cos(phi), sr * sin(phi), sqrt(fmax(0.0, 1.0 - u1)));
        } else {
            int idx = s - 1, j = 0;
            double cz = 1.0;
            for (; j < 2; ++j) {
                if (L->alpha[j] > 0.0 && idx-- == 0) {
                    double a2 = L->alpha[j] * L->alpha[j];
                    cz = sqrt((1.0 - u1) / (1.0 + (a2 - 1.0) * u1));
                    break;
                }
                if (L->power[j] >= 0.0 && idx-- == 0) {
                    cz = pow(u1, 1.0 / (L->power[j] + 1.0));
                    break;
                }
            }
            double sz = sqrt(fmax(0.0, 1.0 - cz * cz));
            soak_vec3 h = soak_v3(sz * cos(phi), sz * sin(phi), cz);
            wo = soak_v3_sub(soak_v3_scale(h, 2.0 * soak_v3_dot(wi, h)), wi);
            wo = soak_v3_norm(wo);
        }
        double val = 0.0;
        if (wo.z > 0.0) {
            double f = 0.0, pdf = mixture_pdf(L, wi, wo, nstrat);
            if (soak_model_eval(m, ctx, wi, wo, &f) == SOAK_OK && pdf > 0.0) val = f * wo.z / pdf;
        }
        sum += val;
        sum2 += val * val;
    }
    double mean = sum / N, var = fmax(0.0, sum2 / N - mean * mean);
    *stderr_out = sqrt(var / N);
    return mean;
}

/* The registry entries whose headers claim that the directional albedo of
 * their non-delta part is <= 1 (ww-triace, a fast path, claims nothing and
 * is reported only). */
static int claims_conservation(const char *name) { return strcmp(name, "ww-triace") != 0; }

static void white_furnace(soak_rng *r)
{
    size_t n;
    const soak_model *models = soak_models(&n);
    static soak_model_ctx ctx;
    const double albedos[] = {0.0, 0.5, 1.0}, roughs[] = {0.01, 0.1, 0.3, 0.6, 1.0}, iors[] = {1.0, 1.5, 3.0},
                 nfilm[] = {1.0, 1.333, 3.0}, pors[] = {0.0, 0.5, 1.0}, fills[] = {0.0, 0.5, 1.0},
                 kss[] = {0.0, 0.05, 0.5, 1.0}, ksws[] = {0.02, 0.25, SOAK_POROUS_KS_WATER_MAX},
                 sps[] = {0.0, 2.0, 20.0};
    const double thetas[] = {0.0, 45.0, 75.0, 88.0};
#define PICK(a) a[(int)(uni(r) * (sizeof a / sizeof a[0]))]
    for (size_t i = 0; i < n; ++i) {
        const soak_model *m = &models[i];
        int sets = !strcmp(m->name, "porous-ggx") ? 6 : (!strcmp(m->name, "film") ? 4 : 30);
        const int samples = 12000;
        double worst = 0.0, worst_err = 0.0, worst_z = -1e9;
        int done = 0;
        for (int s = 0; s < 4 * sets && done < sets; ++s) {
            soak_model_params p;
            soak_model_params_default(&p);
            p.albedo = PICK(albedos);
            p.roughness = PICK(roughs);
            p.ior = PICK(iors);
            p.k = uni(r) < 0.25 ? 3.0 : 0.0;
            p.n_film = PICK(nfilm);
            p.absorption = 0.0;
            p.porosity = PICK(pors);
            p.fill = PICK(fills);
            p.ks = PICK(kss);
            p.ks_water = PICK(ksws);
            p.sp = PICK(sps);
            if (p.ks + p.albedo > 1.0) p.ks = 1.0 - p.albedo;
            if (m->setup(&p, &ctx) != SOAK_OK) continue;
            ++done;
            double n_spec = 2.0 / (p.roughness * p.roughness) - 2.0;
            furnace_lobes L = {{p.roughness, 0.02}, {n_spec < 0 ? 0 : (n_spec > 1e4 ? 1e4 : n_spec), 200.0}};
            for (size_t t = 0; t < sizeof thetas / sizeof thetas[0]; ++t) {
                double se,
                    a = furnace_albedo(m, &ctx, &L, soak_v3_polar(thetas[t] * SOAK_PI / 180.0, 0.0), r, samples, &se);
                double z = (a - 1.0) / fmax(se, 1e-12);
                if (a > worst) worst = a, worst_err = se;
                if (z > worst_z) worst_z = z;
            }
        }
        char what[200];
        if (claims_conservation(m->name)) {
            snprintf(
                what, sizeof what,
                "%s white furnace: %d parameter sets x 4 angles, max albedo %.4f (+- %.4f), max (A-1)/sigma %.2f <= 4",
                m->name, done, worst, worst_err, worst_z);
            printf("     %s\n", what);
            check_true(what, done >= sets / 2 && worst_z <= 4.0 && worst_err < 0.02);
        } else {
            printf("     %s white furnace (reported, fast path): max albedo %.4f (+- %.4f) over %d sets\n", m->name,
                   worst, worst_err, done);
        }
    }
#undef PICK
    /* The two configurations that broke porous' energy bound, with enough
     * samples to see them: k_s = 1 on a Blinn-Phong lobe of n ~ 8 at normal
     * incidence (was 1.077: (n+8)/(8pi) normaliser) and a white diffuse
     * base whose filled pores hold the brightest allowed water lobe (was
     * 1.29 at ks_water = 1; bound 1 + ks_water - 0.703 at m = 1). */
    const soak_model *pm = soak_model_find("porous");
    soak_model_params cases[2];
    soak_model_params_default(&cases[0]);
    cases[0].albedo = 0.0, cases[0].ks = 1.0, cases[0].roughness = 0.45, cases[0].porosity = 0.0;
    soak_model_params_default(&cases[1]);
    cases[1].albedo = 1.0, cases[1].ks = 0.0, cases[1].roughness = 1.0, cases[1].porosity = 1.0, cases[1].fill = 1.0;
    cases[1].ks_water = SOAK_POROUS_KS_WATER_MAX;
    for (int c = 0; c < 2; ++c) {
        if (!check_status("porous worst-case set-up", pm->setup(&cases[c], &ctx), SOAK_OK)) continue;
        double n_spec = 2.0 / (cases[c].roughness * cases[c].roughness) - 2.0, se;
        furnace_lobes L = {{0.0, 0.0}, {n_spec, 200.0}};
        double a = furnace_albedo(pm, &ctx, &L, soak_v3(0.0, 0.0, 1.0), r, 200000, &se);
        char what[160];
        snprintf(what, sizeof what, "porous worst case %d at normal incidence: albedo %.4f +- %.4f <= 1 + 4 sigma", c,
                 a, se);
        printf("     %s\n", what);
        check_true(what, a <= 1.0 + 4.0 * se && se < 0.005);
    }
}

int main(void)
{
    clock_t start = clock();
    soak_rng r;
    soak_rng_seed(&r, 20, 4);
    triace_reciprocity();
    white_furnace(&r);
    printf("     CPU time %.2f s\n", (double)(clock() - start) / CLOCKS_PER_SEC);
    return check_finish();
}
