/* Poisson counts (soak/poisson.h) against the distribution's identities:
 * mean and variance equal lambda (within 4 standard errors of 200000
 * draws) on both branches (inversion below 30, normal approximation above);
 * 0 for lambda = 0 and NaN. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "soak/poisson.h"

int main(void)
{
    double lambdas[] = {0.05, 3.0, 25.0, 80.0};
    for (int k = 0; k < 4; ++k) {
        soak_rng rng;
        soak_rng_seed(&rng, 11, (uint64_t)k);
        const int n = 200000;
        double s = 0, s2 = 0;
        for (int i = 0; i < n; ++i) {
            double c = (double)soak_rng_poisson(lambdas[k], &rng);
            s += c;
            s2 += c * c;
        }
        double mean = s / n, var = s2 / n - mean * mean, L = lambdas[k];
        char what[96];
        snprintf(what, sizeof what, "Poisson(%g) mean (4 standard errors)", L);
        check_close(what, mean, L, 4.0 * sqrt(L / n));
        snprintf(what, sizeof what, "Poisson(%g) variance (4 standard errors)", L);
        /* var of the sample variance ~ (mu4 - sigma^4)/n, mu4 = L(1 + 3L) for Poisson */
        check_close(what, var, L, 4.0 * sqrt((L * (1 + 3 * L) - L * L) / n));
    }
    soak_rng rng;
    soak_rng_seed(&rng, 1, 1);
    check_true("Poisson(0) and Poisson(NaN) are 0", soak_rng_poisson(0.0, &rng) == 0 && soak_rng_poisson(NAN, &rng) == 0);
    return check_finish();
}
