/* Wetness-modulated parameter volumes (model and formulas in
 * soak/bake_volume.h). */
#include "soak/bake_volume.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "soak/hg.h"
#include "soak/units.h"
#include "soak/wetness.h"

/* Antiderivative of p from 0 to d: P(d) = d - delta (t^3 - t^4/2), t = d/delta,
 * for d <= delta; delta/2 beyond (integral of 3t^2 - 2t^3 is t^3 - t^4/2). */
static double profile_integral(double d, double delta)
{
    if (d >= delta) return 0.5 * delta;
    double t = d / delta;
    return d - delta * (t * t * t - 0.5 * t * t * t * t);
}

double soak_wet_profile(double depth, double delta)
{
    if (!(depth >= 0.0) || !(delta > 0.0) || depth >= delta) return 0.0; /* delta = 0: no penetration */
    double t = depth / delta;
    return 1.0 - t * t * (3.0 - 2.0 * t);
}

double soak_wet_profile_mean(double d0, double d1, double delta)
{
    if (!(d0 >= 0.0 && d1 >= d0) || !(delta > 0.0)) return 0.0;
    if (d1 - d0 <= 1e-12 * (d1 + delta)) return soak_wet_profile(0.5 * (d0 + d1), delta);
    return (profile_integral(d1, delta) - profile_integral(d0, delta)) / (d1 - d0);
}

/* Bilinear lookup, clamp to edge; (u, v) in [0,1]^2 with v = 0 at the bottom
 * image row (y = 0 of the box) and v = 1 at the top row. Mean of the colour
 * channels (alpha ignored). */
static double map_lookup(const soak_image *img, double u, double v)
{
    int colours = img->channels >= 3 ? 3 : 1;
    double px = u * img->width - 0.5, py = (1.0 - v) * img->height - 0.5;
    double fx = floor(px), fy = floor(py);
    double ax = px - fx, ay = py - fy;
    double sum = 0.0;
    for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
            int x = (int)fx + dx, y = (int)fy + dy;
            x = x < 0 ? 0 : (x >= img->width ? img->width - 1 : x);
            y = y < 0 ? 0 : (y >= img->height ? img->height - 1 : y);
            const float *p = img->pixels + ((size_t)y * img->width + x) * img->channels;
            double val = 0.0;
            for (int c = 0; c < colours; ++c) val += p[c];
            val /= colours;
            sum += (dx ? ax : 1.0 - ax) * (dy ? ay : 1.0 - ay) * val;
        }
    return sum;
}

/* Surface wetness averaged over the top-face footprint of column (i, j):
 * s x s bilinear samples, s = texels per voxel rounded up (box filter, so a
 * fine map is not aliased by a coarse grid). */
static soak_status column_wetness(const soak_volume *v, const soak_image *img, int i, int j, double *out)
{
    double tx = (double)img->width / v->nx, ty = (double)img->height / v->ny;
    int s = (int)ceil(tx > ty ? tx : ty);
    if (s < 1) s = 1;
    if (s > 16) s = 16;
    double sum = 0.0;
    for (int b = 0; b < s; ++b)
        for (int a = 0; a < s; ++a) {
            double u = (i + (a + 0.5) / s) / v->nx, w = (j + (b + 0.5) / s) / v->ny;
            double val = map_lookup(img, u, w);
            if (val != val) return SOAK_ERR_ARG;
            sum += val < 0.0 ? 0.0 : (val > 1.0 ? 1.0 : val);
        }
    *out = sum / ((double)s * s);
    return SOAK_OK;
}

soak_status soak_vol_rows_from_preset(const soak_preset *preset, const soak_liquid *liquid, double m_per_unit,
                                      int n_rows, soak_vol_medium *rows)
{
    if (!preset || !liquid || !rows) return SOAK_ERR_NULL;
    if (!soak_in_range(m_per_unit, 1e-12, 1e6) || n_rows < 2 || n_rows > SOAK_VOL_ROWS_MAX) return SOAK_ERR_ARG;
    if (preset->kind == SOAK_KIND_CONDUCTOR) return SOAK_ERR_ARG;
    soak_wet_params *t = malloc((size_t)n_rows * sizeof *t);
    if (!t) return SOAK_ERR_NOMEM;
    soak_status st = soak_wetness_table(preset, liquid, n_rows, -1.0, t);
    for (int i = 0; i < n_rows && st == SOAK_OK; ++i) {
        rows[i].sigma_s = soak_rgb_per_unit_from_per_m(t[i].sigma_s_per_m, m_per_unit);
        rows[i].sigma_a = soak_rgb_per_unit_from_per_m(t[i].sigma_a_per_m, m_per_unit);
        rows[i].g1 = t[i].phase.g1;
        rows[i].g2 = t[i].phase.g2;
        rows[i].w = t[i].phase.w;
        if (soak_vol_medium_validate(&rows[i]) != SOAK_OK) st = SOAK_ERR_NUMERIC;
    }
    free(t);
    return st;
}

static void store_voxel(const soak_volume *v, size_t idx, double wet, const soak_vol_medium *rows, int n_rows)
{
    size_t n = soak_volume_count(v);
    soak_vol_medium m = soak_vol_rows_eval(rows, n_rows, wet);
    for (int c = 0; c < 3; ++c) {
        v->data[(SOAK_VOL_SIGMA_S_R + c) * n + idx] = (float)soak_rgb_at(m.sigma_s, c);
        v->data[(SOAK_VOL_SIGMA_A_R + c) * n + idx] = (float)soak_rgb_at(m.sigma_a, c);
    }
    v->data[SOAK_VOL_G1 * n + idx] = (float)m.g1;
    v->data[SOAK_VOL_G2 * n + idx] = (float)m.g2;
    v->data[SOAK_VOL_W * n + idx] = (float)m.w;
    v->data[SOAK_VOL_WETNESS * n + idx] = (float)wet;
}

soak_status soak_vol_turbulence_check(const soak_vol_turbulence *t)
{
    if (!t) return SOAK_ERR_NULL;
    if (!(t->length > 0.0 && soak_is_finite(t->length))) return SOAK_ERR_ARG;
    return soak_turbulence_check(&t->params);
}

double soak_vol_turbulence_wetness(void *ctx, double x, double y, double z)
{
    const soak_vol_turbulence *t = ctx;
    const soak_turbulence_params *p = &t->params;
    double f = p->frequency / t->length, amp = 1.0, sum = 0.0, norm = 0.0;
    for (int o = 0; o < p->octaves; ++o) {
        double n = soak_noise3(soak_seed_derive(p->seed, (uint64_t)o), f * x, f * y, f * z, 0, 0, 0);
        sum += amp * (p->sum == SOAK_NOISE_TURBULENCE ? fabs(n) : n);
        norm += amp;
        amp *= p->gain;
        f *= p->lacunarity;
    }
    double v = norm > 0.0 ? sum / norm : 0.0;
    double w;
    if (p->thresholded) w = soak_smoothstep(p->threshold - p->softness, p->threshold + p->softness, v);
    else w = p->sum == SOAK_NOISE_TURBULENCE ? v : 0.5 + 0.5 * v;
    return w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w);
}

typedef struct bake_job {
    soak_volume *v;
    const soak_vol_medium *rows;
    int n_rows;
    const soak_volume_source *src;
    double *column;      /* nx*ny surface wetness (map mode) */
    const double *layer; /* nz profile means */
    unsigned char *bad;  /* per line: NaN met */
} bake_job;

/* Line `line` of the map pass: row j of columns. */
static void column_line(void *ctx, int j, int thread)
{
    (void)thread;
    bake_job *b = ctx;
    for (int i = 0; i < b->v->nx; ++i)
        if (column_wetness(b->v, b->src->surface_map, i, j, &b->column[(size_t)j * b->v->nx + i]) != SOAK_OK)
            b->bad[j] = 1;
}

/* Line (j, k) = line index k*ny + j of the voxel pass. */
static void voxel_line(void *ctx, int line, int thread)
{
    (void)thread;
    bake_job *b = ctx;
    soak_volume *v = b->v;
    int j = line % v->ny, k = line / v->ny;
    double dx = v->size[0] / v->nx, dy = v->size[1] / v->ny, dz = v->size[2] / v->nz;
    for (int i = 0; i < v->nx; ++i) {
        double w;
        if (b->src->wetness3d) {
            w = b->src->wetness3d(b->src->wetness3d_ctx, (i + 0.5) * dx, (j + 0.5) * dy, (k + 0.5) * dz);
            if (w != w) {
                b->bad[line] = 1;
                w = 0.0;
            }
            w = w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w);
        } else {
            double surf = b->column ? b->column[(size_t)j * v->nx + i] : b->src->surface_wetness;
            w = surf * b->layer[k];
        }
        store_voxel(v, soak_volume_index(v, i, j, k), w, b->rows, b->n_rows);
    }
}

soak_status soak_volume_bake(soak_volume *v, const soak_vol_medium *rows, int n_rows, const soak_volume_source *src,
                             const soak_bake_exec *exec)
{
    if (!v || !v->data || !rows || !src) return SOAK_ERR_NULL;
    if (n_rows < 2 || n_rows > SOAK_VOL_ROWS_MAX) return SOAK_ERR_ARG;
    for (int i = 0; i < n_rows; ++i)
        if (soak_vol_medium_validate(&rows[i]) != SOAK_OK) return SOAK_ERR_ARG;
    if (!soak_in_range(src->penetration_depth, 0.0, 1e30)) return SOAK_ERR_ARG;
    if (!src->wetness3d && !src->surface_map && !soak_in_range(src->surface_wetness, 0.0, 1.0)) return SOAK_ERR_ARG;
    if (!src->wetness3d && src->surface_map &&
        (!src->surface_map->pixels || src->surface_map->width < 1 || src->surface_map->height < 1 ||
         src->surface_map->channels < 1))
        return SOAK_ERR_ARG;
    if (exec && soak_bake_threads(exec) == 0) return SOAK_ERR_ARG;

    int lines = v->ny * v->nz;
    bake_job b = {v, rows, n_rows, src, NULL, NULL, NULL};
    double *layer = malloc((size_t)v->nz * sizeof *layer);
    b.bad = calloc((size_t)lines, 1); /* lines >= ny: also serves the map pass */
    int map_pass = !src->wetness3d && src->surface_map;
    if (map_pass) b.column = malloc((size_t)v->nx * v->ny * sizeof *b.column);
    soak_status st = layer && b.bad && (!map_pass || b.column) ? SOAK_OK : SOAK_ERR_NOMEM;
    if (st == SOAK_OK) {
        /* Depth profile of each layer (the top layer k = nz-1 touches the surface). */
        double dz = v->size[2] / v->nz;
        for (int k = 0; k < v->nz; ++k)
            layer[k] = soak_wet_profile_mean((v->nz - 1 - k) * dz, (v->nz - k) * dz, src->penetration_depth);
        b.layer = layer;
        if (map_pass) {
            st = soak_parallel_rows(v->ny, exec, column_line, &b, 0.0, 0.2);
            for (int j = 0; j < v->ny && st == SOAK_OK; ++j)
                if (b.bad[j]) st = SOAK_ERR_ARG;
        }
    }
    if (st == SOAK_OK) {
        memset(b.bad, 0, (size_t)lines);
        st = soak_parallel_rows(lines, exec, voxel_line, &b, map_pass ? 0.2 : 0.0, 1.0);
        for (int l = 0; l < lines && st == SOAK_OK; ++l)
            if (b.bad[l]) st = SOAK_ERR_ARG;
    }
    free(layer);
    free(b.bad);
    free(b.column);
    return st;
}
