/* Beads bake: raindrops standing as spherical caps on a surface of high
 * contact angle, coalescing where they touch (model in soak/bake_beads.h). */
#include "soak/bake_beads.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "soak/bake_drops.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)
#define GRID_CELL 8 /* texels per side of a neighbour-search cell */

soak_status soak_bead_cap(double volume_m3, double theta_deg, soak_bead_shape *out)
{
    if (!out) return SOAK_ERR_NULL;
    if (!soak_in_range(volume_m3, 1e-30, 1.0) || !soak_in_range(theta_deg, SOAK_BEAD_ANGLE_MIN, SOAK_BEAD_ANGLE_MAX))
        return SOAK_ERR_ARG;
    const double theta = theta_deg * DEG, t = tan(0.5 * theta);
    const double r = cbrt(6.0 * volume_m3 / (PI * t * (3.0 + t * t)));
    const double R = r / sin(theta);
    out->contact_radius_m = r;
    out->height_m = t * r;
    out->sphere_radius_m = R;
    out->outline_m = theta_deg <= 90.0 ? r : R;
    out->theta_rad = theta;
    return SOAK_OK;
}

double soak_bead_surface(const soak_bead_shape *b, double rho_m)
{
    if (!b || !(rho_m >= 0) || !(rho_m < b->outline_m)) return 0.0;
    const double R = b->sphere_radius_m;
    const double z = b->height_m - R + sqrt(fmax(0.0, R * R - rho_m * rho_m));
    return z > 0 ? z : 0.0;
}

double soak_bead_column_volume(const soak_bead_shape *b)
{
    if (!b) return 0.0;
    const double r = b->contact_radius_m, h = b->height_m, R = b->sphere_radius_m;
    if (b->theta_rad <= 0.5 * PI) return PI * h * (3.0 * r * r + h * h) / 6.0;
    return PI * R * R * R * (2.0 / 3.0 - cos(b->theta_rad));
}

void soak_beads_defaults(soak_beads_params *p)
{
    if (!p) return;
    memset(p, 0, sizeof *p);
    p->rate_mm_h = 10;
    p->texel_m = 2.5e-4;
    p->duration = 10;
    p->contact_angle_deg = 90;
    p->height_range_m = 6e-3;
    p->supersample = 4;
}

soak_status soak_beads_check(const soak_beads_params *p)
{
    if (!p) return SOAK_ERR_NULL;
    if (!soak_in_range(p->rate_mm_h, 1e-9, SOAK_DROP_RATE_MAX) ||
        !soak_in_range(p->texel_m, 1e-9, SOAK_DROPS_MAX_SCALE) || !soak_in_range(p->duration, 0, SOAK_DROPS_MAX_TIME) ||
        !(soak_in_range(p->min_diameter_mm, 0, SOAK_DROP_D_MAX_MM) && p->min_diameter_mm < SOAK_DROP_D_MAX_MM) ||
        !soak_in_range(p->contact_angle_deg, SOAK_BEAD_ANGLE_MIN, SOAK_BEAD_ANGLE_MAX) ||
        !soak_in_range(p->height_range_m, 1e-12, 1) ||
        !(p->supersample >= 1 && p->supersample <= SOAK_BEADS_MAX_SUPERSAMPLE))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

/* ---- coalescence: live beads in a grid of GRID_CELL-texel cells ---------- */

typedef struct bead {
    double x, y, volume, outline_tx; /* texels, m^3, texels */
    int cell, prev, next, alive;
} bead;

typedef struct bead_set {
    bead *v;
    size_t n, cap;
    int *head; /* first bead of each cell, -1 when empty */
    int gx, gy, width, height;
    double theta_deg, texel_m, max_outline_tx;
} bead_set;

/* Shortest displacement from a to b on the wrapping map, texels. */
static double wrap_delta(double d, int size)
{
    d = fmod(d, (double)size);
    if (d > 0.5 * size) d -= size;
    if (d < -0.5 * size) d += size;
    return d;
}

static double wrap_coord(double x, int size)
{
    x = fmod(x, (double)size);
    return x < 0 ? x + size : x;
}

static int cell_of(const bead_set *s, double x, double y)
{
    int cx = (int)(x / GRID_CELL), cy = (int)(y / GRID_CELL);
    cx = cx < s->gx ? cx : s->gx - 1, cy = cy < s->gy ? cy : s->gy - 1;
    return cy * s->gx + cx;
}

static void link_bead(bead_set *s, int i)
{
    bead *b = &s->v[i];
    b->cell = cell_of(s, b->x, b->y);
    b->prev = -1, b->next = s->head[b->cell];
    if (b->next >= 0) s->v[b->next].prev = i;
    s->head[b->cell] = i;
    b->alive = 1;
    if (b->outline_tx > s->max_outline_tx) s->max_outline_tx = b->outline_tx;
}

static void unlink_bead(bead_set *s, int i)
{
    bead *b = &s->v[i];
    if (b->prev >= 0) s->v[b->prev].next = b->next;
    else s->head[b->cell] = b->next;
    if (b->next >= 0) s->v[b->next].prev = b->prev;
    b->alive = 0;
}

static soak_status set_outline(const bead_set *s, bead *b)
{
    soak_bead_shape shape;
    soak_status st = soak_bead_cap(b->volume, s->theta_deg, &shape);
    if (st == SOAK_OK) b->outline_tx = shape.outline_m / s->texel_m;
    return st;
}

/* The k-th of the n cells around c along an axis of size cells (every cell
 * once when the span covers the axis). */
static int around(int c, int span, int k, int cells)
{
    return 2 * span + 1 >= cells ? k : ((c - span + k) % cells + cells) % cells;
}

/* The live bead of lowest index whose outline overlaps b's, or -1. */
static int find_overlap(const bead_set *s, const bead *b)
{
    const int span = (int)ceil((b->outline_tx + s->max_outline_tx) / GRID_CELL);
    const int nx = 2 * span + 1 < s->gx ? 2 * span + 1 : s->gx, ny = 2 * span + 1 < s->gy ? 2 * span + 1 : s->gy;
    int found = -1;
    for (int ky = 0; ky < ny; ++ky)
        for (int kx = 0; kx < nx; ++kx) {
            int c = around(b->cell / s->gx, span, ky, s->gy) * s->gx + around(b->cell % s->gx, span, kx, s->gx);
            for (int i = s->head[c]; i >= 0; i = s->v[i].next) {
                const bead *o = &s->v[i];
                double ddx = wrap_delta(o->x - b->x, s->width), ddy = wrap_delta(o->y - b->y, s->height);
                double lim = o->outline_tx + b->outline_tx;
                if (ddx * ddx + ddy * ddy < lim * lim && (found < 0 || i < found)) found = i;
            }
        }
    return found;
}

static soak_status push_bead(bead_set *s, const bead *b)
{
    if (s->n == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 1024;
        if (cap > (size_t)0x7fffffff) return SOAK_ERR_NOMEM;
        bead *v = realloc(s->v, cap * sizeof *v);
        if (!v) return SOAK_ERR_NOMEM;
        s->v = v, s->cap = cap;
    }
    s->v[s->n++] = *b;
    return SOAK_OK;
}

/* Adds a drop, merging it with every bead its outline reaches. */
static soak_status add_drop(bead_set *s, const soak_bead_drop *d)
{
    bead b = {wrap_coord(d->x, s->width), wrap_coord(d->y, s->height), d->volume_m3, 0, 0, -1, -1, 0};
    soak_status st = set_outline(s, &b);
    b.cell = cell_of(s, b.x, b.y);
    for (int o; st == SOAK_OK && (o = find_overlap(s, &b)) >= 0;) {
        const bead *other = &s->v[o];
        const double w = other->volume / (other->volume + b.volume);
        b.x = wrap_coord(b.x + w * wrap_delta(other->x - b.x, s->width), s->width);
        b.y = wrap_coord(b.y + w * wrap_delta(other->y - b.y, s->height), s->height);
        b.volume += other->volume;
        unlink_bead(s, o);
        st = set_outline(s, &b);
        b.cell = cell_of(s, b.x, b.y);
    }
    if (st == SOAK_OK) st = push_bead(s, &b);
    if (st == SOAK_OK) link_bead(s, (int)s->n - 1);
    return st;
}

/* ---- raster: mean height and normal over supersample^2 points ------------ */

typedef struct raster {
    double *h, *nx, *ny, *nz_missing; /* per texel sums; nz_missing counts points on a bead */
    int width, height, ss;
    double texel_m;
} raster;

static void stamp_bead(raster *ra, const bead *b, const soak_bead_shape *shape)
{
    const int ss = ra->ss, reach = (int)ceil(b->outline_tx) + 1;
    const double R = shape->sphere_radius_m, z0 = shape->height_m - R;
    for (int ty = (int)floor(b->y) - reach; ty <= (int)floor(b->y) + reach; ++ty)
        for (int tx = (int)floor(b->x) - reach; tx <= (int)floor(b->x) + reach; ++tx) {
            const size_t i = (size_t)((ty % ra->height + ra->height) % ra->height) * ra->width +
                             (size_t)((tx % ra->width + ra->width) % ra->width);
            for (int sy = 0; sy < ss; ++sy)
                for (int sx = 0; sx < ss; ++sx) {
                    double dx = (tx + (sx + 0.5) / ss - b->x) * ra->texel_m;
                    double dy = (ty + (sy + 0.5) / ss - b->y) * ra->texel_m;
                    double rho = sqrt(dx * dx + dy * dy), z = soak_bead_surface(shape, rho);
                    if (!(rho < shape->outline_m) || z <= 0) continue;
                    double nz = z - z0; /* the sphere's normal (p - centre) / R; rows grow down, v up */
                    ra->h[i] += z;
                    ra->nx[i] += dx / R, ra->ny[i] += -dy / R, ra->nz_missing[i] += 1.0 - nz / R;
                }
        }
}

static void encode(const raster *ra, const soak_beads_params *p, soak_image *out, soak_beads_stats *stats)
{
    const double pts = (double)ra->ss * ra->ss;
    for (size_t i = 0; i < (size_t)ra->width * ra->height; ++i) {
        double nx = ra->nx[i] / pts, ny = ra->ny[i] / pts, nz = 1.0 - ra->nz_missing[i] / pts;
        double len = sqrt(nx * nx + ny * ny + nz * nz);
        if (!(len > 1e-12)) nx = ny = 0, nz = len = 1;
        float *px = out->pixels + 4 * i;
        px[0] = (float)(0.5 * (nx / len + 1)), px[1] = (float)(0.5 * (ny / len + 1)),
        px[2] = (float)(0.5 * (nz / len + 1));
        double a = ra->h[i] / pts / p->height_range_m;
        if (a > 1) a = 1, ++stats->clipped_texels;
        px[3] = (float)a;
    }
}

static soak_status raster_beads(const bead_set *s, const soak_beads_params *p, soak_image *out, soak_beads_stats *stats)
{
    const size_t n = (size_t)s->width * s->height;
    raster ra = {calloc(n, sizeof(double)),
                 calloc(n, sizeof(double)),
                 calloc(n, sizeof(double)),
                 calloc(n, sizeof(double)),
                 s->width,
                 s->height,
                 p->supersample,
                 p->texel_m};
    soak_status st = ra.h && ra.nx && ra.ny && ra.nz_missing ? SOAK_OK : SOAK_ERR_NOMEM;
    const double l_c = sqrt(SOAK_WATER_SIGMA / (SOAK_WATER_RHO * SOAK_GRAVITY));
    for (size_t k = 0; st == SOAK_OK && k < s->n; ++k) {
        if (!s->v[k].alive) continue;
        soak_bead_shape shape;
        st = soak_bead_cap(s->v[k].volume, p->contact_angle_deg, &shape);
        if (st != SOAK_OK) break;
        stamp_bead(&ra, &s->v[k], &shape);
        ++stats->beads;
        stats->bead_volume_m3 += s->v[k].volume;
        stats->column_volume_m3 += soak_bead_column_volume(&shape);
        if (shape.contact_radius_m > stats->largest_contact_radius_m)
            stats->largest_contact_radius_m = shape.contact_radius_m;
        stats->beyond_capillary += shape.contact_radius_m > l_c;
    }
    if (st == SOAK_OK) st = soak_image_alloc(out, s->width, s->height, 4);
    if (st == SOAK_OK) encode(&ra, p, out, stats);
    free(ra.h), free(ra.nx), free(ra.ny), free(ra.nz_missing);
    return st;
}

static soak_status check_drops(const soak_bead_drop *drops, size_t n)
{
    if (n > SOAK_BEADS_MAX_DROPS) return SOAK_ERR_ARG;
    if (n && !drops) return SOAK_ERR_NULL;
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(drops[i].x) || !isfinite(drops[i].y) || !(fabs(drops[i].x) < 1e9 && fabs(drops[i].y) < 1e9) ||
            !soak_in_range(drops[i].volume_m3, 1e-30, 1e-3))
            return SOAK_ERR_ARG;
    return SOAK_OK;
}

soak_status soak_beads_from_drops(const soak_beads_params *p, int width, int height, const soak_bead_drop *drops,
                                  size_t n, const soak_bake_exec *exec, soak_image *out, soak_beads_stats *stats)
{
    if (!p || !out) return SOAK_ERR_NULL;
    soak_beads_stats local;
    stats = stats ? stats : &local;
    memset(stats, 0, sizeof *stats);
    soak_status st = soak_beads_check(p);
    if (st == SOAK_OK) st = soak_bake_check_size(width, height);
    if (st == SOAK_OK) st = check_drops(drops, n);
    if (st != SOAK_OK) return st;
    bead_set s = {NULL,
                  0,
                  0,
                  NULL,
                  (width + GRID_CELL - 1) / GRID_CELL,
                  (height + GRID_CELL - 1) / GRID_CELL,
                  width,
                  height,
                  p->contact_angle_deg,
                  p->texel_m,
                  0};
    s.head = malloc((size_t)s.gx * s.gy * sizeof *s.head);
    if (!s.head) return SOAK_ERR_NOMEM;
    for (size_t c = 0; c < (size_t)s.gx * s.gy; ++c) s.head[c] = -1;
    for (size_t i = 0; st == SOAK_OK && i < n; ++i) {
        st = add_drop(&s, &drops[i]);
        stats->drop_volume_m3 += drops[i].volume_m3;
        if (exec && exec->progress && (i & 4095) == 0) exec->progress(exec->progress_user, 0.8 * (double)i / n);
    }
    stats->drops = n;
    if (st == SOAK_OK) st = raster_beads(&s, p, out, stats);
    if (exec && exec->progress && st == SOAK_OK) exec->progress(exec->progress_user, 1.0);
    free(s.v), free(s.head);
    return st;
}

soak_status soak_beads_bake(const soak_beads_params *p, int width, int height, const soak_bake_exec *exec,
                            soak_image *out, soak_beads_stats *stats)
{
    if (!p || !out) return SOAK_ERR_NULL;
    soak_status st = soak_beads_check(p);
    if (st != SOAK_OK) return st;
    soak_drops_params dp;
    soak_drops_defaults(&dp);
    dp.seed = p->seed, dp.rate_mm_h = p->rate_mm_h, dp.texel_m = p->texel_m;
    dp.min_diameter_mm = p->min_diameter_mm, dp.duration = p->duration, dp.wrap = 1;
    soak_drop_impact *imp = NULL;
    size_t count = 0;
    st = soak_drops_impacts(&dp, NULL, width, height, 0, (long)ceil(p->duration / SOAK_DROPS_SLAB), &imp, &count);
    soak_bead_drop *drops = st == SOAK_OK && count ? malloc(count * sizeof *drops) : NULL;
    if (st == SOAK_OK && count && !drops) st = SOAK_ERR_NOMEM;
    size_t n = 0;
    for (size_t i = 0; st == SOAK_OK && i < count; ++i)
        if (imp[i].t < p->duration) {
            const double d = imp[i].d_mm * 1e-3;
            drops[n++] = (soak_bead_drop){imp[i].x, imp[i].y, PI * d * d * d / 6.0};
        }
    free(imp);
    if (st == SOAK_OK) st = soak_beads_from_drops(p, width, height, drops, n, exec, out, stats);
    free(drops);
    return st;
}
