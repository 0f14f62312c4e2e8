/* Rain bake (soak/bake_rain.h) on meshes built here:
 *  - an open plane: exposure 1 +- Monte Carlo noise (mean within 3 standard
 *    errors of 1; >= 99 % of texels within 4/sqrt(N));
 *  - a floor under a wider roof: exposure ~0 and no water;
 *  - a paraboloid bowl: water routed to the bottom (bottom > 5x the rim);
 *  - mass balance on the bowl without evaporation and splat: total volume
 *    vs the analytic expectation rainfall * duration * sum(E_i A_i), within
 *    4 Poisson standard deviations;
 *  - same bytes on 1 and 2 threads; a mesh without UVs is refused. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "surface_mesh.h"
#include "soak/bake_rain.h"

/* Grid mesh (n x n quads) over uv in [0,1]^2 with z = f(x, y), x, y = uv * L
 * centred; CCW seen from +z. */
typedef double (*height_fn)(double x, double y);

static void grid_mesh(soak_mesh *m, int n, double L, height_fn f, double z0)
{
    m->tri_uv = NULL;
    m->n_vertices = (size_t)(n + 1) * (n + 1);
    m->n_triangles = 2 * (size_t)n * n;
    m->positions = malloc(3 * m->n_vertices * sizeof(double));
    m->uvs = malloc(2 * m->n_vertices * sizeof(double));
    m->normals = NULL;
    m->indices = malloc(3 * m->n_triangles * sizeof(unsigned));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            size_t v = (size_t)j * (n + 1) + i;
            double u = (double)i / n, w = (double)j / n, x = (u - 0.5) * L, y = (w - 0.5) * L;
            m->positions[3 * v] = x;
            m->positions[3 * v + 1] = y;
            m->positions[3 * v + 2] = z0 + (f ? f(x, y) : 0.0);
            m->uvs[2 * v] = u;
            m->uvs[2 * v + 1] = w;
        }
    size_t t = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            unsigned a = (unsigned)(j * (n + 1) + i), b = a + 1, c = a + (unsigned)(n + 1), d = c + 1;
            unsigned tri[6] = {a, b, d, a, d, c};
            memcpy(m->indices + 3 * t, tri, sizeof tri);
            t += 2;
        }
}

/* Appends b's triangles to a (a's come first, so a wins the UV texels). */
static void append_mesh(soak_mesh *a, const soak_mesh *b)
{
    size_t nv = a->n_vertices + b->n_vertices, nt = a->n_triangles + b->n_triangles;
    a->positions = realloc(a->positions, 3 * nv * sizeof(double));
    a->uvs = realloc(a->uvs, 2 * nv * sizeof(double));
    a->indices = realloc(a->indices, 3 * nt * sizeof(unsigned));
    memcpy(a->positions + 3 * a->n_vertices, b->positions, 3 * b->n_vertices * sizeof(double));
    memcpy(a->uvs + 2 * a->n_vertices, b->uvs, 2 * b->n_vertices * sizeof(double));
    for (size_t i = 0; i < 3 * b->n_triangles; ++i)
        a->indices[3 * a->n_triangles + i] = b->indices[i] + (unsigned)a->n_vertices;
    a->n_vertices = nv;
    a->n_triangles = nt;
}

/* Appends quad p0 p1 p2 p3 (CCW seen from its front) with UVs outside
 * [0,1]^2, so with SOAK_UV_SKIP it only occludes and never owns texels. */
static void append_quad(soak_mesh *m, const double q[4][3])
{
    soak_mesh b;
    double uv[8] = {5, 5, 6, 5, 6, 6, 5, 6};
    unsigned idx[6] = {0, 1, 2, 0, 2, 3};
    b.n_vertices = 4;
    b.n_triangles = 2;
    b.positions = (double *)q;
    b.uvs = uv;
    b.normals = NULL;
    b.indices = idx;
    append_mesh(m, &b);
}

static double paraboloid(double x, double y)
{
    return 2.0 * (x * x + y * y); /* bowl of radius 0.5 m, 0.5 m deep at the corners */
}

static void test_open_plane(void)
{
    soak_mesh m;
    grid_mesh(&m, 1, 1.0, NULL, 0.0);
    soak_rain_params p;
    soak_rain_defaults(&p);
    p.spread_deg = 60; /* wide cone: the cosine weight varies, so there is noise */
    p.duration = 0;
    p.rays = 64;
    soak_rain_result r;
    char err[256] = "";
    if (!check_status("plane bake", soak_bake_rain(&m, 64, 64, &p, NULL, &r, err, sizeof err), SOAK_OK)) {
        printf("%s\n", err);
        return;
    }
    size_t n = 64 * 64;
    double sum = 0, sum2 = 0;
    long within = 0;
    for (size_t i = 0; i < n; ++i) {
        double e = r.exposure.pixels[i];
        sum += e;
        sum2 += e * e;
        if (fabs(e - 1.0) <= 4.0 / sqrt((double)p.rays)) ++within;
    }
    double mean = sum / n, sd = sqrt(fmax(0.0, sum2 / n - mean * mean)), se = sd / sqrt((double)n);
    printf("open plane: mean %.6f, texel sd %.4g, standard error %.3g\n", mean, sd, se);
    check_close("open plane: mean exposure within 3 standard errors of 1", mean, 1.0, 3.0 * se + 1e-12);
    check_true("open plane: >= 99% of texels within 4/sqrt(N) of 1", within >= (long)(0.99 * n));
    soak_rain_result_free(&r);

    p.sky = SOAK_RAIN_SKY_HEMISPHERE;
    soak_bake_rain(&m, 16, 16, &p, NULL, &r, err, sizeof err);
    double lo = 2, hi = -1;
    for (size_t i = 0; i < 256; ++i) {
        lo = fmin(lo, r.exposure.pixels[i]);
        hi = fmax(hi, r.exposure.pixels[i]);
    }
    check_true("open plane, hemisphere sky: every texel exactly 1", lo == 1.0 && hi == 1.0);
    soak_rain_result_free(&r);
    surface_mesh_free(&m);
}

static void test_roof(void)
{
    soak_mesh floor_m, roof;
    grid_mesh(&floor_m, 1, 1.0, NULL, 0.0);
    grid_mesh(&roof, 1, 2.0, NULL, 0.2);
    /* The roof occludes and owns no texel: UVs outside [0,1]^2, skipped. On
     * shared UVs the roof would win the texels (more surface per texel). */
    for (size_t i = 0; i < 2 * roof.n_vertices; ++i) roof.uvs[i] += 5.0;
    append_mesh(&floor_m, &roof);
    soak_rain_params p;
    soak_rain_defaults(&p);
    p.uv.outside = SOAK_UV_SKIP;
    p.rays = 32;
    p.duration = 600;
    p.steps = 4;
    soak_rain_result r;
    char err[256] = "";
    if (!check_status("roofed floor bake", soak_bake_rain(&floor_m, 32, 32, &p, NULL, &r, err, sizeof err), SOAK_OK))
        return;
    double emax = 0, wmax = 0;
    for (size_t i = 0; i < 32 * 32; ++i) {
        emax = fmax(emax, r.exposure.pixels[i]);
        wmax = fmax(wmax, r.water.pixels[i]);
    }
    check_close("floor under a roof: max exposure", emax, 0.0, 1e-3);
    check_close("floor under a roof: max water depth (m)", wmax, 0.0, 1e-12);
    soak_rain_result_free(&r);
    surface_mesh_free(&floor_m);
    surface_mesh_free(&roof);
}

/* Floor of a square well (half-width a, walls of height H), hemisphere sky:
 * the exposure at the floor centre is the view factor from a differential
 * horizontal element to the coaxial opening, 4 F(a/H, a/H) with the corner
 * formula F(A, B) = (1/2pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) +
 * B/sqrt(1+B^2) atan(A/sqrt(1+B^2))] (Howell, A Catalog of Radiation Heat
 * Transfer Configuration Factors, B-3). */
static void test_well(void)
{
    const double a = 0.5, H = 0.6;
    soak_mesh m;
    grid_mesh(&m, 1, 2 * a, NULL, 0.0);
    const double walls[4][4][3] = {
        {{-a, -a, 0}, {a, -a, 0}, {a, -a, H}, {-a, -a, H}},
        {{a, -a, 0}, {a, a, 0}, {a, a, H}, {a, -a, H}},
        {{a, a, 0}, {-a, a, 0}, {-a, a, H}, {a, a, H}},
        {{-a, a, 0}, {-a, -a, 0}, {-a, -a, H}, {-a, a, H}},
    };
    for (int k = 0; k < 4; ++k) append_quad(&m, walls[k]);
    soak_rain_params p;
    soak_rain_defaults(&p);
    p.sky = SOAK_RAIN_SKY_HEMISPHERE;
    p.uv.outside = SOAK_UV_SKIP; /* the walls' UVs lie outside [0,1]^2: they occlude and own no texel */
    p.duration = 0;
    p.rays = 16384;
    soak_rain_result r;
    char err[256] = "";
    if (!check_status("well bake", soak_bake_rain(&m, 3, 3, &p, NULL, &r, err, sizeof err), SOAK_OK)) return;
    double A = a / H, s1 = sqrt(1 + A * A);
    double F = 4.0 * (1.0 / (2.0 * SOAK_PI)) * 2.0 * (A / s1) * atan(A / s1);
    double got = r.exposure.pixels[4]; /* centre texel = floor centre */
    check_close("well floor centre: exposure vs view factor to the opening (4 sd)", got, F,
                4.0 * sqrt(F * (1 - F) / p.rays));
    soak_rain_result_free(&r);
    surface_mesh_free(&m);
}

static void test_bowl(void)
{
    soak_mesh m;
    grid_mesh(&m, 32, 1.0, paraboloid, 0.0);
    soak_rain_params p;
    soak_rain_defaults(&p);
    p.rays = 16;
    p.duration = 1800;
    p.steps = 16;
    p.rainfall_mm_h = 20;
    p.evaporation_mm_h = 0;
    p.splat_radius = 0;
    p.flow_iterations = 16;
    const int W = 48;
    soak_rain_result r, r2;
    char err[256] = "";
    soak_bake_exec one = {1, NULL, NULL}, two = {2, NULL, NULL};
    if (!check_status("bowl bake", soak_bake_rain(&m, W, W, &p, &one, &r, err, sizeof err), SOAK_OK)) return;
    /* Bottom: r < 0.1 m; rim: r > 0.45 m (texel centres, uv -> x, y). */
    double bottom = 0, rim = 0, vol = 0, expect = 0;
    int nb = 0, nr = 0;
    for (int y = 0; y < W; ++y)
        for (int x = 0; x < W; ++x) {
            double u = (x + 0.5) / W, v = 1.0 - (y + 0.5) / W, px = u - 0.5, py = v - 0.5, rr = sqrt(px * px + py * py);
            double h = r.water.pixels[y * W + x];
            if (rr < 0.1) bottom += h, ++nb;
            if (rr > 0.45 && rr < 0.5) rim += h, ++nr;
            /* Texel area on z = 2(x^2+y^2): sqrt(1 + |grad z|^2) dx dy. */
            double area = sqrt(1.0 + 16.0 * (px * px + py * py)) / ((double)W * W);
            vol += h * area;
            expect += r.exposure.pixels[y * W + x] * area;
        }
    bottom /= nb;
    rim /= nr;
    printf("bowl: mean water bottom %.4g m, rim %.4g m\n", bottom, rim);
    check_true("bowl: bottom holds > 5x the rim's water", bottom > 5.0 * rim && bottom > 0.0);
    /* Expected deposited volume: rainfall depth * sum(E A); drops are Poisson:
     * sd of the volume = drop volume * sqrt(expected drops). */
    double depth_rain = p.rainfall_mm_h / 3.6e6 * p.duration;
    double drop_v = SOAK_PI / 6 * pow(p.drop_diameter, 3);
    double want = depth_rain * expect, sd = drop_v * sqrt(want / drop_v);
    check_close("bowl mass balance: water volume vs rainfall * sum(E A) (4 Poisson sd)", vol, want, 4.0 * sd);
    if (check_status("bowl bake, 2 threads", soak_bake_rain(&m, W, W, &p, &two, &r2, err, sizeof err), SOAK_OK)) {
        check_true("1 and 2 threads: identical wetness bytes",
                   memcmp(r.wetness.pixels, r2.wetness.pixels, (size_t)W * W * sizeof(float)) == 0);
        check_true("1 and 2 threads: identical exposure bytes",
                   memcmp(r.exposure.pixels, r2.exposure.pixels, (size_t)W * W * sizeof(float)) == 0);
        soak_rain_result_free(&r2);
    }
    soak_rain_result_free(&r);

    free(m.uvs);
    m.uvs = NULL;
    check_status("mesh without UVs", soak_bake_rain(&m, W, W, &p, NULL, &r, err, sizeof err), SOAK_ERR_ARG);
    check_true("message says the mesh has no UVs", strstr(err, "no UVs") != NULL);
    surface_mesh_free(&m);
}

static void test_params(void)
{
    soak_rain_params p;
    soak_rain_defaults(&p);
    check_status("defaults valid", soak_rain_check(&p), SOAK_OK);
    p.rain_dir = soak_v3(0, 0, -1);
    check_status("rain from below", soak_rain_check(&p), SOAK_ERR_ARG);
    soak_rain_defaults(&p);
    p.rays = 0;
    check_status("0 rays", soak_rain_check(&p), SOAK_ERR_ARG);
    soak_rain_defaults(&p);
    p.spread_deg = NAN;
    check_status("NaN spread", soak_rain_check(&p), SOAK_ERR_ARG);
}

int main(void)
{
    test_params();
    test_open_plane();
    test_roof();
    test_well();
    test_bowl();
    return check_finish();
}
