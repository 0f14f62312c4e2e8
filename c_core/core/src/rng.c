/* PCG32 with SplitMix64 seeding; see soak/rng.h for sources. */
#include "soak/rng.h"

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

void soak_rng_seed(soak_rng *rng, uint64_t seed, uint64_t stream)
{
    uint64_t mix = seed ^ (stream * 0xD1B54A32D192ED03ull);
    uint64_t s0 = splitmix64(&mix);
    uint64_t s1 = splitmix64(&mix);
    rng->state = 0;
    rng->inc = (s1 << 1) | 1u;
    (void)soak_rng_u32(rng);
    rng->state += s0;
    (void)soak_rng_u32(rng);
}

