/* Knots and base-colour tables of soak export (soak/export.h): where the
 * front ends' linear interpolation needs nodes so that it stays within the
 * stated tolerance of soak_wetness_eval. */
#include "soak/export.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "soak/sheet.h"

#define PROBES 7            /* interior test points per knot interval */
#define BASE_PROBES 3       /* per base-table interval (its checks run on a grid) */
#define MIN_WIDTH (1.0 / 4096.0)
#define SAFETY 0.5          /* refine until half the tolerance */

/* ---- the quantities a front end interpolates ---------------------------- */

enum { MAX_Q = 40, VIEW_PAIRS = 9 };

/* Quantities in [0, ~1] compared absolutely; coefficients (1/m, thousands)
 * relative to their magnitude, as export.h states. */
static int quantities(const soak_wet_params *p, double sheet_m, double sheet_ior, double *q)
{
    int n = 0;
    if (sheet_m > 0.0) {
        /* thin-sheet transmittance spans decades (1e-3 .. 1): followed in
         * log, 0.1 ln T, so the absolute tolerance is ~2 % relative */
        soak_rgb T;
        if (soak_sheet_transmittance(p, sheet_m, sheet_ior, &T) == SOAK_OK)
            for (int c = 0; c < 3; ++c) q[n++] = 0.1 * log(fmax(soak_rgb_at(T, c), 1e-6));
    }
    const soak_rgb *rgb[] = {&p->albedo, &p->albedo_total, &p->albedo_subsurface, &p->albedo_film, &p->omega};
    for (size_t k = 0; k < sizeof rgb / sizeof rgb[0]; ++k)
        for (int c = 0; c < 3; ++c) q[n++] = soak_rgb_at(*rgb[k], c);
    q[n++] = p->fill;
    q[n++] = p->film_coverage;
    q[n++] = p->ggx_alpha;
    q[n++] = sqrt(p->ggx_alpha);
    q[n++] = p->phase.g1;
    q[n++] = p->phase.g2;
    q[n++] = p->phase.w;
    q[n++] = p->mean_cosine;
    q[n++] = p->specular_weight;
    q[n++] = p->water_specular_weight;
    for (int c = 0; c < 3; ++c) {
        double ss = soak_rgb_at(p->sigma_s_per_m, c), sa = soak_rgb_at(p->sigma_a_per_m, c);
        double scale = 1.0 + ss + sa;
        q[n++] = ss / scale;
        q[n++] = sa / scale;
    }
    return n;
}

typedef struct knot_ctx {
    const soak_preset *preset;
    const soak_liquid *liquid;
    double film_m;
} knot_ctx;

static soak_status eval_at(const knot_ctx *k, double w, double *q, int *nq)
{
    soak_wet_input in = soak_wet_input_steady(k->preset, w);
    in.film_thickness_m = k->film_m;
    soak_wet_params p;
    soak_status st = soak_wetness_eval(k->preset, k->liquid, &in, &p);
    if (st != SOAK_OK) return st;
    *nq = quantities(&p, k->preset->kind == SOAK_KIND_THIN_SHEET ? k->preset->thickness_m : 0.0, k->preset->ior, q);
    /* the view factor at 0, 60 and 75.5 deg, after the albedo it multiplies:
     * q[*nq ..] = 9 albedos, then 9 factors (VIEW_PAIRS) */
    const double views[3] = {1.0, 0.5, 0.25};
    for (int v = 0; v < 3; ++v) {
        soak_rgb f;
        st = soak_wetness_view_factor(k->preset, k->liquid, &p, views[v], &f);
        if (st != SOAK_OK) return st;
        for (int c = 0; c < 3; ++c) {
            q[*nq + 3 * v + c] = soak_rgb_at(p.albedo, c);
            q[*nq + VIEW_PAIRS + 3 * v + c] = soak_rgb_at(f, c);
        }
    }
    return SOAK_OK;
}

/* A front end multiplies the interpolated albedo by the interpolated view
 * factor: the error that counts is that product's, not the factor's alone
 * (where the albedo vanishes, under a black coffee film, a steep factor
 * multiplies nothing). */
static double view_error(const double *qa, const double *qb, const double *qm, double t)
{
    double worst = 0.0;
    for (int j = 0; j < VIEW_PAIRS; ++j) {
        double albedo = qa[j] + (qb[j] - qa[j]) * t;
        double factor = qa[VIEW_PAIRS + j] + (qb[VIEW_PAIRS + j] - qa[VIEW_PAIRS + j]) * t;
        worst = fmax(worst, fabs(albedo * factor - qm[j] * qm[VIEW_PAIRS + j]));
    }
    return worst;
}

/* Largest error of linear interpolation over [a, b] at PROBES points. */
static soak_status interval_error(const knot_ctx *k, double a, double b, double *err)
{
    double qa[MAX_Q + 2 * VIEW_PAIRS], qb[MAX_Q + 2 * VIEW_PAIRS], qm[MAX_Q + 2 * VIEW_PAIRS];
    int n = 0;
    soak_status st = eval_at(k, a, qa, &n);
    if (st == SOAK_OK) st = eval_at(k, b, qb, &n);
    *err = 0.0;
    for (int i = 1; st == SOAK_OK && i <= PROBES; ++i) {
        double t = (double)i / (PROBES + 1);
        st = eval_at(k, a + (b - a) * t, qm, &n);
        for (int j = 0; st == SOAK_OK && j < n; ++j) {
            double e = fabs(qa[j] + (qb[j] - qa[j]) * t - qm[j]);
            if (e > *err) *err = e;
        }
        if (st == SOAK_OK) *err = fmax(*err, view_error(qa + n, qb + n, qm + n, t));
    }
    return st;
}

/* Refines [a, b] by bisection, appending knots (b included) to out. */
static soak_status refine(const knot_ctx *k, double a, double b, double *out, int max, int *n)
{
    double e = 0.0;
    soak_status st = interval_error(k, a, b, &e);
    if (st != SOAK_OK) return st;
    if (e > SAFETY * SOAK_EXPORT_KNOT_TOL && b - a > MIN_WIDTH) {
        double m = 0.5 * (a + b);
        st = refine(k, a, m, out, max, n);
        if (st == SOAK_OK) st = refine(k, m, b, out, max, n);
        return st;
    }
    if (*n >= max) return SOAK_ERR_ARG;
    out[(*n)++] = b;
    return SOAK_OK;
}

static int porous_saturation(const soak_preset *p, double *w_sat)
{
    *w_sat = soak_material_kind_porous(p->kind) ? p->porosity : 0.0;
    return *w_sat > 0.0 && *w_sat < 1.0;
}

soak_status soak_export_knots(const soak_preset *preset, const soak_liquid *liquid, double film_thickness_m,
                              double *knots, int max, int *n)
{
    if (!preset || !liquid || !knots || !n) return SOAK_ERR_NULL;
    if (max < 2 || !(film_thickness_m <= SOAK_WET_FILM_MAX_M)) return SOAK_ERR_ARG;
    knot_ctx k = {preset, liquid, film_thickness_m < 0.0 ? preset->film_thickness_m : film_thickness_m};
    int count = 0;
    knots[count++] = 0.0;
    double w_sat = 0.0;
    soak_status st = SOAK_OK;
    if (porous_saturation(preset, &w_sat)) st = refine(&k, 0.0, w_sat, knots, max, &count);
    if (st == SOAK_OK) st = refine(&k, count > 1 ? w_sat : 0.0, 1.0, knots, max, &count);
    if (st != SOAK_OK) return st;
    *n = count;
    return SOAK_OK;
}

/* ---- base-colour table nodes -------------------------------------------- */

/* Refinement passes probe the same grid points again and again: a small
 * open-addressing memo of (a, w) -> values, owned by the call. */
#define MEMO_BITS 16
#define MEMO_SIZE (1u << MEMO_BITS)

typedef struct memo_entry {
    double a, w;
    double q[6];
    int used;
} memo_entry;

typedef struct base_ctx {
    const soak_preset *preset;
    const soak_liquid *liquid;
    memo_entry *memo; /* MEMO_SIZE entries, or NULL */
} base_ctx;

static unsigned memo_slot(double a, double w)
{
    uint64_t x, y;
    memcpy(&x, &a, sizeof x);
    memcpy(&y, &w, sizeof y);
    uint64_t h = (x * 0x9e3779b97f4a7c15ULL) ^ (y + 0x632be59bd9b4e019ULL + (x << 6));
    h ^= h >> 29;
    h *= 0xbf58476d1ce4e5b9ULL;
    return (unsigned)(h >> (64 - MEMO_BITS));
}

static soak_status base_eval_uncached(const base_ctx *b, double a, double w, double q[6])
{
    soak_wet_input in = soak_wet_input_steady(b->preset, w);
    soak_wet_params p;
    soak_status st = soak_wet_params_for_base(b->preset, b->liquid, &in, (soak_rgb){a, a, a}, &p);
    if (st != SOAK_OK) return st;
    for (int c = 0; c < 3; ++c) {
        q[c] = soak_rgb_at(p.albedo, c);
        q[3 + c] = soak_rgb_at(p.albedo_total, c);
    }
    return SOAK_OK;
}

/* albedo and albedo_total, three channels each, at grey dry albedo a. */
static soak_status base_eval(const base_ctx *b, double a, double w, double q[6])
{
    if (!b->memo) return base_eval_uncached(b, a, w, q);
    unsigned i = memo_slot(a, w);
    for (unsigned probe = 0; probe < 8; ++probe, i = (i + 1) & (MEMO_SIZE - 1)) {
        memo_entry *e = &b->memo[i];
        if (e->used && e->a == a && e->w == w) {
            memcpy(q, e->q, sizeof e->q);
            return SOAK_OK;
        }
        if (!e->used) {
            soak_status st = base_eval_uncached(b, a, w, q);
            if (st != SOAK_OK) return st;
            e->a = a;
            e->w = w;
            memcpy(e->q, q, sizeof e->q);
            e->used = 1;
            return SOAK_OK;
        }
    }
    return base_eval_uncached(b, a, w, q); /* neighbourhood full */
}

/* Error of linear interpolation along one axis (a when along_a, else w)
 * over [lo, hi] with the other coordinate fixed at other. */
static soak_status base_interval_error(const base_ctx *b, int along_a, double lo, double hi, double other,
                                       double *err)
{
    double q0[6], q1[6], qm[6];
    soak_status st = along_a ? base_eval(b, lo, other, q0) : base_eval(b, other, lo, q0);
    if (st == SOAK_OK) st = along_a ? base_eval(b, hi, other, q1) : base_eval(b, other, hi, q1);
    for (int i = 1; st == SOAK_OK && i <= BASE_PROBES; ++i) {
        double t = (double)i / (BASE_PROBES + 1), x = lo + (hi - lo) * t;
        st = along_a ? base_eval(b, x, other, qm) : base_eval(b, other, x, qm);
        for (int j = 0; st == SOAK_OK && j < 6; ++j) {
            double e = fabs(q0[j] + (q1[j] - q0[j]) * t - qm[j]);
            if (e > *err) *err = e;
        }
    }
    return st;
}

/* One refinement pass along an axis: splits every interval whose error, at
 * any of the other axis' probe values, exceeds the budget. Returns the
 * number of splits in *splits. */
static soak_status refine_axis(const base_ctx *b, int along_a, double *nodes, int *n, int max, const double *other,
                               int n_other, double budget, int *splits)
{
    double out[SOAK_EXPORT_KNOTS_MAX];
    int m = 0;
    *splits = 0;
    out[m++] = nodes[0];
    for (int i = 0; i + 1 < *n; ++i) {
        double lo = nodes[i], hi = nodes[i + 1], err = 0.0;
        for (int j = 0; j < n_other; ++j) {
            double o = other[j];
            soak_status st = base_interval_error(b, along_a, lo, hi, o, &err);
            if (st != SOAK_OK) return st;
            /* midpoints of the other axis too: bilinear error lives there */
            if (j + 1 < n_other) {
                st = base_interval_error(b, along_a, lo, hi, 0.5 * (o + other[j + 1]), &err);
                if (st != SOAK_OK) return st;
            }
        }
        if (err > budget && hi - lo > MIN_WIDTH) {
            if (m + 2 > max || m + 2 > SOAK_EXPORT_KNOTS_MAX) return SOAK_ERR_ARG;
            out[m++] = 0.5 * (lo + hi);
            ++*splits;
        }
        if (m + 1 > max || m + 1 > SOAK_EXPORT_KNOTS_MAX) return SOAK_ERR_ARG;
        out[m++] = hi;
    }
    memcpy(nodes, out, (size_t)m * sizeof *nodes);
    *n = m;
    return SOAK_OK;
}

soak_status soak_export_base_nodes(const soak_preset *preset, const soak_liquid *liquid, double *albedo_nodes,
                                   int max_albedo, int *n_albedo, double *wet_knots, int max_wet, int *n_wet)
{
    if (!preset || !liquid || !albedo_nodes || !n_albedo || !wet_knots || !n_wet) return SOAK_ERR_NULL;
    if (max_albedo < 5 || max_wet < 2) return SOAK_ERR_ARG;
    base_ctx b = {preset, liquid, calloc(MEMO_SIZE, sizeof(memo_entry))};
    int na = 5, nw = 0;
    for (int i = 0; i < na; ++i) albedo_nodes[i] = i / 4.0;
    soak_status st = soak_export_knots(preset, liquid, -1.0, wet_knots, max_wet, &nw);
    /* Each axis gets 0.4 of the tolerance: bilinear error <= sum of both. */
    const double budget = 0.4 * SOAK_EXPORT_BASE_TOL;
    for (int pass = 0; st == SOAK_OK && pass < 12; ++pass) {
        int sa = 0, sw = 0;
        st = refine_axis(&b, 1, albedo_nodes, &na, max_albedo, wet_knots, nw, budget, &sa);
        if (st == SOAK_OK) st = refine_axis(&b, 0, wet_knots, &nw, max_wet, albedo_nodes, na, budget, &sw);
        if (sa + sw == 0) break;
    }
    free(b.memo);
    if (st != SOAK_OK) return st;
    *n_albedo = na;
    *n_wet = nw;
    return SOAK_OK;
}

soak_status soak_export_view_factors(const soak_preset *preset, const soak_liquid *liquid, const soak_wet_params *w,
                                     soak_rgb out[SOAK_EXPORT_VIEW_N])
{
    if (!out) return SOAK_ERR_NULL;
    soak_status st = SOAK_OK;
    for (int i = 0; st == SOAK_OK && i < SOAK_EXPORT_VIEW_N; ++i)
        st = soak_wetness_view_factor(preset, liquid, w, (double)i / (SOAK_EXPORT_VIEW_N - 1), &out[i]);
    return st;
}
