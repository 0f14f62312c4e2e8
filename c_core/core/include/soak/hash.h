/* Inline hashing shared by the bakers and the render sampler (private to
 * libsoak and its tests).
 * lowbias32 finaliser: C. Wellons, "Prospecting for hash functions" (2018),
 * constants 0x7feb352d / 0x846ca68b; bias ~0.17 on the avalanche test. The
 * coordinates are chained one at a time so lattice neighbours decorrelate. */
#ifndef SOAK_HASH_H
#define SOAK_HASH_H

#include <stdint.h>

static inline uint32_t soak_mix32(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

/* 32-bit key of a 64-bit seed; hash chains start from it. */
static inline uint32_t soak_seed_key(uint64_t seed)
{
    return soak_mix32((uint32_t)seed ^ soak_mix32((uint32_t)(seed >> 32) + 0x9e3779b9U));
}

static inline uint32_t soak_hash_key2(uint32_t key, int32_t a, int32_t b)
{
    return soak_mix32(soak_mix32(key ^ (uint32_t)a) + (uint32_t)b);
}

static inline uint32_t soak_hash_key3(uint32_t key, int32_t a, int32_t b, int32_t c)
{
    return soak_mix32(soak_mix32(soak_mix32(key ^ (uint32_t)a) + (uint32_t)b) ^ (uint32_t)c);
}

#endif
