/* Beach wetness left by the last waves ([JLD99], Jensen et al. 1999,
 * sec. 4.2: the beach wetness is "a sum of turbulence functions simulating
 * the water left from the four previous waves"; the paper gives no formula,
 * this is our model of it).
 *
 * Geometry: s = signed distance inland from the still-water line, a =
 * coordinate along the shore. Wave j (any integer) arrives at time j*period
 * and runs up to the front F_j(a) = reach_j + A fbm_j(a f), reach_j hashed
 * from (seed, j) in [reach_min, reach_max] and fbm_j an fBm of gradient noise
 * (gain 1/2, lacunarity 2) with its own seed: a turbulence-perturbed front.
 * Behind its soft front the wave leaves water that dries with its age and
 * drains faster further up the beach:
 *     w_j = smoothstep(0, edge, F_j - s) exp(-age_j / dry_time) exp(-s+ / dry_length).
 * Below the still-water line the sand is saturated; above it the capillary
 * fringe of the water table keeps b = exp(-s / fringe). Waters combine as
 * independent coverages, wetness = 1 - (1 - b) prod_j (1 - w_j), which stays
 * in [0, 1] and equals 1 at the water line. The oldest of the N waves fades
 * out linearly over the period before the next arrival so an animation does
 * not pop when it leaves the set. */
#include "soak/bake.h"

#include <math.h>
#include <stdlib.h>


void soak_waves_defaults(soak_waves_params *p)
{
    if (!p) return;
    p->seed = 0;
    p->waves = 4; /* [JLD99]: "the four previous waves" */
    p->direction_deg = 90;
    p->shore = -0.2;
    p->reach_min = 0.05;
    p->reach_max = 0.3;
    p->period = 8;
    p->dry_time = 20;
    p->dry_length = 0.5;
    p->fringe = 0.03;
    p->front_amplitude = 0.04;
    p->front_frequency = 3;
    p->front_octaves = 4;
    p->edge = 0.01;
    p->time = 0;
}

soak_status soak_waves_check(const soak_waves_params *p)
{
    if (!p) return SOAK_ERR_NULL;
    if (!(p->waves >= 1 && p->waves <= SOAK_WAVES_MAX_WAVES) ||
        !(p->front_octaves >= 1 && p->front_octaves <= SOAK_WAVES_MAX_FRONT_OCTAVES))
        return SOAK_ERR_ARG;
    const double len = SOAK_WAVES_MAX_LENGTH, dry_len = SOAK_WAVES_MAX_DRY_LENGTH;
    if (!soak_in_range(p->direction_deg, -SOAK_WAVES_MAX_DIRECTION, SOAK_WAVES_MAX_DIRECTION) ||
        !soak_in_range(p->shore, -len, len) || !soak_in_range(p->reach_min, 0, len) ||
        !soak_in_range(p->reach_max, p->reach_min, len) || !soak_in_range(p->period, 1e-9, SOAK_WAVES_MAX_PERIOD) ||
        !soak_in_range(p->dry_time, 1e-9, SOAK_WAVES_MAX_DRY_TIME) || !soak_in_range(p->dry_length, 1e-9, dry_len) ||
        !soak_in_range(p->fringe, 1e-9, dry_len) || !soak_in_range(p->front_amplitude, 0, len) ||
        !soak_in_range(p->front_frequency, 1e-9, SOAK_WAVES_MAX_FRONT_FREQUENCY) || !soak_in_range(p->edge, 0, len) ||
        !soak_in_range(p->time, -1e12, 1e12))
        return SOAK_ERR_ARG;
    /* Wave indices must fit in int32. */
    if (!(fabs(p->time / p->period) <= 1e9)) return SOAK_ERR_ARG;
    return SOAK_OK;
}

typedef struct wave {
    double reach, weight, dryness; /* dryness = exp(-age / dry_time) * fade weight */
    uint64_t seed;
} wave;

typedef struct wave_set {
    soak_waves_params p;
    double nx, ny; /* inland unit direction */
    double norm;   /* 1 / sum of fBm octave weights */
    int n;
    wave w[SOAK_WAVES_MAX_WAVES];
} wave_set;

static void make_set(const soak_waves_params *p, wave_set *S)
{
    S->p = *p;
    double th = p->direction_deg * (3.14159265358979323846 / 180);
    S->nx = cos(th);
    S->ny = sin(th);
    double sum = 0, amp = 1;
    for (int o = 0; o < p->front_octaves; ++o, amp *= 0.5) sum += amp;
    S->norm = 1 / sum;
    double latest = floor(p->time / p->period);
    double phase = p->time / p->period - latest; /* [0, 1) */
    S->n = p->waves;
    for (int k = 0; k < p->waves; ++k) {
        int32_t j = (int32_t)(latest - k);
        double age = p->time - (double)j * p->period;
        double fadeout = k == p->waves - 1 ? 1 - phase : 1;
        wave *w = &S->w[k];
        w->reach = p->reach_min + (p->reach_max - p->reach_min) * soak_hash_unit(p->seed, j, 0x5eed, 1);
        w->dryness = exp(-age / p->dry_time) * fadeout;
        w->seed = soak_seed_derive(p->seed, (uint64_t)(int64_t)j);
    }
}

static double front_offset(const wave_set *S, const wave *w, double along)
{
    if (S->p.front_amplitude == 0) return 0;
    double sum = 0, amp = 1, f = S->p.front_frequency;
    for (int o = 0; o < S->p.front_octaves; ++o, amp *= 0.5, f *= 2)
        sum += amp * soak_noise2(soak_seed_derive(w->seed, (uint64_t)o + 1), along * f, 0.5, 0, 0);
    return S->p.front_amplitude * sum * S->norm;
}

static double eval_set(const wave_set *S, double u, double v)
{
    const soak_waves_params *p = &S->p;
    double s = u * S->nx + v * S->ny - p->shore;
    if (s <= 0) return 1.0;
    double along = -u * S->ny + v * S->nx;
    double dry = exp(-s / p->fringe); /* 1 - dry accumulates below */
    dry = 1 - dry;
    double drain = exp(-s / p->dry_length);
    for (int k = 0; k < S->n; ++k) {
        const wave *w = &S->w[k];
        double front = w->reach + front_offset(S, w, along);
        double cover = soak_smoothstep(0, p->edge, front - s);
        if (cover > 0) dry *= 1 - cover * w->dryness * drain;
    }
    return fmin(1.0, fmax(0.0, 1 - dry));
}

soak_status soak_waves_eval(const soak_waves_params *p, double u, double v, double *wetness)
{
    if (!p || !wetness) return SOAK_ERR_NULL;
    soak_status st = soak_waves_check(p);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(u, -1e6, 1e6) || !soak_in_range(v, -1e6, 1e6)) return SOAK_ERR_ARG;
    wave_set S;
    make_set(p, &S);
    *wetness = eval_set(&S, u, v);
    return SOAK_OK;
}

typedef struct waves_ctx {
    const wave_set *S;
    int width, height;
    float *out;
} waves_ctx;

static void waves_row(void *vctx, int row, int thread)
{
    (void)thread;
    waves_ctx *c = vctx;
    double inv = 1.0 / c->width;
    double v = (row + 0.5) * inv - 0.5 * c->height * inv;
    float *dst = c->out + (size_t)row * c->width;
    for (int i = 0; i < c->width; ++i) dst[i] = (float)eval_set(c->S, (i + 0.5) * inv - 0.5, v);
}

soak_status soak_bake_waves(const soak_waves_params *p, int width, int height, const soak_bake_exec *exec,
                            soak_image *out)
{
    if (!p || !out) return SOAK_ERR_NULL;
    soak_status st = soak_waves_check(p);
    if (st != SOAK_OK) return st;
    if (soak_bake_check_size(width, height) != SOAK_OK || soak_bake_threads(exec) == 0) return SOAK_ERR_ARG;
    wave_set *S = malloc(sizeof *S);
    if (!S) return SOAK_ERR_NOMEM;
    make_set(p, S);
    if ((st = soak_image_alloc(out, width, height, 1)) != SOAK_OK) {
        free(S);
        return st;
    }
    waves_ctx c = {S, width, height, out->pixels};
    st = soak_parallel_rows(height, exec, waves_row, &c, 0, 1);
    free(S);
    if (st != SOAK_OK) soak_image_free(out);
    return st;
}
