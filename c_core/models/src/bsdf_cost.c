/* Per-evaluation cost of a BSDF (soak/bsdf.h), CPU time: for reports. */
#include <time.h>

#include "bsdf_internal.h"

#define COST_PAIRS 64

static soak_vec3 dir_at(int i, int n, double phi0)
{
    double z = (i + 0.5) / n, r = sqrt(1 - z * z), phi = phi0 + 2.399963229728653 * i; /* golden angle */
    return soak_v3(r * cos(phi), r * sin(phi), z);
}

static void cost_pairs(soak_vec3 wi[COST_PAIRS], soak_vec3 wo[COST_PAIRS])
{
    for (int i = 0; i < COST_PAIRS; ++i) {
        wi[i] = dir_at(i, COST_PAIRS, 0.0);
        wo[i] = dir_at(COST_PAIRS - 1 - i, COST_PAIRS, 1.0);
    }
}

soak_status soak_bsdf_eval_loop(const soak_bsdf *b, long n, double *checksum)
{
    if (!b || !checksum) return SOAK_ERR_NULL;
    if (!(n >= 0 && n <= 10000000000L)) return SOAK_ERR_ARG;
    soak_vec3 wi[COST_PAIRS], wo[COST_PAIRS];
    cost_pairs(wi, wo);
    double sum = 0;
    for (long i = 0; i < n; ++i) {
        soak_rgb f;
        double pdf;
        soak_status st = soak_bsdf_eval(b, wi[i % COST_PAIRS], wo[i % COST_PAIRS], &f, &pdf);
        if (st != SOAK_OK) return st;
        sum += f.g + pdf;
    }
    *checksum = sum;
    return SOAK_OK;
}

soak_status soak_bsdf_eval_cost_ns(const soak_bsdf *b, int n_rounds, double *ns)
{
    if (!b || !ns) return SOAK_ERR_NULL;
    if (!(n_rounds >= 1 && n_rounds <= 100000000)) return SOAK_ERR_ARG;
    long n = (long)n_rounds * COST_PAIRS;
    volatile double sink = 0;
    double checksum = 0;
    clock_t t0 = clock();
    soak_status st = soak_bsdf_eval_loop(b, n, &checksum);
    clock_t t1 = clock();
    if (st != SOAK_OK) return st;
    sink = checksum;
    (void)sink;
    *ns = (double)(t1 - t0) / CLOCKS_PER_SEC * 1e9 / (double)n;
    return SOAK_OK;
}
