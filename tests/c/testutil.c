#include "testutil.h"

#include <math.h>

#define TU_GOLDEN_GAMMA 0x9E3779B97F4A7C15ull

tu_rng tu_splitmix64(uint64_t seed)
{
    tu_rng r = {seed, TU_SPLITMIX64};
    return r;
}

tu_rng tu_xorshift64(uint64_t seed)
{
    tu_rng r = {seed, TU_XORSHIFT64};
    return r;
}

static uint64_t next_u64(tu_rng *r)
{
    if (r->kind == TU_XORSHIFT64) {
        r->state ^= r->state << 13;
        r->state ^= r->state >> 7;
        r->state ^= r->state << 17;
        return r->state;
    }
    uint64_t z = (r->state += TU_GOLDEN_GAMMA);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double tu_uniform(tu_rng *r)
{
    return (double)(next_u64(r) >> 11) * 0x1.0p-53;
}

soak_vec3 tu_upper_dir(tu_rng *r, double zmin)
{
    double z = zmin + (1.0 - zmin) * tu_uniform(r);
    double phi = 2.0 * SOAK_PI * tu_uniform(r);
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    return soak_v3(s * cos(phi), s * sin(phi), z);
}

double tu_legendre_root(int n, int i, double *dpn)
{
    double x = cos(SOAK_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= n; ++k) {
            double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
            p0 = p1;
            p1 = p2;
        }
        dp = n * (x * p1 - p0) / (x * x - 1.0);
        double dx = p1 / dp;
        x -= dx;
        if (fabs(dx) < 1e-16) break;
    }
    *dpn = dp;
    return x;
}

void tu_gauss_legendre_unit(int n, int count, double *x, double *w)
{
    for (int i = 0; i < count; ++i) {
        double dp, z = tu_legendre_root(n, i, &dp);
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
}

void tu_gauss_legendre(int n, double a, double b, double *x, double *w)
{
    for (int i = 0; i < n; ++i) {
        double dp, z = tu_legendre_root(n, i, &dp);
        x[i] = 0.5 * (a + b) - 0.5 * (b - a) * z;
        w[i] = (b - a) / ((1.0 - z * z) * dp * dp);
    }
}

double tu_fresnel_angle(double cos_i, double n_i, double n_t)
{
    if (n_i == n_t) return 0.0;
    double ti = acos(fmin(1.0, cos_i));
    double st = n_i / n_t * sin(ti);
    if (st >= 1.0) return 1.0;
    if (ti < 1e-7) {
        double r = (n_t - n_i) / (n_t + n_i);
        return r * r;
    }
    double tt = asin(st);
    double s = sin(ti - tt) / sin(ti + tt);
    double t = tan(ti - tt) / tan(ti + tt);
    return 0.5 * (s * s + t * t);
}
