/* Randomised quasi-Monte Carlo for the first RT_QMC_DIMS random numbers of
 * every camera path: dimension pairs of an Owen-scrambled Sobol (0,2)
 * sequence, padded (each pair gets its own scramble and its own shuffle of
 * the sample order), then the path's PCG stream for the rest.
 *
 * Sources (facts and constants, not code): the first two Sobol dimensions
 * (I. M. Sobol 1967; direction numbers v_k = 2^{31-k} and v_1 = 2^31,
 * v_{k+1} = v_k ^ (v_k >> 1)); Owen scrambling as a nested uniform scramble
 * built from the Laine-Karras hash, with its four multipliers, and the
 * padding by scrambling the sample index: B. Burley, "Practical Hash-based
 * Owen Scrambling", JCGT 9(4), 2020. Cycles' Sobol-Burley sampler and
 * pbrt-v4's padded Sobol sampler use the same construction.
 *
 * Unbiasedness: with a random scramble every point is uniform in [0,1)^d,
 * so each sample still has the expectation of plain Monte Carlo; only the
 * correlation between the samples of a pixel changes (their strata). Renders
 * with different seeds are independent, which the tests' standard errors
 * rely on. Values lie on the 2^-32 grid in [0, 1 - 2^-32]: enough for the
 * pixel, lobe and direction choices they serve (the walk's free flights,
 * whose logarithm needs the 2^-53 grid, draw from the PCG stream). */
#include "soak/hash.h"
#include "rt_ctx.h"

static uint32_t reverse_bits(uint32_t x)
{
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
    x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
    return (x >> 16) | (x << 16);
}

/* Sobol dimension 1 before its bit reversal (dimension 0 is the index
 * itself): the direction numbers v_1 = 2^31, v_{k+1} = v_k ^ (v_k >> 1) are
 * the rows of Pascal's triangle mod 2, so bit j of the reversed result is
 * the parity of the index's set bits k with j a subset of k (Lucas), a
 * superset sum over the five bit levels. Equal to the XOR of the direction
 * numbers of the set bits, reversed, for every index tried (10^8, the first
 * 2^24 among them): one step per level instead of one per set bit. */
static uint32_t sobol_second_reversed(uint32_t y)
{
    y ^= (y >> 1) & 0x55555555u;
    y ^= (y >> 2) & 0x33333333u;
    y ^= (y >> 4) & 0x0F0F0F0Fu;
    y ^= (y >> 8) & 0x00FF00FFu;
    y ^= (y >> 16) & 0x0000FFFFu;
    return y;
}

/* Laine-Karras style hash: each bit is flipped depending only on the bits
 * below it, i.e. a random permutation that respects the dyadic strata of
 * the reversed number. */
static uint32_t lk_permute(uint32_t x, uint32_t seed)
{
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

static uint32_t owen_scramble(uint32_t x, uint32_t seed) { return reverse_bits(lk_permute(reverse_bits(x), seed)); }

/* owen_scramble of a number given bit-reversed: the two reversals cancel. */
static uint32_t owen_scramble_reversed(uint32_t rx, uint32_t seed) { return reverse_bits(lk_permute(rx, seed)); }

static uint32_t hash2(uint32_t a, uint32_t b) { return soak_mix32(a ^ soak_mix32(b + 0x9e3779b9u)); }

void rt_qmc_start(rt_thread *t, uint64_t seed, uint64_t pixel, uint32_t sample)
{
    t->qmc.seed = hash2((uint32_t)(seed ^ (seed >> 32)), hash2((uint32_t)pixel, (uint32_t)(pixel >> 32)));
    t->qmc.index = sample;
    t->qmc.dim = 0;
    t->qmc.end = RT_QMC_DIMS;
}

double rt_qmc_next(rt_thread *t)
{
    int d = t->qmc.dim++;
    if (!(d & 1)) { /* a new pair: one shuffled index and two scramble seeds for its coordinates */
        uint32_t pair_seed = hash2(t->qmc.seed, (uint32_t)(d >> 1));
        t->qmc.pair_index = owen_scramble(t->qmc.index, pair_seed); /* padding: each pair its own order */
        t->qmc.seed_x = hash2(pair_seed, 1u);
        t->qmc.seed_y = hash2(pair_seed, 2u);
    }
    uint32_t i = t->qmc.pair_index;
    uint32_t x = (d & 1) ? owen_scramble_reversed(sobol_second_reversed(i), t->qmc.seed_y) : owen_scramble_reversed(i, t->qmc.seed_x);
    return (double)x * (1.0 / 4294967296.0);
}

void rt_rand2(rt_thread *t, double *u1, double *u2)
{
    if (t->qmc.dim < t->qmc.end && (t->qmc.dim & 1)) t->qmc.dim++; /* start a fresh pair */
    *u1 = rt_rand(t);
    *u2 = rt_rand(t);
}
