/* Per-tile stopping of the progressive render (soak render --target-error). */
#include <math.h>

#include "render_adaptive.h"

/* The standard error of a mean of n samples from the unbiased sample
 * variance: se^2 = (sum y^2 - n mean^2) / (n (n - 1)). */
int rt_adaptive_converged(const double *sum_y, const double *sum_y2, const int *count, int n, double target)
{
    for (int i = 0; i < n; ++i) {
        const int k = count[i];
        if (k < RT_ADAPTIVE_MIN_SPP) return 0;
        double mean = sum_y[i] / k;
        double var = fmax(0.0, (sum_y2[i] - k * mean * mean) / (k - 1.0));
        double se = sqrt(var / k), bound = target * fmax(mean, RT_ADAPTIVE_FLOOR);
        if (!(se <= bound)) return 0;
    }
    return 1;
}
