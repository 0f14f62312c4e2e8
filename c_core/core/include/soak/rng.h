/* Small seedable random number generator for the Monte Carlo tracers.
 * PCG32 (M. E. O'Neill, "PCG: A Family of Simple Fast Space-Efficient
 * Statistically Good Algorithms for Random Number Generation", HMC-CS-2014-0905,
 * the XSH-RR output on a 64-bit LCG). State and stream selector are derived
 * from (seed, stream) through SplitMix64 (Steele, Lea, Flood, OOPSLA 2014) so
 * that neighbouring seeds and streams start far apart.
 *
 * Determinism: a tracer gives every path (or every pixel sample) its own
 * stream, soak_rng_seed(&rng, seed, path_index); results then depend only on
 * the seed, never on how paths are spread over threads.
 *
 * This header is shared by `soak measure` and the renderer: keep its output
 * sequence stable (tests and recorded runs rely on it). */
#ifndef SOAK_RNG_H
#define SOAK_RNG_H

#include <stdint.h>

typedef struct soak_rng {
    uint64_t state;
    uint64_t inc; /* odd LCG increment: selects the stream */
} soak_rng;

/* Any seed and stream are valid. */
void soak_rng_seed(soak_rng *rng, uint64_t seed, uint64_t stream);

/* Next 32 random bits. Inline: the tracers' walks draw several per step. */
static inline uint32_t soak_rng_u32(soak_rng *rng)
{
    uint64_t old = rng->state;
    rng->state = old * 6364136223846793005ull + rng->inc;
    uint32_t xorshifted = (uint32_t)(((old >> 18) ^ old) >> 27);
    uint32_t rot = (uint32_t)(old >> 59);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

/* Uniform double in [0, 1) with 53 random bits (two 32-bit draws); never 1. */
static inline double soak_rng_uniform(soak_rng *rng)
{
    uint64_t hi = soak_rng_u32(rng) >> 5; /* 27 bits */
    uint64_t lo = soak_rng_u32(rng) >> 6; /* 26 bits */
    return (double)((hi << 26) | lo) * (1.0 / 9007199254740992.0);
}

#endif
