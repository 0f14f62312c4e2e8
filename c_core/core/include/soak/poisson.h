/* Poisson-distributed counts drawn from a soak_rng: the number of events
 * of a Poisson process with mean lambda in one interval (the rain bakes'
 * drop impacts per texel and step). */
#ifndef SOAK_POISSON_H
#define SOAK_POISSON_H

#include "soak/rng.h"

/* Poisson(lambda) count drawn with rng: inversion of the CDF for
 * lambda <= 30 (at most 1000), the normal approximation rounded to the
 * nearest count above (error O(1/sqrt(lambda))); 0 for lambda <= 0 or NaN. */
long soak_rng_poisson(double lambda, soak_rng *rng);

#endif
