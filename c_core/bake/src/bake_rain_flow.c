/* Fused downhill-flow sweeps of the rain bake (bake_rain_flow.h). */
#include "bake_rain_flow.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "soak/vec.h"

#include "bake_rain_flow_rows.h"
#include "bake_rain_stream.h"

/* SOAK_RAIN_DX and _DY as constants the compiler folds into unrolled loops. */
static const int FLOW_DX[8] = SOAK_RAIN_DX_INIT, FLOW_DY[8] = SOAK_RAIN_DY_INIT;

/* Rows per task; each task also computes the outflows of one row either
 * side of its band, so wider bands repeat less work. */
enum { BAND = 32 };

struct soak_rain_flow_plan {
    soak_rain_flow_grid g;
    int threads;
    flux_row_fn flux_row; /* the vector kernels, or NULL */
    gather_row_fn gather_row;
    unsigned char *pulls;
    double *next;
    double *lvl_mem, *lvl_next_mem; /* with the w + 1 zeros either side (flow_job) */
    float *ring_o;
    double *ring_out;
};

/* The routing's split (soak/bake_rain.h step 3, [Qui91]) of what leaves
 * texel i at level lvl with depth h, its neighbours at levels nb: diff[d]
 * the level drop to 3D-adjacent neighbour d (0 if none or uphill), diff[8]
 * the drop to a virtual dry neighbour beyond an open edge; their sum and
 * largest. The sweeps and the steady discharge share it. */
static void route_drops(const soak_rain_flow_grid *g, size_t i, double lvl, const double nb[8], double h,
                        double diff[9], double *sum_out, double *max_out)
{
    double sum = 0.0, mx = 0.0;
    for (int d = 0; d < 8; ++d) { /* adj says which neighbours count */
        double dl = lvl - nb[d];
        diff[d] = (g->adj[i] >> d & 1u) && dl > 0.0 ? dl : 0.0;
    }
    diff[8] = g->drip[i] > 0.0f ? h + g->drip[i] : 0.0;
    for (int d = 0; d < 9; ++d) { /* diff >= 0, never NaN: comparisons give fmax / fmin's values */
        sum += diff[d];
        mx = diff[d] > mx ? diff[d] : mx;
    }
    *sum_out = sum;
    *max_out = mx;
}

static void texel_flux(const flow_job *j, const flux_row_ptrs *row, int x, int y)
{
    const soak_rain_flow_grid *g = j->g;
    size_t i = (size_t)y * g->w + x;
    for (int d = 0; d < 8; ++d) row->o[d][x] = 0.0f;
    row->out[x] = 0.0;
    if (!g->covered[i]) return;
    double h = j->depth[i], mobile = h - g->retain[i];
    if (!(mobile > 0.0)) return;
    if (g->drip[i] < 0.0f) { /* faces down: everything drips, nothing to the neighbours */
        row->out[x] = (float)mobile;
        return;
    }
    double nb[8], diff[9], sum, mx;
    for (int d = 0; d < 8; ++d) nb[d] = j->lvl[(ptrdiff_t)i + j->step[d]]; /* the padding makes all loadable */
    route_drops(g, i, j->lvl[i], nb, h, diff, &sum, &mx);
    if (!(sum > 0.0)) return;
    double moved = 0.5 * mx < mobile ? 0.5 * mx : mobile, out = 0.0;
    /* A direction without a level drop sends moved * 0 / sum = +0, which was
     * written above and adds nothing to out (>= +0): skipping its division
     * leaves every bit as it was. */
    for (int d = 0; d < 8; ++d) {
        if (!(diff[d] > 0.0)) continue;
        row->o[d][x] = (float)(moved * diff[d] / sum);
        out += row->o[d][x];
    }
    row->out[x] = diff[8] > 0.0 ? out + (float)(moved * diff[8] / sum) : out;
}

static void ring_row(const flow_job *j, int thread, int y, flux_row_ptrs *row)
{
    size_t w = (size_t)j->g->w, slot = (size_t)thread * 3 + (size_t)(y % 3);
    for (int d = 0; d < 8; ++d) row->o[d] = j->ring_o + (slot * 8 + (size_t)d) * w;
    row->out = j->ring_out + slot * w;
}

static void flux_row(const flow_job *j, int thread, int y)
{
    flux_row_ptrs row;
    ring_row(j, thread, y, &row);
    int x = j->flux_row ? j->flux_row(j, &row, y, 0) : 0;
    for (; x < j->g->w; ++x) texel_flux(j, &row, x, y);
}

static void texel_gather(const flow_job *j, const flux_row_ptrs fr[3], const float *const ar[3], int x, int y)
{
    const soak_rain_flow_grid *g = j->g;
    size_t i = (size_t)y * g->w + x;
    if (!g->covered[i]) {
        j->next[i] = j->depth[i];
        j->lvl_next[i] = 0.0;
        return;
    }
    double vol_in = 0.0;
    if (j->pulls[i] == 0xFFu) { /* all eight send (inside a chart): the same sum in the same order, unrolled */
        for (int d = 0; d < 8; ++d) {
            int r = FLOW_DY[d] + 1, kx = x + FLOW_DX[d];
            vol_in += fr[r].o[(d + 4) & 7][kx] * (double)ar[r][kx];
        }
    } else {
        for (unsigned m = j->pulls[i]; m; m &= m - 1) {
            int d = __builtin_ctz(m), r = SOAK_RAIN_DY[d] + 1, kx = x + SOAK_RAIN_DX[d];
            vol_in += fr[r].o[(d + 4) & 7][kx] * (double)ar[r][kx];
        }
    }
    double h = j->depth[i] - fr[1].out[x] + vol_in / g->area[i];
    j->next[i] = h > 0.0 ? h : 0.0;
    j->lvl_next[i] = g->level[i] + j->next[i];
}

static void gather_row(const flow_job *j, int thread, int y)
{
    const soak_rain_flow_grid *g = j->g;
    /* rows y - 1, y, y + 1 of the ring and of the areas, by DY + 1 */
    flux_row_ptrs fr[3];
    const float *ar[3];
    for (int r = 0; r < 3; ++r) {
        int ky = y - 1 + r < 0 ? 0 : (y - 1 + r >= g->h ? g->h - 1 : y - 1 + r); /* clamped rows are never pulled from */
        ring_row(j, thread, ky, &fr[r]);
        ar[r] = g->area + (size_t)ky * g->w;
    }
    int x = 0;
    if (j->gather_row && g->w > 1) { /* the kernel reads one texel either side: not the first column */
        texel_gather(j, fr, ar, 0, y);
        x = j->gather_row(j, fr, ar, y, 1);
    }
    for (; x < g->w; ++x) texel_gather(j, fr, ar, x, y);
}

static void flow_band(void *ctx, int band, int thread)
{
    flow_job *j = ctx;
    int h = j->g->h, y0 = band * BAND, y1 = y0 + BAND < h ? y0 + BAND : h;
    if (y0 > 0) flux_row(j, thread, y0 - 1);
    flux_row(j, thread, y0);
    for (int y = y0; y < y1; ++y) {
        if (y + 1 < h) flux_row(j, thread, y + 1);
        gather_row(j, thread, y);
    }
}

/* level + depth of the covered texels of a band, before the first sweep. */
static void level_band(void *ctx, int band, int thread)
{
    (void)thread;
    flow_job *j = ctx;
    const soak_rain_flow_grid *g = j->g;
    int y0 = band * BAND, y1 = y0 + BAND < g->h ? y0 + BAND : g->h;
    double *lvl = (double *)j->lvl; /* the plan's buffer: writable, const only for the sweeps */
    for (size_t i = (size_t)y0 * g->w, end = (size_t)y1 * g->w; i < end; ++i)
        lvl[i] = g->covered[i] ? g->level[i] + j->depth[i] : 0.0;
}

static void find_pulls(const soak_rain_flow_grid *g, unsigned char *pulls)
{
    for (int y = 0; y < g->h; ++y)
        for (int x = 0; x < g->w; ++x) {
            size_t i = (size_t)y * g->w + x;
            pulls[i] = 0;
            for (int d = 0; d < 8; ++d) {
                int kx = x + SOAK_RAIN_DX[d], ky = y + SOAK_RAIN_DY[d];
                if (kx < 0 || ky < 0 || kx >= g->w || ky >= g->h) continue;
                if (g->adj[(size_t)ky * g->w + kx] >> ((d + 4) & 7) & 1u) pulls[i] |= (unsigned char)(1u << d);
            }
        }
}

/* The widest vector kernels the CPU runs (all give the same bits). */
static void pick_kernels(soak_rain_flow_plan *f, soak_rain_flow_isa isa)
{
    f->flux_row = NULL;
    f->gather_row = NULL;
    if (isa == SOAK_RAIN_FLOW_PORTABLE) return;
#ifdef SOAK_BUILD_FLOW_AVX512
    if (isa == SOAK_RAIN_FLOW_AUTO && soak_rain_cpu_has_avx512()) {
        f->flux_row = soak_rain_flux_row_avx512;
        f->gather_row = soak_rain_gather_row_avx512;
        return;
    }
#endif
#ifdef SOAK_BUILD_FLOW_AVX2
    if (soak_rain_cpu_has_avx2()) {
        f->flux_row = soak_rain_flux_row_avx2;
        f->gather_row = soak_rain_gather_row_avx2;
    }
#endif
}

void soak_rain_flow_destroy(soak_rain_flow_plan *f)
{
    if (!f) return;
    free(f->pulls);
    free(f->next);
    free(f->lvl_mem);
    free(f->lvl_next_mem);
    free(f->ring_o);
    free(f->ring_out);
    free(f);
}

soak_status soak_rain_flow_create(const soak_rain_flow_grid *g, const soak_bake_exec *exec, soak_rain_flow_isa isa,
                                  soak_rain_flow_plan **out)
{
    if (!g || !out) return SOAK_ERR_NULL;
    *out = NULL;
    int threads = soak_bake_threads(exec);
    if (threads == 0 || g->w < 1 || g->h < 1 || isa < SOAK_RAIN_FLOW_AUTO || isa > SOAK_RAIN_FLOW_AVX2)
        return SOAK_ERR_ARG;
    if (!g->covered || !g->adj || !g->area || !g->drip || !g->level || !g->retain) return SOAK_ERR_NULL;
    soak_rain_flow_plan *f = calloc(1, sizeof *f);
    if (!f) return SOAK_ERR_NOMEM;
    size_t n = (size_t)g->w * g->h, padded = n + 2 * ((size_t)g->w + 1), ring = (size_t)threads * 3 * g->w;
    f->g = *g;
    f->threads = threads;
    pick_kernels(f, isa);
    f->pulls = malloc(n);
    f->next = malloc(n * sizeof(double));
    f->lvl_mem = calloc(padded, sizeof(double));
    f->lvl_next_mem = calloc(padded, sizeof(double));
    f->ring_o = malloc(ring * 8 * sizeof(float));
    f->ring_out = malloc(ring * sizeof(double));
    if (!f->pulls || !f->next || !f->lvl_mem || !f->lvl_next_mem || !f->ring_o || !f->ring_out) {
        soak_rain_flow_destroy(f);
        return SOAK_ERR_NOMEM;
    }
    find_pulls(g, f->pulls);
    *out = f;
    return SOAK_OK;
}

soak_status soak_rain_flow_run(soak_rain_flow_plan *f, double *depth, int iterations, const soak_bake_exec *exec,
                               double progress_lo, double progress_hi)
{
    if (!f || !depth) return SOAK_ERR_NULL;
    int threads = soak_bake_threads(exec);
    if (threads == 0 || threads > f->threads) return SOAK_ERR_ARG;
    if (iterations <= 0) return SOAK_OK;
    const soak_rain_flow_grid *g = &f->g;
    size_t n = (size_t)g->w * g->h, pad = (size_t)g->w + 1;
    flow_job j = {g, depth, f->next, f->lvl_mem + pad, f->lvl_next_mem + pad, f->pulls, f->ring_o, f->ring_out,
                  {0}, f->flux_row, f->gather_row};
    for (int d = 0; d < 8; ++d) j.step[d] = (ptrdiff_t)SOAK_RAIN_DY[d] * g->w + SOAK_RAIN_DX[d];
    int bands = (g->h + BAND - 1) / BAND;
    soak_status st = soak_parallel_rows(bands, exec, level_band, &j, progress_lo, progress_lo);
    for (int it = 0; it < iterations && st == SOAK_OK; ++it) {
        st = soak_parallel_rows(bands, exec, flow_band, &j, progress_lo, progress_hi);
        double *t = (double *)j.depth;
        j.depth = j.next;
        j.next = t;
        t = (double *)j.lvl;
        j.lvl = j.lvl_next;
        j.lvl_next = t;
    }
    if (j.depth != depth) memcpy(depth, j.depth, n * sizeof(double)); /* an odd number of sweeps */
    return st;
}

soak_status soak_rain_flow(const soak_rain_flow_grid *g, double *depth, int iterations, const soak_bake_exec *exec,
                           double progress_lo, double progress_hi)
{
    if (!g || !depth) return SOAK_ERR_NULL;
    if (iterations <= 0) return SOAK_OK;
    soak_rain_flow_plan *f = NULL;
    soak_status st = soak_rain_flow_create(g, exec, SOAK_RAIN_FLOW_AUTO, &f);
    if (st == SOAK_OK) st = soak_rain_flow_run(f, depth, iterations, exec, progress_lo, progress_hi);
    soak_rain_flow_destroy(f);
    return st;
}

/* The index of neighbour d of texel i (it must exist). */
static size_t neighbour(const soak_rain_flow_grid *g, size_t i, int d)
{
    return (size_t)((ptrdiff_t)i + (ptrdiff_t)SOAK_RAIN_DY[d] * g->w + SOAK_RAIN_DX[d]);
}

/* The steepest descent's split of a full texel (bake_rain_stream.c: the
 * line-crossing form of the D-infinity routing of Tarboton 1997, Water
 * Resources Research 33(2), 309-319, with the direction from the surface's
 * own gradient instead of a facet fit) as drops summing to 1; 0 (use the
 * level drops) where the texel is level or a target is not lower. */
static int descent_drops(const soak_rain_flow_grid *g, size_t i, double diff[9], double *sum)
{
    soak_rain_box piece[8];
    if (!soak_rain_stream_split(g, i, SOAK_RAIN_BOX_FULL, diff, piece)) return 0;
    *sum = 1.0;
    return 1;
}

/* The routing's drops from texel i on the dry surface (levels without the
 * water): the steepest descent's split where it applies, else diff and
 * their sum as route_drops gives them; 0 where nothing is lower (a pit or
 * flat). */
static int dry_drops(const soak_rain_flow_grid *g, size_t i, double diff[9], double *sum)
{
    if (descent_drops(g, i, diff, sum)) return 1;
    int x = (int)(i % (size_t)g->w), y = (int)(i / (size_t)g->w);
    double nb[8], mx;
    for (int d = 0; d < 8; ++d)
        nb[d] = g->adj[i] >> d & 1u ? g->level[(size_t)(y + SOAK_RAIN_DY[d]) * g->w + (x + SOAK_RAIN_DX[d])] : 0.0;
    route_drops(g, i, g->level[i], nb, 0.0, diff, sum, &mx);
    return *sum > 0.0;
}

/* Spreads q over the lower neighbours of i in the shares diff / sum into
 * inflow; returns the share that drips off. */
static double spread(const soak_rain_flow_grid *g, size_t i, double q, const double diff[9], double sum,
                     double *inflow)
{
    for (int d = 0; d < 8; ++d)
        if (diff[d] > 0.0) inflow[neighbour(g, i, d)] += q * diff[d] / sum;
    return q * diff[8] / sum;
}

/* ---- steady discharge: the same routing, every texel passing on all it gets ---- */

typedef struct level_order {
    const double *level;
} level_order;

static int by_level_down(const void *a, const void *b, void *ctx)
{
    const double *lv = ((const level_order *)ctx)->level;
    size_t i = *(const size_t *)a, j = *(const size_t *)b;
    if (lv[i] != lv[j]) return lv[i] > lv[j] ? -1 : 1;
    return i < j ? -1 : (i > j);
}

/* Sorts idx (n covered texels) by level, highest first, ties by index: one
 * total order, so every sum below has one order. A bottom-up merge sort
 * (qsort passes no context in C11). */
static void sort_by_level(size_t *idx, size_t *tmp, size_t n, const double *level)
{
    level_order o = {level};
    for (size_t width = 1; width < n; width *= 2) {
        for (size_t lo = 0; lo < n; lo += 2 * width) {
            size_t mid = lo + width < n ? lo + width : n, hi = lo + 2 * width < n ? lo + 2 * width : n;
            size_t a = lo, b = mid, k = lo;
            while (a < mid && b < hi) tmp[k++] = by_level_down(&idx[b], &idx[a], &o) < 0 ? idx[b++] : idx[a++];
            while (a < mid) tmp[k++] = idx[a++];
            while (b < hi) tmp[k++] = idx[b++];
        }
        memcpy(idx, tmp, n * sizeof *idx);
    }
}

/* Texel i passes on what it receives minus its loss: along the descent
 * with the streams' boxes (bake_rain_stream.h), else to its lower
 * neighbours in the level drops' shares, off an open edge or a down-facing
 * face (drips), or nowhere (a pit or flat: held). */
static void pass_on(const soak_rain_flow_grid *g, soak_rain_box *boxes, size_t i, double source, double loss,
                    double *inflow, double *discharge, soak_rain_flow_balance *b)
{
    double got = source + inflow[i];
    double lost = loss * g->area[i] < got ? loss * g->area[i] : got, q = got - lost;
    b->lost += lost;
    discharge[i] = q;
    if (!(q > 0.0)) return;
    if (g->drip[i] < 0.0f) {
        b->dripped += q;
        return;
    }
    double off = soak_rain_stream_pass(g, boxes, i, source > 0.0, q, inflow);
    if (off >= 0.0) {
        b->dripped += off;
        return;
    }
    double diff[9], sum;
    if (!dry_drops(g, i, diff, &sum)) {
        b->held += q;
        return;
    }
    b->dripped += spread(g, i, q, diff, sum, inflow);
}

soak_status soak_rain_flow_discharge(const soak_rain_flow_grid *g, const double *source, double loss,
                                     double *discharge, soak_rain_flow_balance *balance)
{
    if (!g || !source || !discharge || !balance) return SOAK_ERR_NULL;
    if (g->w < 1 || g->h < 1 || !(loss >= 0.0 && loss < 1e300)) return SOAK_ERR_ARG;
    if (!g->covered || !g->adj || !g->area || !g->drip || !g->level) return SOAK_ERR_NULL;
    size_t n = (size_t)g->w * g->h, m = 0, *idx = NULL;
    double *inflow = calloc(n, sizeof *inflow);
    soak_rain_box *boxes = g->descent ? malloc(n * sizeof *boxes) : NULL;
    soak_status st = inflow && (boxes || !g->descent) ? soak_rain_flow_order(g, &idx, &m) : SOAK_ERR_NOMEM;
    if (st != SOAK_OK) {
        free(inflow);
        free(boxes);
        return st;
    }
    memset(balance, 0, sizeof *balance);
    for (size_t i = 0; i < n; ++i) {
        discharge[i] = 0.0;
        if (boxes) boxes[i] = SOAK_RAIN_BOX_EMPTY;
        if (g->covered[i]) balance->in += source[i];
    }
    for (size_t k = 0; k < m; ++k) /* every share goes strictly downhill: to a texel later in the order */
        pass_on(g, boxes, idx[k], source[idx[k]], loss, inflow, discharge, balance);
    free(idx);
    free(inflow);
    free(boxes);
    return SOAK_OK;
}

/* ---- cascade: the routing's shares at the film's speed ---- */

soak_status soak_rain_flow_order(const soak_rain_flow_grid *g, size_t **order, size_t *count)
{
    if (!g || !order || !count) return SOAK_ERR_NULL;
    *order = NULL;
    *count = 0;
    size_t n = (size_t)g->w * g->h, m = 0;
    size_t *idx = malloc((n ? n : 1) * sizeof *idx), *tmp = malloc((n ? n : 1) * sizeof *tmp);
    if (!idx || !tmp) {
        free(idx);
        free(tmp);
        return SOAK_ERR_NOMEM;
    }
    for (size_t i = 0; i < n; ++i)
        if (g->covered[i]) idx[m++] = i;
    sort_by_level(idx, tmp, m, g->level);
    free(tmp);
    *order = idx;
    *count = m;
    return SOAK_OK;
}

/* Texel i keeps up to its retention of what it holds and receives (all of
 * it where it is not fast or nothing is lower: a pit or flat) and passes
 * the rest on. */
static double cascade_texel(const soak_rain_flow_grid *g, const unsigned char *fast, size_t i, double *depth,
                            double *inflow)
{
    double a = g->area[i], have = depth[i] * a + inflow[i], keep = g->retain[i] * a;
    inflow[i] = 0.0;
    if (!fast[i] || !(have > keep)) {
        depth[i] = have / a;
        return 0.0;
    }
    depth[i] = g->retain[i];
    double q = have - keep;
    if (g->drip[i] < 0.0f) return q;
    double diff[9], sum;
    if (!dry_drops(g, i, diff, &sum)) {
        depth[i] = have / a;
        return 0.0;
    }
    return spread(g, i, q, diff, sum, inflow);
}

soak_status soak_rain_flow_cascade(const soak_rain_flow_grid *g, const unsigned char *fast, const size_t *order,
                                   size_t count, double *depth, double *inflow, double *dripped)
{
    if (!g || !fast || (!order && count) || !depth || !inflow || !dripped) return SOAK_ERR_NULL;
    *dripped = 0.0;
    for (size_t k = 0; k < count; ++k) inflow[order[k]] = 0.0;
    for (size_t k = 0; k < count; ++k) *dripped += cascade_texel(g, fast, order[k], depth, inflow);
    return SOAK_OK;
}

/* ---- the routing's shares of one texel, for the film's wave ---- */

int soak_rain_flow_shares(const soak_rain_flow_grid *g, size_t i, double share[9])
{
    for (int d = 0; d < 9; ++d) share[d] = 0.0;
    if (g->drip[i] < 0.0f) {
        share[8] = 1.0;
        return 1;
    }
    double diff[9], sum;
    if (!dry_drops(g, i, diff, &sum)) return 0;
    for (int d = 0; d < 9; ++d) share[d] = diff[d] / sum;
    return 1;
}

double soak_rain_flow_width(const soak_rain_flow_grid *g, size_t i)
{
    double area = g->area[i];
    if (g->descent) {
        double a = fabs(g->descent[2 * i]), b = fabs(g->descent[2 * i + 1]), m = a > b ? a : b;
        if (m > 0.0) return area * m;
    }
    return sqrt(area);
}
