/* Poisson counts (soak/poisson.h). */
#include "soak/poisson.h"

#include <math.h>

#include "soak/vec.h"

long soak_rng_poisson(double lambda, soak_rng *rng)
{
    if (!(lambda > 0.0)) return 0;
    if (lambda > 30.0) {
        /* Normal approximation (Box-Muller), rounded; error O(1/sqrt(lambda)). */
        double u1 = 1.0 - soak_rng_uniform(rng), u2 = soak_rng_uniform(rng);
        double z = sqrt(-2.0 * log(u1)) * cos(2.0 * SOAK_PI * u2);
        double k = floor(lambda + sqrt(lambda) * z + 0.5);
        return k > 0 ? (long)k : 0;
    }
    /* Inversion: walk the CDF P(k) = e^-lambda lambda^k / k!. */
    double u = soak_rng_uniform(rng), pk = exp(-lambda), cdf = pk;
    long k = 0;
    while (u > cdf && k < 1000) {
        ++k;
        pk *= lambda / (double)k;
        cdf += pk;
    }
    return k;
}
