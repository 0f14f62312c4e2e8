/* Fused downhill-flow sweeps of the rain bake (bake_rain_flow.h). */
#include "bake_rain_flow.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#define FLOW_DX_INIT {1, 1, 0, -1, -1, -1, 0, 1}
#define FLOW_DY_INIT {0, -1, -1, -1, 0, 1, 1, 1}
const int SOAK_RAIN_DX[8] = FLOW_DX_INIT;
const int SOAK_RAIN_DY[8] = FLOW_DY_INIT;
/* The same, as constants the compiler folds into unrolled loops. */
static const int FLOW_DX[8] = FLOW_DX_INIT, FLOW_DY[8] = FLOW_DY_INIT;

/* Rows per task; each task also computes the outflows of one row either
 * side of its band, so wider bands repeat less work. */
enum { BAND = 32 };

/* What texel k sends: o[d] to neighbour d (float, as the two-pass scheme
 * stores it) and out, the sum of its nine outflows (drip included) in that
 * scheme's order. */
typedef struct flux {
    float o[8];
    double out;
} flux;

typedef struct flow_job {
    const soak_rain_flow_grid *g;
    const double *depth;
    double *next;
    flux *scratch;        /* 3 rows (a ring: row y in slot y % 3) per thread */
    unsigned char *pulls; /* bit d: neighbour d exists and sends to this texel (its adj has the way back) */
    ptrdiff_t step[8];    /* index offset of neighbour d */
    /* level + depth per covered texel before and after the sweep, each sum
     * made once (by the gather that writes the depth) instead of by all
     * nine texels that read it */
    const double *lvl;
    double *lvl_next;
} flow_job;

static double level_at(const flow_job *j, size_t i) { return j->lvl[i]; }

static void texel_flux(const flow_job *j, int x, int y, flux *f)
{
    const soak_rain_flow_grid *g = j->g;
    size_t i = (size_t)y * g->w + x;
    memset(f, 0, sizeof *f);
    if (!g->covered[i]) return;
    double h = j->depth[i], mobile = h - g->retain[i];
    if (!(mobile > 0.0)) return;
    if (g->drip[i] < 0.0f) { /* faces down: everything drips, nothing to the neighbours */
        f->out = (float)mobile;
        return;
    }
    double lvl = level_at(j, i), diff[9], sum = 0.0, mx = 0.0;
    if (g->adj[i] == 0xFFu) { /* all eight adjacent (inside a chart): no per-direction test */
        for (int d = 0; d < 8; ++d) {
            double dl = lvl - level_at(j, i + (size_t)j->step[d]);
            diff[d] = dl > 0.0 ? dl : 0.0;
        }
    } else {
        for (int d = 0; d < 8; ++d) {
            diff[d] = 0.0;
            if (!(g->adj[i] >> d & 1u)) continue;
            size_t k = (size_t)(y + SOAK_RAIN_DY[d]) * g->w + (size_t)(x + SOAK_RAIN_DX[d]);
            double dl = lvl - level_at(j, k);
            if (dl > 0.0) diff[d] = dl;
        }
    }
    diff[8] = g->drip[i] > 0.0f ? h + g->drip[i] : 0.0; /* virtual dry neighbour beyond the edge */
    for (int d = 0; d < 9; ++d) { /* diff >= 0, never NaN: comparisons give fmax / fmin's values */
        sum += diff[d];
        mx = diff[d] > mx ? diff[d] : mx;
    }
    if (!(sum > 0.0)) return;
    double moved = 0.5 * mx < mobile ? 0.5 * mx : mobile, out = 0.0;
    /* A direction without a level drop sends moved * 0 / sum = +0, which the
     * memset above wrote and which adds nothing to out (>= +0): skipping its
     * division leaves every bit as it was. */
    for (int d = 0; d < 8; ++d) {
        if (!(diff[d] > 0.0)) continue;
        f->o[d] = (float)(moved * diff[d] / sum);
        out += f->o[d];
    }
    f->out = diff[8] > 0.0 ? out + (float)(moved * diff[8] / sum) : out;
}

static void flux_row(const flow_job *j, flux *ring, int y)
{
    flux *row = ring + (size_t)(y % 3) * j->g->w;
    for (int x = 0; x < j->g->w; ++x) texel_flux(j, x, y, &row[x]);
}

static void gather_row(const flow_job *j, const flux *ring, int y)
{
    const soak_rain_flow_grid *g = j->g;
    /* rows y - 1, y, y + 1 of the ring and of the areas, by DY + 1 */
    const flux *fr[3];
    const float *ar[3];
    for (int r = 0; r < 3; ++r) {
        int ky = y - 1 + r < 0 ? 0 : (y - 1 + r >= g->h ? g->h - 1 : y - 1 + r); /* clamped rows are never pulled from */
        fr[r] = ring + (size_t)(ky % 3) * g->w;
        ar[r] = g->area + (size_t)ky * g->w;
    }
    for (int x = 0; x < g->w; ++x) {
        size_t i = (size_t)y * g->w + x;
        if (!g->covered[i]) {
            j->next[i] = j->depth[i];
            j->lvl_next[i] = 0.0; /* never read: only covered texels are neighbours */
            continue;
        }
        double vol_in = 0.0;
        if (j->pulls[i] == 0xFFu) { /* all eight send (inside a chart): the same sum in the same order, unrolled */
            for (int d = 0; d < 8; ++d) {
                int r = FLOW_DY[d] + 1, kx = x + FLOW_DX[d];
                vol_in += fr[r][kx].o[(d + 4) & 7] * (double)ar[r][kx];
            }
        } else {
            for (unsigned m = j->pulls[i]; m; m &= m - 1) {
                int d = __builtin_ctz(m), r = SOAK_RAIN_DY[d] + 1, kx = x + SOAK_RAIN_DX[d];
                vol_in += fr[r][kx].o[(d + 4) & 7] * (double)ar[r][kx];
            }
        }
        double h = j->depth[i] - fr[1][x].out + vol_in / g->area[i];
        j->next[i] = h > 0.0 ? h : 0.0;
        j->lvl_next[i] = g->level[i] + j->next[i];
    }
}

static void flow_band(void *ctx, int band, int thread)
{
    flow_job *j = ctx;
    int h = j->g->h, y0 = band * BAND, y1 = y0 + BAND < h ? y0 + BAND : h;
    flux *ring = j->scratch + (size_t)thread * 3 * j->g->w;
    if (y0 > 0) flux_row(j, ring, y0 - 1);
    flux_row(j, ring, y0);
    for (int y = y0; y < y1; ++y) {
        if (y + 1 < h) flux_row(j, ring, y + 1);
        gather_row(j, ring, y);
    }
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

soak_status soak_rain_flow(const soak_rain_flow_grid *g, double *depth, int iterations, const soak_bake_exec *exec,
                           double progress_lo, double progress_hi)
{
    if (!g || !depth) return SOAK_ERR_NULL;
    if (iterations <= 0) return SOAK_OK;
    int threads = soak_bake_threads(exec);
    if (threads == 0) return SOAK_ERR_ARG;
    size_t n = (size_t)g->w * g->h;
    double *lvl = malloc(n * sizeof(double)), *lvl_next = malloc(n * sizeof(double));
    flow_job j = {g,   depth, malloc(n * sizeof(double)), malloc((size_t)threads * 3 * g->w * sizeof(flux)), malloc(n),
                  {0}, lvl,   lvl_next};
    for (int d = 0; d < 8; ++d) j.step[d] = (ptrdiff_t)SOAK_RAIN_DY[d] * g->w + SOAK_RAIN_DX[d];
    soak_status st = j.next && j.scratch && j.pulls && lvl && lvl_next ? SOAK_OK : SOAK_ERR_NOMEM;
    if (st == SOAK_OK) {
        find_pulls(g, j.pulls);
        for (size_t i = 0; i < n; ++i) lvl[i] = g->covered[i] ? g->level[i] + depth[i] : 0.0;
    }
    int bands = (g->h + BAND - 1) / BAND;
    for (int it = 0; it < iterations && st == SOAK_OK; ++it) {
        st = soak_parallel_rows(bands, exec, flow_band, &j, progress_lo, progress_hi);
        double *t = (double *)j.depth;
        j.depth = j.next;
        j.next = t;
        t = (double *)j.lvl;
        j.lvl = j.lvl_next;
        j.lvl_next = t;
    }
    if (st == SOAK_OK && j.depth != depth) memcpy(depth, j.depth, n * sizeof(double));
    free(j.depth == depth ? j.next : (double *)j.depth);
    free(j.scratch);
    free(j.pulls);
    free(lvl);
    free(lvl_next);
    return st;
}
