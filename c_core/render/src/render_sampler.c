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
#include "render_internal.h"

static uint32_t reverse_bits(uint32_t x)
{
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
    x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
    return (x >> 16) | (x << 16);
}

/* Sobol dimension 1 (dimension 0 is reverse_bits): XOR of the direction
 * numbers v_1 = 2^31, v_{k+1} = v_k ^ (v_k >> 1) of the index's set bits. */
static uint32_t sobol_second(uint32_t index)
{
    static const uint32_t v[32] = {
        0x80000000u, 0xc0000000u, 0xa0000000u, 0xf0000000u, 0x88000000u, 0xcc000000u, 0xaa000000u, 0xff000000u,
        0x80800000u, 0xc0c00000u, 0xa0a00000u, 0xf0f00000u, 0x88880000u, 0xcccc0000u, 0xaaaa0000u, 0xffff0000u,
        0x80008000u, 0xc000c000u, 0xa000a000u, 0xf000f000u, 0x88008800u, 0xcc00cc00u, 0xaa00aa00u, 0xff00ff00u,
        0x80808080u, 0xc0c0c0c0u, 0xa0a0a0a0u, 0xf0f0f0f0u, 0x88888888u, 0xccccccccu, 0xaaaaaaaau, 0xffffffffu};
    uint32_t r = 0;
    for (; index; index &= index - 1) r ^= v[__builtin_ctz(index)];
    return r;
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
    uint32_t x = (d & 1) ? owen_scramble(sobol_second(i), t->qmc.seed_y) : owen_scramble(reverse_bits(i), t->qmc.seed_x);
    return (double)x * (1.0 / 4294967296.0);
}

void rt_rand2(rt_thread *t, double *u1, double *u2)
{
    if (t->qmc.dim < t->qmc.end && (t->qmc.dim & 1)) t->qmc.dim++; /* start a fresh pair */
    *u1 = rt_rand(t);
    *u2 = rt_rand(t);
}
