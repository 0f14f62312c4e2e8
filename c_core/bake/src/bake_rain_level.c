/* Puddles that level (bake_rain_level.h). The spill levels are those of the
 * priority flood of Barnes, Lehman & Mulla 2014 ("Priority-Flood: An optimal
 * depression-filling and watershed-labeling algorithm", Computers &
 * Geosciences 62, 117-127): from the outlets inward, lowest first, every
 * texel's spill level is the larger of its own level and that of the texel
 * the flood reached it from. */
#include "bake_rain_level.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* A binary min-heap of texels keyed by spill level (ties by index: one
 * order, the same bits every run). */
typedef struct flood_heap {
    size_t *idx, n;
    const double *key;
} flood_heap;

static int heap_less(const flood_heap *q, size_t a, size_t b)
{
    double ka = q->key[a], kb = q->key[b];
    return ka < kb || (ka == kb && a < b);
}

static void heap_push(flood_heap *q, size_t i)
{
    size_t k = q->n++;
    while (k > 0 && heap_less(q, i, q->idx[(k - 1) / 2])) {
        q->idx[k] = q->idx[(k - 1) / 2];
        k = (k - 1) / 2;
    }
    q->idx[k] = i;
}

static size_t heap_pop(flood_heap *q)
{
    size_t top = q->idx[0], last = q->idx[--q->n], k = 0;
    for (;;) {
        size_t c = 2 * k + 1;
        if (c >= q->n) break;
        if (c + 1 < q->n && heap_less(q, q->idx[c + 1], q->idx[c])) ++c;
        if (!heap_less(q, q->idx[c], last)) break;
        q->idx[k] = q->idx[c];
        k = c;
    }
    if (q->n) q->idx[k] = last;
    return top;
}

static size_t neighbour_of(const soak_rain_flow_grid *g, size_t i, int d)
{
    return (size_t)((ptrdiff_t)i + (ptrdiff_t)SOAK_RAIN_DY[d] * g->w + SOAK_RAIN_DX[d]);
}

/* Water leaves the surface at texel i: an open edge or a drip. */
static int is_outlet(const soak_rain_flow_grid *g, size_t i) { return g->adj[i] != 0xFFu || g->drip[i] != 0.0f; }

/* The flood: spill[i] for every covered texel, from[i] the texel the flood
 * came from (i itself for a seed). Unreached texels (a closed surface)
 * seed from their lowest. */
static void flood(const soak_rain_flow_grid *g, double *spill, size_t *from, unsigned char *done, flood_heap *q)
{
    size_t n = (size_t)g->w * g->h;
    for (size_t i = 0; i < n; ++i) {
        done[i] = !g->covered[i];
        spill[i] = g->level[i];
        from[i] = i;
        if (!done[i] && is_outlet(g, i)) done[i] = 1, heap_push(q, i);
    }
    for (size_t next = 0;;) {
        while (q->n) {
            size_t c = heap_pop(q);
            for (int d = 0; d < 8; ++d) {
                if (!(g->adj[c] >> d & 1u)) continue;
                size_t k = neighbour_of(g, c, d);
                if (done[k]) continue;
                done[k] = 1;
                spill[k] = g->level[k] > spill[c] ? g->level[k] : spill[c];
                from[k] = c;
                heap_push(q, k);
            }
        }
        while (next < n && done[next]) ++next;
        if (next == n) break;
        done[next] = 1;
        heap_push(q, next);
    }
}

static int by_level_up(const void *a, const void *b, const double *level)
{
    double la = level[*(const size_t *)a], lb = level[*(const size_t *)b];
    return la < lb ? -1 : la > lb;
}

/* Sorts m texels by level, lowest first (insertion into a merge, as the
 * flow's sort: qsort passes no context in C11). */
static void sort_up(size_t *idx, size_t *tmp, size_t m, const double *level)
{
    for (size_t width = 1; width < m; width *= 2) {
        for (size_t lo = 0; lo < m; lo += 2 * width) {
            size_t mid = lo + width < m ? lo + width : m, hi = lo + 2 * width < m ? lo + 2 * width : m;
            size_t a = lo, b = mid, k = lo;
            while (a < mid && b < hi) tmp[k++] = by_level_up(&idx[b], &idx[a], level) < 0 ? idx[b++] : idx[a++];
            while (a < mid) tmp[k++] = idx[a++];
            while (b < hi) tmp[k++] = idx[b++];
        }
        memcpy(idx, tmp, m * sizeof *idx);
    }
}

/* One depression (its m texels in idx, lowest first; spill level top,
 * sill texel the flood entered it from): its water as a horizontal
 * surface. */
static void fill_depression(const soak_rain_flow_grid *g, const size_t *idx, size_t m, double top, size_t sill,
                            double *depth)
{
    double vol = 0.0, cap = 0.0;
    for (size_t k = 0; k < m; ++k) {
        vol += depth[idx[k]] * g->area[idx[k]];
        cap += (top - g->level[idx[k]]) * g->area[idx[k]];
    }
    double surface = top;
    if (vol < cap) { /* the lowest j texels wet: surface = (vol + sum a l) / sum a */
        double a = 0.0, al = 0.0;
        for (size_t k = 0; k < m; ++k) {
            a += g->area[idx[k]];
            al += g->area[idx[k]] * g->level[idx[k]];
            surface = (vol + al) / a;
            if (k + 1 == m || surface <= g->level[idx[k + 1]]) break;
        }
    } else if (g->area[sill] > 0.0f) {
        depth[sill] += (vol - cap) / g->area[sill];
    }
    for (size_t k = 0; k < m; ++k) {
        double d = surface - g->level[idx[k]];
        depth[idx[k]] = d > 0.0 ? d : 0.0;
    }
}

/* Collects into idx the depression holding texel s (texels below their
 * spill level, that level equal to s's, connected through adj); marks them
 * in seen. Returns the count; *sill the texel the flood entered from. */
static size_t collect(const soak_rain_flow_grid *g, const double *spill, const size_t *from, size_t s, size_t *idx,
                      unsigned char *seen, size_t *sill)
{
    size_t m = 0;
    idx[m++] = s;
    seen[s] = 1;
    *sill = from[s];
    for (size_t head = 0; head < m; ++head) {
        size_t c = idx[head];
        if (spill[from[c]] == spill[s] && !(spill[from[c]] > g->level[from[c]])) *sill = from[c];
        for (int d = 0; d < 8; ++d) {
            if (!(g->adj[c] >> d & 1u)) continue;
            size_t k = neighbour_of(g, c, d);
            if (seen[k] || !(spill[k] > g->level[k]) || spill[k] != spill[s]) continue;
            seen[k] = 1;
            idx[m++] = k;
        }
    }
    return m;
}

/* The depressions, found once per surface: their texels lowest first,
 * depression k at idx[start[k]] .. idx[start[k + 1] - 1]. */
struct soak_rain_level_plan {
    soak_rain_flow_grid g;
    size_t *idx, *start, *sill, count;
    double *top;
};

void soak_rain_level_destroy(soak_rain_level_plan *lp)
{
    if (!lp) return;
    free(lp->idx);
    free(lp->start);
    free(lp->sill);
    free(lp->top);
    free(lp);
}

/* The flood and the depressions into lp (its arrays allocated, n each). */
static void find_depressions(soak_rain_level_plan *lp, double *spill, size_t *from, unsigned char *seen, size_t *tmp,
                             flood_heap *q)
{
    const soak_rain_flow_grid *g = &lp->g;
    size_t n = (size_t)g->w * g->h, used = 0;
    flood(g, spill, from, seen, q);
    for (size_t i = 0; i < n; ++i) seen[i] = 0;
    for (size_t i = 0; i < n; ++i) {
        if (!g->covered[i] || seen[i] || !(spill[i] > g->level[i])) continue;
        size_t sill, m = collect(g, spill, from, i, lp->idx + used, seen, &sill);
        sort_up(lp->idx + used, tmp, m, g->level);
        lp->start[lp->count] = used;
        lp->sill[lp->count] = sill;
        lp->top[lp->count++] = spill[i];
        used += m;
    }
    lp->start[lp->count] = used;
}

soak_status soak_rain_level_create(const soak_rain_flow_grid *g, soak_rain_level_plan **out)
{
    if (!g || !out) return SOAK_ERR_NULL;
    *out = NULL;
    if (!g->covered || !g->adj || !g->area || !g->drip || !g->level) return SOAK_ERR_NULL;
    if (g->w < 1 || g->h < 1) return SOAK_ERR_ARG;
    size_t n = (size_t)g->w * g->h;
    soak_rain_level_plan *lp = calloc(1, sizeof *lp);
    double *spill = malloc(n * sizeof *spill);
    size_t *from = malloc(n * sizeof *from), *tmp = malloc(n * sizeof *tmp);
    unsigned char *seen = malloc(n);
    flood_heap q = {malloc(n * sizeof(size_t)), 0, spill};
    if (lp) {
        lp->g = *g;
        lp->idx = malloc(n * sizeof *lp->idx);
        lp->start = malloc((n + 1) * sizeof *lp->start);
        lp->sill = malloc(n * sizeof *lp->sill);
        lp->top = malloc(n * sizeof *lp->top);
    }
    soak_status st = lp && lp->idx && lp->start && lp->sill && lp->top && spill && from && tmp && seen && q.idx
                         ? SOAK_OK
                         : SOAK_ERR_NOMEM;
    if (st == SOAK_OK) find_depressions(lp, spill, from, seen, tmp, &q);
    free(spill);
    free(from);
    free(tmp);
    free(seen);
    free(q.idx);
    if (st == SOAK_OK) *out = lp;
    else soak_rain_level_destroy(lp);
    return st;
}

soak_status soak_rain_level_run(const soak_rain_level_plan *lp, double *depth)
{
    if (!lp || !depth) return SOAK_ERR_NULL;
    for (size_t k = 0; k < lp->count; ++k)
        fill_depression(&lp->g, lp->idx + lp->start[k], lp->start[k + 1] - lp->start[k], lp->top[k], lp->sill[k],
                        depth);
    return SOAK_OK;
}

soak_status soak_rain_level(const soak_rain_flow_grid *g, double *depth)
{
    if (!depth) return SOAK_ERR_NULL;
    soak_rain_level_plan *lp = NULL;
    soak_status st = soak_rain_level_create(g, &lp);
    if (st == SOAK_OK) st = soak_rain_level_run(lp, depth);
    soak_rain_level_destroy(lp);
    return st;
}
