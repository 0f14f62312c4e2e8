/* Virtual gonio-reflectometer: see soak/measure.h. Every path is traced
 * through the geometry with soak_medium_walk; nothing here knows a closed
 * form. */
#include "soak/measure.h"

#include "measure_internal.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>

#include "soak/film.h"
#include "soak/fresnel.h"
#include "soak/medium.h"
#include "soak/rng.h"

#define BLOCK_PATHS 1024

void soak_measure_setup_default(soak_measure_setup *s)
{
    s->config = SOAK_MEASURE_HALFSPACE;
    s->quantity = SOAK_MEASURE_R;
    s->diffuse_incidence = 0;
    s->cos_incidence = 1.0;
    s->ior = 1.0;
    s->base_albedo = 0.5;
    s->film_alpha = 0.0;
    s->film_thickness = 0.0;
    s->coat_ior = 1.5;
    s->coat_alpha = 0.1;
    s->coat_weight = 1.0;
    s->albedo = 1.0;
    s->phase.g1 = 0.0;
    s->phase.g2 = 0.0;
    s->phase.w = 1.0;
    s->tau = 1.0;
    s->paths = 1000000;
    s->seed = 1;
    s->threads = 1;
    s->max_events = 1000000;
    s->roulette = 1;
    s->progress = NULL;
    s->progress_ctx = NULL;
}

soak_status soak_measure_validate(const soak_measure_setup *s)
{
    if (!s) return SOAK_ERR_NULL;
    if (s->config != SOAK_MEASURE_FILM && s->config != SOAK_MEASURE_HALFSPACE && s->config != SOAK_MEASURE_SLAB &&
        s->config != SOAK_MEASURE_COATED)
        return SOAK_ERR_ARG;
    if (s->quantity != SOAK_MEASURE_R && s->quantity != SOAK_MEASURE_T) return SOAK_ERR_ARG;
    if (s->quantity == SOAK_MEASURE_T && s->config != SOAK_MEASURE_SLAB) return SOAK_ERR_ARG;
    if (s->diffuse_incidence != 0 && s->diffuse_incidence != 1) return SOAK_ERR_ARG;
    if (!s->diffuse_incidence && !(s->cos_incidence > 0.0 && s->cos_incidence <= 1.0)) return SOAK_ERR_ARG;
    if (!soak_in_range(s->ior, SOAK_MEASURE_MIN_IOR, SOAK_MEASURE_MAX_IOR)) return SOAK_ERR_ARG;
    if (s->paths < 1 || s->paths > SOAK_MEASURE_MAX_PATHS || s->threads < 1 || s->threads > SOAK_MEASURE_MAX_THREADS ||
        s->max_events < 1)
        return SOAK_ERR_ARG;
    if (s->roulette != 0 && s->roulette != 1) return SOAK_ERR_ARG;
    if (s->config == SOAK_MEASURE_FILM || s->config == SOAK_MEASURE_COATED) {
        if (!soak_in_range(s->base_albedo, 0.0, 1.0) || !soak_in_range(s->film_alpha, 0.0, SOAK_FILM_MAX_ALPHA) ||
            !soak_in_range(s->film_thickness, 0.0, SOAK_FILM_MAX_THICKNESS))
            return SOAK_ERR_ARG;
        if (s->config == SOAK_MEASURE_COATED &&
            (!soak_in_range(s->coat_ior, SOAK_MEASURE_MIN_IOR, SOAK_MEASURE_MAX_IOR) ||
             !soak_in_range(s->coat_alpha, 1e-4, 1.0) || !soak_in_range(s->coat_weight, 0.0, 1.0)))
            return SOAK_ERR_ARG;
        return SOAK_OK;
    }
    if (!soak_in_range(s->albedo, 0.0, 1.0)) return SOAK_ERR_ARG;
    if (s->config == SOAK_MEASURE_SLAB && !(s->tau > 0.0 && s->tau <= SOAK_MEASURE_MAX_TAU)) return SOAK_ERR_ARG;
    return soak_hg2_validate(&s->phase);
}

/* What every worker shares (read-only except the atomics and its own block
 * slots). */
typedef struct job {
    const soak_measure_setup *setup;
    soak_medium medium;
    soak_slab_boundary slab;
    soak_boundary boundary;
    soak_walk_options opt;
    long long nblocks;
    long long round_start, round_end; /* blocks of the current round */
    atomic_llong next_block;
    atomic_llong done_blocks;
    atomic_int failed; /* first soak_status != OK, as int */
    double *sums;      /* per block of the round: R, R^2, T, T^2, capped weight, events, capped */
} job;

#define NSUM 7
/* Blocks are summed in path order round by round, which bounds the memory
 * for any path count and keeps the sum independent of the thread count. */
#define ROUND_BLOCKS 16384

/* Direction of the incident photon (propagating downwards). */
static soak_vec3 incident_direction(const soak_measure_setup *s, soak_rng *rng)
{
    double c = s->diffuse_incidence ? sqrt(soak_rng_uniform(rng)) : s->cos_incidence;
    if (s->diffuse_incidence && c == 0.0) c = 1e-300; /* u = 0: grazing limit, weightless */
    double phi = 2.0 * SOAK_PI * soak_rng_uniform(rng);
    double sn = sqrt(fmax(0.0, 1.0 - c * c));
    return soak_v3(sn * cos(phi), sn * sin(phi), -c);
}

/* One path: returns its reflected and transmitted weight. */
static soak_status trace_path(job *jb, soak_rng *rng, double *r_out, double *t_out, double *capped_w,
                              long *events, int *capped)
{
    const soak_measure_setup *s = jb->setup;
    soak_vec3 d = incident_direction(s, rng);
    *r_out = *t_out = *capped_w = 0.0;
    *events = 0;
    *capped = 0;
    if (s->config == SOAK_MEASURE_COATED) return measure_coated_path(s, d, rng, r_out, events, capped);
    if (s->ior != 1.0) {
        /* Air to medium: eta = ior. */
        double cos_t;
        double R = soak_fresnel_dielectric_raw(-d.z, s->ior, &cos_t);
        if (soak_rng_uniform(rng) < R) {
            *r_out = 1.0; /* specular reflection at the top surface */
            return SOAK_OK;
        }
        d = soak_v3_norm(soak_v3(d.x / s->ior, d.y / s->ior, -cos_t));
    }
    soak_walk_result w;
    soak_status st = soak_medium_walk(&jb->medium, &jb->opt, soak_v3(0, 0, 0), d, &jb->boundary, rng, &w);
    if (st != SOAK_OK) return st;
    *events = w.events;
    if (w.end == SOAK_WALK_EXITED) {
        if (w.dir.z > 0.0)
            *r_out = w.weight;
        else
            *t_out = w.weight;
    } else if (w.end == SOAK_WALK_CAPPED) {
        *capped = 1;
        *capped_w = w.weight;
    }
    return SOAK_OK;
}

static void run_block(job *jb, long long b)
{
    const soak_measure_setup *s = jb->setup;
    long long first = b * BLOCK_PATHS;
    long long last = first + BLOCK_PATHS < s->paths ? first + BLOCK_PATHS : s->paths;
    double acc[NSUM] = {0};
    for (long long i = first; i < last; ++i) {
        soak_rng rng;
        soak_rng_seed(&rng, s->seed, (uint64_t)i);
        double r, t, cw;
        long ev;
        int capped;
        soak_status st = trace_path(jb, &rng, &r, &t, &cw, &ev, &capped);
        if (st != SOAK_OK) {
            int expected = 0;
            atomic_compare_exchange_strong(&jb->failed, &expected, (int)st);
            return;
        }
        acc[0] += r;
        acc[1] += r * r;
        acc[2] += t;
        acc[3] += t * t;
        acc[4] += cw;
        acc[5] += (double)ev;
        acc[6] += capped;
    }
    for (int k = 0; k < NSUM; ++k) jb->sums[(b - jb->round_start) * NSUM + k] = acc[k];
}

static void *worker(void *arg)
{
    job *jb = arg;
    for (;;) {
        if (atomic_load(&jb->failed)) break;
        long long b = atomic_fetch_add(&jb->next_block, 1);
        if (b >= jb->round_end) break;
        run_block(jb, b);
        atomic_fetch_add(&jb->done_blocks, 1);
    }
    return NULL;
}

static void mean_and_error(double sum, double sum2, double n, double *mean, double *err)
{
    double m = sum / n;
    double var = n > 1 ? (sum2 / n - m * m) * n / (n - 1) : 0.0;
    *mean = m;
    *err = var > 0.0 ? sqrt(var / n) : 0.0;
}

static soak_status setup_job(const soak_measure_setup *s, job *jb)
{
    jb->setup = s;
    soak_walk_options_default(&jb->opt);
    jb->opt.roulette = s->roulette;
    jb->opt.max_events = s->max_events;
    jb->medium.density = NULL;
    jb->medium.density_ctx = NULL;
    jb->slab.ior = s->ior;
    jb->slab.base_albedo = 0.0;
    jb->slab.diffuse_base = 0;
    if (s->config == SOAK_MEASURE_FILM || s->config == SOAK_MEASURE_COATED) {
        /* A purely absorbing layer over the base; geometry matters only
         * through absorption, so a non-absorbing film gets unit thickness. */
        int absorbing = s->film_alpha > 0.0 && s->film_thickness > 0.0;
        jb->medium.sigma_t = absorbing ? s->film_alpha : 0.0;
        jb->medium.albedo = 0.0;
        jb->medium.phase = (soak_hg2){0.0, 0.0, 1.0};
        jb->slab.thickness = absorbing ? s->film_thickness : 1.0;
        jb->slab.diffuse_base = 1;
        jb->slab.base_albedo = s->base_albedo;
    } else {
        jb->medium.sigma_t = 1.0;
        jb->medium.albedo = s->albedo;
        jb->medium.phase = s->phase;
        jb->slab.thickness = s->config == SOAK_MEASURE_SLAB ? s->tau : INFINITY;
    }
    return soak_slab_boundary_make(&jb->slab, &jb->boundary);
}

soak_status soak_measure_run(const soak_measure_setup *s, soak_measure_result *out)
{
    if (!s || !out) return SOAK_ERR_NULL;
    soak_status st = soak_measure_validate(s);
    if (st != SOAK_OK) return st;
    job *jb = calloc(1, sizeof *jb);
    if (!jb) return SOAK_ERR_NOMEM;
    if ((st = setup_job(s, jb)) != SOAK_OK) {
        free(jb);
        return st;
    }
    jb->nblocks = (s->paths + BLOCK_PATHS - 1) / BLOCK_PATHS;
    long long round_blocks = jb->nblocks < ROUND_BLOCKS ? jb->nblocks : ROUND_BLOCKS;
    atomic_init(&jb->next_block, 0);
    atomic_init(&jb->done_blocks, 0);
    atomic_init(&jb->failed, 0);
    jb->sums = calloc((size_t)round_blocks * NSUM, sizeof(double));
    int nthreads = s->threads;
    if ((long long)nthreads > round_blocks) nthreads = (int)round_blocks;
    pthread_t *tids = calloc((size_t)nthreads, sizeof(pthread_t));
    if (!jb->sums || !tids) {
        free(jb->sums);
        free(tids);
        free(jb);
        return SOAK_ERR_NOMEM;
    }
    double tot[NSUM] = {0};
    for (jb->round_start = 0; jb->round_start < jb->nblocks && !atomic_load(&jb->failed);
         jb->round_start += ROUND_BLOCKS) {
        jb->round_end = jb->round_start + ROUND_BLOCKS < jb->nblocks ? jb->round_start + ROUND_BLOCKS : jb->nblocks;
        atomic_store(&jb->next_block, jb->round_start);
        int started = 0;
        for (int i = 1; i < nthreads; ++i) {
            if (pthread_create(&tids[i], NULL, worker, jb) != 0) break;
            ++started;
        }
        /* The calling thread works too and is the only one reporting progress. */
        for (;;) {
            if (atomic_load(&jb->failed)) break;
            long long b = atomic_fetch_add(&jb->next_block, 1);
            if (b >= jb->round_end) break;
            run_block(jb, b);
            long long done = atomic_fetch_add(&jb->done_blocks, 1) + 1;
            if (s->progress && done < jb->nblocks) s->progress(s->progress_ctx, (double)done / (double)jb->nblocks);
        }
        for (int i = 1; i <= started; ++i) pthread_join(tids[i], NULL);
        for (long long b = 0; b < jb->round_end - jb->round_start; ++b)
            for (int k = 0; k < NSUM; ++k) tot[k] += jb->sums[b * NSUM + k];
    }
    if (s->progress) s->progress(s->progress_ctx, 1.0);

    st = (soak_status)atomic_load(&jb->failed);
    if (st == SOAK_OK) {
        double n = (double)s->paths;
        soak_measure_result r;
        mean_and_error(tot[0], tot[1], n, &r.reflectance, &r.reflectance_err);
        mean_and_error(tot[2], tot[3], n, &r.transmittance, &r.transmittance_err);
        r.value = s->quantity == SOAK_MEASURE_T ? r.transmittance : r.reflectance;
        r.std_error = s->quantity == SOAK_MEASURE_T ? r.transmittance_err : r.reflectance_err;
        r.paths = s->paths;
        r.capped_weight = tot[4] / n;
        r.mean_events = tot[5] / n;
        r.capped = (long long)tot[6];
        if (!soak_is_finite(r.value) || !soak_is_finite(r.std_error) || !soak_is_finite(r.capped_weight))
            st = SOAK_ERR_NUMERIC;
        else
            *out = r;
    }
    free(tids);
    free(jb->sums);
    free(jb);
    return st;
}
