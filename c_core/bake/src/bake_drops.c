/* Drops bake: a space-time Poisson process of raindrop impacts wetting a
 * surface splat by splat (model and determinism in soak/bake_drops.h). */
#include "soak/bake_drops.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "soak/bake_rain.h"
#include "soak/poisson.h"

#define PI 3.14159265358979323846
#define POISSON_EXACT_MAX 30.0 /* soak_rng_poisson inverts its CDF up to here */

void soak_drops_defaults(soak_drops_params *p)
{
    if (!p) return;
    memset(p, 0, sizeof *p);
    p->rate_mm_h = 10;
    p->texel_m = 1e-3;
    p->capacity_m = 2e-4;
    p->duration = 10;
    p->dry_time = 20;
    p->t_fill = 0.2;
    p->wrap = 1;
    p->splash_fraction = 0.2;
    p->splash_speed = 0.2;
}

soak_status soak_drops_check(const soak_drops_params *p)
{
    if (!p) return SOAK_ERR_NULL;
    if (!soak_in_range(p->rate_mm_h, 0, SOAK_DROP_RATE_MAX) || !soak_in_range(p->texel_m, 1e-9, SOAK_DROPS_MAX_SCALE) ||
        !soak_in_range(p->capacity_m, 1e-12, 1) ||
        !(p->spread_factor == 0 || soak_in_range(p->spread_factor, 1, 100)) ||
        !(soak_in_range(p->min_diameter_mm, 0, SOAK_DROP_D_MAX_MM) && p->min_diameter_mm < SOAK_DROP_D_MAX_MM) ||
        !soak_in_range(p->duration, 0, SOAK_DROPS_MAX_TIME) || !soak_in_range(p->dry_time, 1e-9, SOAK_DROPS_MAX_TIME) ||
        !soak_in_range(p->t_fill, 0, 1) || !(p->wrap == 0 || p->wrap == 1) || !(p->splash == 0 || p->splash == 1) ||
        !soak_in_range(p->splash_fraction, 0, 1) || !soak_in_range(p->splash_speed, 0, 1))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

static soak_status check_exposure(const soak_image *e, int width, int height, double *e_max)
{
    *e_max = 1;
    if (!e) return SOAK_OK;
    if (!e->pixels) return SOAK_ERR_NULL;
    if (e->width != width || e->height != height || e->channels != 1) return SOAK_ERR_ARG;
    size_t n = (size_t)width * height;
    for (size_t i = 0; i < n; ++i) {
        if (!soak_in_range(e->pixels[i], 0, 1e6)) return SOAK_ERR_ARG;
        if (e->pixels[i] > *e_max) *e_max = e->pixels[i];
    }
    return SOAK_OK;
}

static double rng_uniform(void *ctx)
{
    return soak_rng_uniform(ctx);
}

typedef struct impact_list {
    soak_drop_impact *v;
    size_t n, cap;
} impact_list;

static soak_status list_push(impact_list *l, const soak_drop_impact *imp)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 256;
        soak_drop_impact *v = realloc(l->v, cap * sizeof *v);
        if (!v) return SOAK_ERR_NOMEM;
        l->v = v, l->cap = cap;
    }
    l->v[l->n++] = *imp;
    return SOAK_OK;
}

typedef struct gen_ctx {
    const soak_drops_params *p;
    const soak_image *exposure;
    int width, height;
    double flux, e_max;
} gen_ctx;

/* Impacts of one (slab, cell): counts Poisson(lambda) in parts of at most
 * POISSON_EXACT_MAX (a sum of independent Poisson draws is Poisson, and
 * each part is drawn exactly), then thinned by the exposure. */
static soak_status gen_cell(const gen_ctx *g, long slab, uint32_t cell, impact_list *out)
{
    int cells_x = (g->width + SOAK_DROPS_CELL - 1) / SOAK_DROPS_CELL;
    int x0 = (int)(cell % (uint32_t)cells_x) * SOAK_DROPS_CELL, y0 = (int)(cell / (uint32_t)cells_x) * SOAK_DROPS_CELL;
    int cw = g->width - x0 < SOAK_DROPS_CELL ? g->width - x0 : SOAK_DROPS_CELL;
    int ch = g->height - y0 < SOAK_DROPS_CELL ? g->height - y0 : SOAK_DROPS_CELL;
    double area = (double)cw * ch * g->p->texel_m * g->p->texel_m;
    double lambda = g->flux * area * SOAK_DROPS_SLAB * g->e_max;
    soak_rng rng;
    soak_rng_seed(&rng, soak_seed_derive(g->p->seed, (uint64_t)slab), cell);
    double parts = ceil(lambda / POISSON_EXACT_MAX);
    long count = 0;
    for (double k = 0; k < parts; ++k) count += soak_rng_poisson(lambda / parts, &rng);
    for (long i = 0; i < count; ++i) {
        soak_drop_impact imp = {x0 + soak_rng_uniform(&rng) * cw, y0 + soak_rng_uniform(&rng) * ch,
                                (slab + soak_rng_uniform(&rng)) * SOAK_DROPS_SLAB, 0, cell, (uint32_t)i};
        imp.d_mm = soak_drop_sample(g->p->rate_mm_h, g->p->min_diameter_mm, rng_uniform, &rng);
        double keep = soak_rng_uniform(&rng);
        if (g->exposure) {
            int tx = (int)imp.x, ty = (int)imp.y;
            tx = tx < g->width ? tx : g->width - 1, ty = ty < g->height ? ty : g->height - 1;
            if (!(keep * g->e_max < g->exposure->pixels[(size_t)ty * g->width + tx])) continue;
        }
        soak_status st = list_push(out, &imp);
        if (st != SOAK_OK) return st;
    }
    return SOAK_OK;
}

static int impact_order(const void *va, const void *vb)
{
    const soak_drop_impact *a = va, *b = vb;
    if (a->t != b->t) return a->t < b->t ? -1 : 1;
    if (a->cell != b->cell) return a->cell < b->cell ? -1 : 1;
    return (a->index > b->index) - (a->index < b->index);
}

static soak_status gen_slabs(const gen_ctx *g, long slab0, long slab1, impact_list *out)
{
    uint32_t cells = (uint32_t)((g->width + SOAK_DROPS_CELL - 1) / SOAK_DROPS_CELL) *
                     (uint32_t)((g->height + SOAK_DROPS_CELL - 1) / SOAK_DROPS_CELL);
    size_t start = out->n;
    for (long s = slab0; s < slab1 && g->flux > 0; ++s)
        for (uint32_t c = 0; c < cells; ++c) {
            soak_status st = gen_cell(g, s, c, out);
            if (st != SOAK_OK) return st;
        }
    if (out->n > start) qsort(out->v + start, out->n - start, sizeof *out->v, impact_order);
    return SOAK_OK;
}

soak_status soak_drops_impacts(const soak_drops_params *p, const soak_image *exposure, int width, int height,
                               long slab0, long slab1, soak_drop_impact **out, size_t *count)
{
    if (!p || !out || !count) return SOAK_ERR_NULL;
    *out = NULL, *count = 0;
    gen_ctx g = {p, exposure, width, height, 0, 1};
    soak_status st = soak_drops_check(p);
    if (st == SOAK_OK) st = soak_bake_check_size(width, height);
    if (st == SOAK_OK) st = check_exposure(exposure, width, height, &g.e_max);
    if (st == SOAK_OK && !(slab0 >= 0 && slab1 >= slab0 && slab1 - slab0 <= 100000000L)) st = SOAK_ERR_ARG;
    if (st != SOAK_OK) return st;
    g.flux = soak_drop_flux(p->rate_mm_h, p->min_diameter_mm, SOAK_DROP_D_MAX_MM);
    impact_list l = {NULL, 0, 0};
    st = gen_slabs(&g, slab0, slab1, &l);
    if (st != SOAK_OK) {
        free(l.v);
        return st;
    }
    *out = l.v, *count = l.n;
    return SOAK_OK;
}
