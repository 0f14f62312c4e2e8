/* The rain bake's routing along the surface's steepest descent
 * (soak/bake_rain.h step 3, bake_rain_flow.c):
 *  - a uniform 30 deg plane carries a uniform film to its bottom edge: the
 *    film of every texel of the bottom row within 1 % of Nusselt's
 *    h = (3 mu q / (rho g sin theta))^(1/3) with q = rainfall * E * L
 *    evaluated here, for the UV layout as laid out and turned by 90, 30,
 *    45, 60 and 200 deg (the flow then runs across texel rows or diagonally), six
 *    texels clear of the side edges;
 *  - a ledge's rain shadow on a wall stays dry in steady slanting rain:
 *    at least 95 % of the shadow (from the ledge's geometry, worked out
 *    here) has a film under the 1 um running-film threshold, for the wall's
 *    UV layout turned by 0, 30, 45, 90, 135 and 200 deg;
 *  - mass: on the ledged wall the rain in equals dripped + held +
 *    evaporated (1e-9), and it equals rainfall * (the wall's area in the
 *    rain less the shadow's) to 2 %;
 *  - puddles level: on a plane rising 0.2 m per metre with a Gaussian dip,
 *    the water in the dip stands no higher than its sill (the saddle of
 *    z(t) along the dip's axis, found here by bisection on dz/dt = 0), its
 *    surface is flat, and in = dripped + held + evaporated. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "surface_mesh.h"
#include "soak/bake_rain.h"

/* Water at 20 C (CRC Handbook) and standard gravity, written out here. */
static const double MU = 1.002e-3, RHO = 998.2, G = 9.80665;
static const double FILM_DRY = 1e-6; /* the running-film threshold of soak/bake_rain.h, written out */

/* A mesh under construction (vertices with UVs, triangles). */
typedef struct builder {
    soak_mesh m;
    size_t cap_v, cap_t;
} builder;

static unsigned add_vertex(builder *b, double x, double y, double z, double u, double v)
{
    if (b->m.n_vertices == b->cap_v) {
        b->cap_v = b->cap_v ? 2 * b->cap_v : 256;
        b->m.positions = realloc(b->m.positions, 3 * b->cap_v * sizeof(double));
        b->m.uvs = realloc(b->m.uvs, 2 * b->cap_v * sizeof(double));
    }
    size_t k = b->m.n_vertices++;
    double *p = b->m.positions + 3 * k, *t = b->m.uvs + 2 * k;
    p[0] = x, p[1] = y, p[2] = z, t[0] = u, t[1] = v;
    return (unsigned)k;
}

static void add_triangle(builder *b, unsigned a, unsigned c, unsigned d)
{
    if (b->m.n_triangles == b->cap_t) {
        b->cap_t = b->cap_t ? 2 * b->cap_t : 256;
        b->m.indices = realloc(b->m.indices, 3 * b->cap_t * sizeof(unsigned));
    }
    unsigned *t = b->m.indices + 3 * b->m.n_triangles++;
    t[0] = a, t[1] = c, t[2] = d;
}

static void builder_free(builder *b)
{
    free(b->m.positions);
    free(b->m.uvs);
    free(b->m.indices);
}

/* The UV of chart point (s, t) in [0,1]^2: scaled by 0.7 about the centre
 * and turned by deg, so that every turn fits the unit square. */
static void chart_uv(double s, double t, double deg, double uv[2])
{
    double c = cos(deg * SOAK_PI / 180.0), n = sin(deg * SOAK_PI / 180.0), a = 0.7 * (s - 0.5), b = 0.7 * (t - 0.5);
    uv[0] = 0.5 + c * a - n * b;
    uv[1] = 0.5 + n * a + c * b;
}

/* The chart point of image texel (x, y) of an N x N map (inverse of the above). */
static void texel_chart(int x, int y, int N, double deg, double st[2])
{
    double u = (x + 0.5) / N - 0.5, v = 1.0 - (y + 0.5) / N - 0.5;
    double c = cos(deg * SOAK_PI / 180.0), n = sin(deg * SOAK_PI / 180.0);
    st[0] = 0.5 + (c * u + n * v) / 0.7;
    st[1] = 0.5 + (-n * u + c * v) / 0.7;
}

typedef void (*place_fn)(double s, double t, double p[3]);

/* M x M quads of a unit chart placed by place, the cells for which skip
 * says 1 left out, UVs turned by deg. */
static void add_chart(builder *b, int M, place_fn place, double deg, int (*skip)(int i, int j, int M))
{
    for (int j = 0; j < M; ++j)
        for (int i = 0; i < M; ++i) {
            if (skip && skip(i, j, M)) continue;
            unsigned v[4];
            for (int k = 0; k < 4; ++k) {
                double s = (double)(i + (k == 1 || k == 2)) / M, t = (double)(j + (k >= 2)) / M, p[3], uv[2];
                place(s, t, p);
                chart_uv(s, t, deg, uv);
                v[k] = add_vertex(b, p[0], p[1], p[2], uv[0], uv[1]);
            }
            add_triangle(b, v[0], v[1], v[2]);
            add_triangle(b, v[0], v[2], v[3]);
        }
}

/* ---- the uniform plane ---- */

static const double THETA = 30.0 * SOAK_PI / 180.0;

/* Unit square rising with t at 30 deg (z up), normal (0, -sin, cos). */
static void tilted(double s, double t, double p[3])
{
    p[0] = s;
    p[1] = t * cos(THETA);
    p[2] = t * sin(THETA);
}

/* The texels measured: chart t from BAND_LO to BAND_HI texels above the
 * bottom edge (in a turned layout the last texels form a staircase whose
 * texels hold part of a texel's water), clear of the side edges by SIDE:
 * where a turned layout's side edge cuts the grid's diagonals, the
 * two-neighbour split starves the outermost texels (11 % thin at 1.5
 * texels, 30 deg; within 1 % from 6 texels on; a layout along the grid is
 * exact up to the edge). */
static const double BAND_LO = 1.5, BAND_HI = 4.0, SIDE = 6.0;

static void check_uniform_plane(double deg)
{
    const int N = 64;
    builder b;
    memset(&b, 0, sizeof b);
    add_chart(&b, 16, tilted, deg, NULL);
    soak_rain_params p;
    surface_rain_params(&p, soak_v3(0, 0, 1));
    soak_rain_result r;
    char err[256] = "", what[200];
    snprintf(what, sizeof what, "plane, UVs turned %g deg: bake", deg);
    if (!check_status(what, soak_bake_rain(&b.m, N, N, &p, NULL, &r, err, sizeof err), SOAK_OK)) {
        builder_free(&b);
        return;
    }
    /* Bottom-edge texels: covered, chart t within 1.5 texels of 0, s clear of the side edges by 1.5 texels. */
    double texel = 1.0 / (0.7 * N), rain = p.rainfall_mm_h / 3.6e6 * cos(THETA), worst = 0.0;
    int count = 0, worst_x = -1, worst_y = -1;
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            size_t i = (size_t)y * N + x;
            double st[2];
            texel_chart(x, y, N, deg, st);
            if (r.coverage.pixels[i] < 0.5f || st[1] < BAND_LO * texel || st[1] > BAND_HI * texel ||
                st[0] < SIDE * texel || st[0] > 1 - SIDE * texel)
                continue;
            double q = rain * (1.0 - st[1]), want = cbrt(3.0 * MU * q / (RHO * G * sin(THETA)));
            double e = fabs(r.film.pixels[i] / want - 1.0);
            ++count;
            if (e > worst) worst = e, worst_x = x, worst_y = y;
        }
    snprintf(what, sizeof what, "plane, UVs turned %g deg: %d bottom texels found", deg, count);
    check_true(what, count >= N / 2);
    snprintf(what, sizeof what,
             "plane, UVs turned %g deg: every film by the bottom edge within 1 %% of Nusselt (worst %.2f %% at %d,%d)",
             deg, 100 * worst, worst_x, worst_y);
    check_true(what, worst <= 0.01);
    printf("uniform plane, UVs turned %g deg: worst bottom-edge film error %.3f %%\n", deg, 100 * worst);
    if (deg == 0.0) { /* the report's column count: the bottom row, every column, edges included */
        int thin = 0, y;
        double edge = 0.0;
        for (y = N - 1; y >= 0 && r.coverage.pixels[(size_t)y * N + N / 2] < 0.5f; --y) continue;
        for (int x = 0, cols = 0; x < N; ++x) {
            size_t i = (size_t)y * N + x;
            double st[2];
            texel_chart(x, y, N, deg, st);
            if (r.coverage.pixels[i] < 0.5f) continue;
            double q = rain * (1.0 - st[1]), e = r.film.pixels[i] / cbrt(3.0 * MU * q / (RHO * G * sin(THETA))) - 1.0;
            thin += e < -0.05;
            if (cols++ == 0) edge = e;
        }
        printf("uniform plane: %d bottom-row columns > 5 %% thin, the first column %.1f %%\n", thin, 100 * edge);
    }
    soak_rain_result_free(&r);
    builder_free(&b);
}

/* ---- the ledge ---- */

/* The wall: x = s, z = t in [0,1]^2 at y = 0, facing -y; the ledge's box
 * spans x in [LX0, LX1], y in [-LD, 0], z in [LZ0, LZ1], and the wall has a
 * hole where the ledge meets it (its water drips off the hole's top edge,
 * as it would onto the ledge). */
static const double LX0 = 0.3, LX1 = 0.7, LZ0 = 0.55, LZ1 = 0.6, LD = 0.2;
enum { WALL_CELLS = 40 };

static void wall(double s, double t, double p[3]) { p[0] = s, p[1] = 0.0, p[2] = t; }

static int behind_ledge(int i, int j, int M)
{
    double s = (i + 0.5) / M, t = (j + 0.5) / M;
    return s > LX0 && s < LX1 && t > LZ0 && t < LZ1;
}

static void add_box(builder *b, const double lo[3], const double hi[3])
{
    unsigned v[8];
    for (int k = 0; k < 8; ++k) /* UVs off the map: the ledge occludes, it is not baked */
        v[k] = add_vertex(b, k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2], 5.0, 5.0);
    static const int F[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (int f = 0; f < 6; ++f) {
        add_triangle(b, v[F[f][0]], v[F[f][1]], v[F[f][2]]);
        add_triangle(b, v[F[f][0]], v[F[f][2]], v[F[f][3]]);
    }
}

static void check_ledge(double deg, double min_dry)
{
    const int N = 128;
    builder b;
    memset(&b, 0, sizeof b);
    add_chart(&b, WALL_CELLS, wall, deg, behind_ledge);
    double lo[3] = {LX0, -LD, LZ0}, hi[3] = {LX1, 0.0, LZ1};
    add_box(&b, lo, hi);
    soak_rain_params p;
    surface_rain_params(&p, soak_v3(0, -1, 1)); /* 45 deg onto the wall: its shadow is z in [LZ0 - LD, LZ0] */
    soak_rain_result r;
    char err[256] = "", what[200];
    snprintf(what, sizeof what, "ledge, UVs turned %g deg: bake", deg);
    if (!check_status(what, soak_bake_rain(&b.m, N, N, &p, NULL, &r, err, sizeof err), SOAK_OK)) {
        builder_free(&b);
        return;
    }
    double texel = 1.0 / (0.7 * N), m = 1.5 * texel;
    int shadow = 0, dry = 0;
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            size_t i = (size_t)y * N + x;
            double st[2];
            texel_chart(x, y, N, deg, st);
            if (r.coverage.pixels[i] < 0.5f || st[0] < LX0 + m || st[0] > LX1 - m || st[1] < LZ0 - LD + m ||
                st[1] > LZ0 - m)
                continue;
            ++shadow;
            dry += r.film.pixels[i] < FILM_DRY;
        }
    double frac = shadow ? (double)dry / shadow : 0.0;
    snprintf(what, sizeof what, "ledge, UVs turned %g deg: %d shadow texels found", deg, shadow);
    check_true(what, shadow > 100);
    snprintf(what, sizeof what, "ledge, UVs turned %g deg: >= 95 %% of the shadow under 1 um (%.1f %%)", deg,
             100 * frac);
    check_true(what, frac >= min_dry);
    printf("ledge, UVs turned %g deg: %.1f %% of the rain shadow dry\n", deg, 100 * frac);
    const soak_rain_runoff *o = &r.runoff;
    snprintf(what, sizeof what, "ledge, UVs turned %g deg: in = dripped + held + evaporated", deg);
    check_rel(what, o->dripped + o->held + o->evaporated, o->in, 1e-9);
    /* E = 1 on the open wall (rain at 45 deg onto a vertical face), 0 in the shadow and the hole. */
    double open = 1.0 - (LX1 - LX0) * (LD + (LZ1 - LZ0));
    snprintf(what, sizeof what, "ledge, UVs turned %g deg: in = rainfall * open wall area (2 %%)", deg);
    check_rel(what, o->in, p.rainfall_mm_h / 3.6e6 * open, 0.02);
    soak_rain_result_free(&r);
    builder_free(&b);
}

/* ---- the tilted dip ---- */

/* z = RISE t - DIP exp(-r^2 / (2 SIG2)), r from the chart's centre. */
static const double RISE = 0.2, DIP = 0.08, SIG2 = 0.01;

static void dipped(double s, double t, double p[3])
{
    double r2 = (s - 0.5) * (s - 0.5) + (t - 0.5) * (t - 0.5);
    p[0] = s, p[1] = t, p[2] = RISE * t - DIP * exp(-r2 / (2 * SIG2));
}

static double dip_z(double t) { return RISE * t - DIP * exp(-(t - 0.5) * (t - 0.5) / (2 * SIG2)); }
static double dip_dz(double t) { return RISE + DIP * (t - 0.5) / SIG2 * exp(-(t - 0.5) * (t - 0.5) / (2 * SIG2)); }

/* The root of dz/dt in [a, b] (a sign change), by bisection. */
static double dz_root(double a, double b)
{
    for (int k = 0; k < 100; ++k) {
        double m = 0.5 * (a + b);
        if ((dip_dz(m) > 0) == (dip_dz(a) > 0)) a = m;
        else b = m;
    }
    return 0.5 * (a + b);
}

static void check_tilted_dip(void)
{
    const int N = 64;
    builder b;
    memset(&b, 0, sizeof b);
    add_chart(&b, 64, dipped, 0.0, NULL);
    soak_rain_params p;
    surface_rain_params(&p, soak_v3(0, 0, 1));
    p.duration = 1200, p.steps = 32, p.flow_iterations = 16, p.rainfall_mm_h = 10, p.rays = 4;
    soak_rain_result r;
    char err[256] = "";
    if (!check_status("tilted dip: bake", soak_bake_rain(&b.m, N, N, &p, NULL, &r, err, sizeof err), SOAK_OK)) {
        builder_free(&b);
        return;
    }
    /* Along the axis s = 0.5 the pit is where dz/dt = 0 near the centre and
     * the sill (the saddle the pool spills over) the root downhill of it. */
    double pit = dz_root(0.5 - 0.1, 0.5), sill = dz_root(0.5 - 0.35, 0.5 - 0.1);
    double z_sill = dip_z(sill), sill_depth = z_sill - dip_z(pit);
    /* Texel levels are the surface at texel centres: a pool filled to the
     * discrete sill can stand above the continuous one by the plane's rise
     * over one texel (the Gaussian's slope cancels the plane's at the
     * saddle). */
    double texel = 1.0 / (0.7 * N), tol = RISE * texel;
    double deepest = 0.0, top = -1e9, low = 1e9;
    int wet = 0;
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            size_t i = (size_t)y * N + x;
            double st[2];
            texel_chart(x, y, N, 0.0, st);
            if (r.coverage.pixels[i] < 0.5f) continue;
            double p3[3], d = r.water.pixels[i];
            dipped(st[0], st[1], p3);
            if (p3[2] > z_sill || st[1] < sill) continue; /* the dip: below its sill, uphill of the saddle */
            if (d > deepest) deepest = d;
            if (d > 1e-3) { /* the pool: water over the 1 mm static film */
                ++wet;
                top = fmax(top, p3[2] + d);
                low = fmin(low, p3[2] + d);
            }
        }
    printf("tilted dip: sill depth %.2f cm, deepest water %.2f cm, pool surface range %.2f mm over %d texels\n",
           100 * sill_depth, 100 * deepest, 1000 * (top - low), wet);
    char what[200];
    snprintf(what, sizeof what, "tilted dip: deepest water %.2f cm <= sill depth %.2f cm + %.2f cm", 100 * deepest,
             100 * sill_depth, 100 * tol);
    check_true(what, deepest <= sill_depth + tol);
    check_true("tilted dip: a pool forms (>= 20 texels over 1 mm)", wet >= 20);
    snprintf(what, sizeof what, "tilted dip: pool surface flat within %.2f mm (range %.2f mm)", 1000 * tol,
             1000 * (top - low));
    check_true(what, top - low <= tol);
    const soak_rain_runoff *o = &r.runoff;
    check_rel("tilted dip: in = dripped + held + evaporated", o->dripped + o->held + o->evaporated, o->in, 1e-9);
    soak_rain_result_free(&r);
    builder_free(&b);
}

int main(void)
{
    check_tilted_dip();
    const double plane_turns[6] = {0, 90, 30, 45, 60, 200};
    for (int k = 0; k < 6; ++k) check_uniform_plane(plane_turns[k]);
    /* UV layouts turned on and off the grid's axes and diagonals: before the
     * streams kept their sub-texel extent (bake_rain_stream.c), 30 deg
     * kept only 86 % of the shadow dry (binomial sideways spread). */
    const double ledge_turns[6] = {0, 30, 45, 90, 135, 200};
    for (int k = 0; k < 6; ++k) check_ledge(ledge_turns[k], 0.95);
    return check_finish();
}
