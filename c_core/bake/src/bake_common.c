/* Shared plumbing of the bakers: parallel rows, hashing, smoothstep, output
 * writing and image-sequence paths. See soak/bake.h. */
#define _POSIX_C_SOURCE 200809L
#include "soak/bake.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "soak/hash.h"
#include "soak/io_guard.h"
#include "soak/staged.h"

int soak_bake_threads(const soak_bake_exec *exec)
{
    int n = exec ? exec->threads : 0;
    if (n == 0) {
        long cores = sysconf(_SC_NPROCESSORS_ONLN);
        n = cores < 1 ? 1 : (cores > SOAK_BAKE_MAX_THREADS ? SOAK_BAKE_MAX_THREADS : (int)cores);
    }
    return (n >= 1 && n <= SOAK_BAKE_MAX_THREADS) ? n : 0;
}

typedef struct rows_job {
    int rows;
    soak_row_fn fn;
    void *ctx;
    atomic_int next; /* next row to hand out */
    atomic_int done; /* rows finished */
} rows_job;

typedef struct rows_worker {
    rows_job *job;
    int thread;
} rows_worker;

static void run_rows(rows_job *job, int thread, const soak_bake_exec *exec, double lo, double hi)
{
    for (;;) {
        int row = atomic_fetch_add(&job->next, 1);
        if (row >= job->rows) break;
        job->fn(job->ctx, row, thread);
        int done = atomic_fetch_add(&job->done, 1) + 1;
        /* Only the calling thread reports, so callbacks need no locking. */
        if (exec && exec->progress) exec->progress(exec->progress_user, lo + (hi - lo) * done / job->rows);
    }
}

static void *worker_main(void *arg)
{
    rows_worker *w = arg;
    run_rows(w->job, w->thread, NULL, 0, 0);
    return NULL;
}

soak_status soak_parallel_rows(int rows, const soak_bake_exec *exec, soak_row_fn fn, void *ctx, double progress_lo,
                               double progress_hi)
{
    if (!fn) return SOAK_ERR_NULL;
    int threads = soak_bake_threads(exec);
    if (threads == 0 || rows < 0 || !soak_in_range(progress_lo, 0, 1) || !soak_in_range(progress_hi, 0, 1))
        return SOAK_ERR_ARG;
    if (threads > rows) threads = rows > 0 ? rows : 1;
    rows_job job;
    job.rows = rows;
    job.fn = fn;
    job.ctx = ctx;
    atomic_init(&job.next, 0);
    atomic_init(&job.done, 0);
    pthread_t tid[SOAK_BAKE_MAX_THREADS];
    rows_worker workers[SOAK_BAKE_MAX_THREADS];
    int started = 0;
    for (int t = 1; t < threads; ++t) {
        workers[t].job = &job;
        workers[t].thread = t;
        /* A thread that cannot start only means fewer helpers: rows are
         * handed out dynamically, the results do not depend on it. */
        if (pthread_create(&tid[started], NULL, worker_main, &workers[t]) != 0) break;
        ++started;
    }
    run_rows(&job, 0, exec, progress_lo, progress_hi);
    for (int t = 0; t < started; ++t) pthread_join(tid[t], NULL);
    if (exec && exec->progress) exec->progress(exec->progress_user, progress_hi);
    return SOAK_OK;
}

soak_status soak_bake_check_size(int width, int height)
{
    return (width >= 1 && width <= SOAK_BAKE_MAX_SIZE && height >= 1 && height <= SOAK_BAKE_MAX_SIZE) ? SOAK_OK
                                                                                                  : SOAK_ERR_ARG;
}

uint32_t soak_hash3(uint64_t seed, int32_t a, int32_t b, int32_t c)
{
    return soak_hash_key3(soak_seed_key(seed), a, b, c);
}

double soak_hash_unit(uint64_t seed, int32_t a, int32_t b, int32_t c)
{
    return soak_hash3(seed, a, b, c) * (1.0 / 4294967296.0);
}

/* SplitMix64 finaliser (Steele, Lea, Flood, OOPSLA 2014). */
static uint64_t splitmix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

uint64_t soak_seed_derive(uint64_t seed, uint64_t index)
{
    return splitmix64(seed ^ splitmix64(index + 0x632be59bd9b4e019ULL));
}

double soak_smoothstep(double e0, double e1, double x)
{
    if (!(e1 > e0)) return x >= e0 ? 1.0 : 0.0;
    double u = (x - e0) / (e1 - e0);
    if (!(u > 0)) return 0.0;
    if (u >= 1) return 1.0;
    return u * u * (3 - 2 * u);
}

static const char *extension_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(path, '.');
    if (!dot || (slash && dot < slash)) return "";
    return dot + 1;
}

static int supported_extension(const char *ext)
{
    static const char *const ok[] = {"exr", "png", "tif", "tiff", "tx"};
    for (size_t i = 0; i < sizeof ok / sizeof ok[0]; ++i)
        if (strcasecmp(ext, ok[i]) == 0) return 1;
    return 0;
}

soak_status soak_bake_stage(soak_staged *stage, const char *path, const soak_image *img, int float_exr, char *err,
                            size_t errlen)
{
    if (!stage || !path || !img || !img->pixels) return SOAK_ERR_NULL;
    soak_status st = soak_path_check_writable(path, err, errlen);
    if (st != SOAK_OK) return st;
    const char *ext = extension_of(path);
    if (!supported_extension(ext)) {
        if (err && errlen) snprintf(err, errlen, "%s: unsupported output type (use .exr, .png, .tif or .tx)", path);
        return SOAK_ERR_ARG;
    }
    if (strcasecmp(ext, "tx") == 0) return soak_image_stage_tx(stage, path, img, err, errlen);
    soak_image_write_opts opts = {SOAK_TONE_LINEAR, SOAK_PIXEL_AUTO};
    if (strcasecmp(ext, "exr") == 0) opts.pixel_type = float_exr ? SOAK_PIXEL_FLOAT : SOAK_PIXEL_HALF;
    else opts.pixel_type = SOAK_PIXEL_UINT16;
    return soak_image_stage(stage, path, img, &opts, err, errlen);
}

soak_status soak_bake_write(const char *path, const soak_image *img, int float_exr, char *err, size_t errlen)
{
    soak_staged stage;
    soak_staged_init(&stage);
    soak_status st = soak_bake_stage(&stage, path, img, float_exr, err, errlen);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return st;
    }
    return soak_staged_commit(&stage, err, errlen);
}

/* Finds the single integer conversion of a pattern. Returns the number of
 * conversions (or -1 if malformed); *at, *len, *width, *zero describe it. */
static int scan_pattern(const char *p, size_t *at, size_t *len, int *width, int *zero)
{
    int count = 0;
    for (size_t i = 0; p[i]; ++i) {
        if (p[i] != '%') continue;
        if (p[i + 1] == '%') {
            ++i;
            continue;
        }
        size_t j = i + 1;
        int z = 0, w = 0;
        if (p[j] == '0') {
            z = 1;
            ++j;
        }
        while (p[j] >= '0' && p[j] <= '9') {
            w = w * 10 + (p[j] - '0');
            if (w > 12) return -1;
            ++j;
        }
        if (p[j] != 'd') return -1;
        ++count;
        *at = i;
        *len = j + 1 - i;
        *width = w;
        *zero = z;
        i = j;
    }
    return count > 1 ? -1 : count;
}

int soak_bake_pattern_kind(const char *pattern)
{
    if (!pattern) return -1;
    size_t at = 0, len = 0;
    int width = 0, zero = 0;
    return scan_pattern(pattern, &at, &len, &width, &zero);
}

soak_status soak_bake_frame_path(const char *pattern, int frame, char *out, size_t outlen)
{
    if (!pattern || !out) return SOAK_ERR_NULL;
    if (!(frame >= 0 && frame <= 9999999) || outlen == 0) return SOAK_ERR_ARG;
    size_t at = 0, len = 0;
    int width = 0, zero = 0;
    if (scan_pattern(pattern, &at, &len, &width, &zero) != 1) return SOAK_ERR_ARG;
    char number[32];
    snprintf(number, sizeof number, zero ? "%0*d" : "%*d", width, frame);
    size_t o = 0;
    for (size_t i = 0; pattern[i]; ++i) {
        const char *piece;
        char one[2] = {pattern[i], 0};
        if (i == at) {
            piece = number;
            i += len - 1;
        } else if (pattern[i] == '%') {
            piece = "%"; /* "%%" */
            ++i;
        } else {
            piece = one;
        }
        size_t n = strlen(piece);
        if (o + n + 1 > outlen) return SOAK_ERR_ARG;
        memcpy(out + o, piece, n);
        o += n;
    }
    out[o] = '\0';
    return SOAK_OK;
}

soak_status soak_bake_check_output(const char *path, const char *const *inputs, int n_inputs, char *err,
                                   size_t errlen)
{
    if (!path || (n_inputs > 0 && !inputs)) return SOAK_ERR_NULL;
    soak_status st = soak_path_check_writable(path, err, errlen);
    if (st == SOAK_ERR_ARG) return st;
    if (!supported_extension(extension_of(path))) {
        if (err && errlen) snprintf(err, errlen, "%s: unsupported output type (use .exr, .png, .tif or .tx)", path);
        return SOAK_ERR_ARG;
    }
    st = soak_io_check_output("output", path, inputs, n_inputs, err, errlen);
    if (st != SOAK_OK) return st;
    return soak_path_check_writable(path, err, errlen);
}
