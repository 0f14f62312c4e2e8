/* Test-only helpers shared by the C tests: small deterministic random number
 * generators with explicit state, random directions on the upper
 * hemisphere, Gauss-Legendre nodes by Newton iteration, and an angle-form
 * Fresnel reference. Everything here is written independently of libsoak so
 * that a test never checks the library against itself. */
#ifndef SOAK_TESTUTIL_H
#define SOAK_TESTUTIL_H

#include <stdint.h>

#include "soak/vec.h"

/* Generator choice is part of a test's reproducibility: Monte Carlo and
 * chi-square tests print numbers that depend on the exact sequence. */
typedef enum { TU_SPLITMIX64, TU_XORSHIFT64 } tu_rng_kind;

typedef struct {
    uint64_t state;
    tu_rng_kind kind;
} tu_rng;

/* splitmix64 (Steele, Lea, Flood 2014): state advances by the golden gamma. */
tu_rng tu_splitmix64(uint64_t seed);
/* Marsaglia's xorshift64 with shifts (13, 7, 17); seed must be non-zero. */
tu_rng tu_xorshift64(uint64_t seed);
/* Uniform double in [0, 1) from the top 53 bits of the next output. */
double tu_uniform(tu_rng *r);

/* Direction on the upper hemisphere (normal +z), uniform in z on [zmin, 1)
 * and in azimuth: uniform in solid angle. zmin > 0 keeps it off the horizon. */
soak_vec3 tu_upper_dir(tu_rng *r, double zmin);

/* i-th root (descending: i = 0 is the largest) of the Legendre polynomial
 * P_n, 0 <= i < n, by Newton iteration from Tricomi's initial guess;
 * *dpn receives P_n' at the root. */
double tu_legendre_root(int n, int i, double *dpn);
/* The first `count` nodes (descending) and weights of the n-point
 * Gauss-Legendre rule on [-1, 1]; count = n/2 gives the positive half. */
void tu_gauss_legendre_unit(int n, int count, double *x, double *w);
/* All n nodes and weights of the n-point Gauss-Legendre rule on [a, b],
 * nodes ascending. */
void tu_gauss_legendre(int n, double a, double b, double *x, double *w);

/* Unpolarised Fresnel reflectance from index n_i into n_t at incidence
 * cosine cos_i, in Fresnel's angle form
 * (sin^2(i-t)/sin^2(i+t) + tan^2(i-t)/tan^2(i+t)) / 2; 1 beyond the critical
 * angle, 0 for equal indices, ((n_t-n_i)/(n_t+n_i))^2 at normal incidence. */
double tu_fresnel_angle(double cos_i, double n_i, double n_t);

#endif
