/* The rain bake's falling film (soak/bake_rain.h step 3b):
 *  - Nusselt's film on an inclined plane (30 deg) and a vertical wall under
 *    steady rain, against h = (3 mu q / (rho g sin theta))^(1/3) evaluated
 *    here with q = rainfall * E * (length of face above), E known exactly
 *    (rain cone of spread 0, no occlusion); edge cases of the formula;
 *  - where the rain goes on the meshes: on the planes in = rainfall * E *
 *    area and all of it drips off; on the relief in = rainfall * (the wall
 *    rectangle's share of the rain) and in = dripped + held + evaporated;
 *  - the cascade (water on the film's faces moved at the film's speed)
 *    conserves volume (before = after + dripped) on that grid;
 *  - mass balance of the steady discharge on a grid with holes, drip edges,
 *    down-facing texels and pits: in = dripped + held + evaporated (1e-9),
 *    and each texel's continuity against shares recomputed here;
 *  - a bas-relief-like wall (ledge, dome) in slanting rain: its lower half
 *    keeps a film, and the time loop's water fills it (but for the last
 *    step's evaporation);
 *  - film and wetness bytes identical at 1 and 2 threads. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_rain_film.h"
#include "check.h"
#include "surface_mesh.h"
#include "soak/bake_rain.h"
#include "soak/rng.h"

/* Water at 20 C (CRC Handbook) and standard gravity, written out here. */
static const double MU = 1.002e-3, RHO = 998.2, G = 9.80665;

static const double PLANE_L = 1.0;
static double plane_cos, plane_sin; /* set before building a plane */

/* Side PLANE_L, rising with v at an angle (cos, sin) from the horizontal;
 * normal (0, -sin, cos). */
static void tilted_plane(double u, double v, double out[3])
{
    out[0] = u * PLANE_L;
    out[1] = v * PLANE_L * plane_cos;
    out[2] = v * PLANE_L * plane_sin;
}

/* Film along the centre column against Nusselt's formula with q the rain
 * on the face above the texel's lower edge, per unit width. */
static void check_plane(double theta_deg, soak_vec3 rain_dir, double exposure, const char *name)
{
    const int N = 64;
    /* 90 deg: exactly vertical (n.up = 0), which must carry its film down, not drip it */
    plane_cos = theta_deg == 90.0 ? 0.0 : cos(theta_deg * SOAK_PI / 180.0);
    plane_sin = theta_deg == 90.0 ? 1.0 : sin(theta_deg * SOAK_PI / 180.0);
    soak_mesh m;
    surface_mesh(&m, N, N, tilted_plane);
    soak_rain_params p;
    surface_rain_params(&p, rain_dir);
    soak_rain_result r;
    char err[256] = "", what[160];
    if (!check_status(name, soak_bake_rain(&m, N, N, &p, NULL, &r, err, sizeof err), SOAK_OK)) {
        surface_mesh_free(&m);
        return;
    }
    double a = PLANE_L / N, rain = p.rainfall_mm_h / 3.6e6, s = plane_sin;
    int rows[4] = {0, 7, 31, 63};
    for (int k = 0; k < 4; ++k) {
        size_t i = (size_t)rows[k] * N + N / 2;
        double q = rain * exposure * a * (rows[k] + 1), want = cbrt(3.0 * MU * q / (RHO * G * s));
        snprintf(what, sizeof what, "%s: film at %.4f m below the top edge vs Nusselt (E %.4f)", name,
                 a * (rows[k] + 1), r.exposure.pixels[i]);
        check_rel(what, r.film.pixels[i], want, 1e-4);
    }
    /* Mass balance on the mesh: the rain on the face (rainfall * E * area),
     * all of which runs off its edges (no pit, no evaporation). */
    const soak_rain_runoff *o = &r.runoff;
    snprintf(what, sizeof what, "%s: water in = rainfall * E * area (1 %%)", name);
    check_rel(what, o->in, rain * exposure * PLANE_L * PLANE_L, 0.01);
    snprintf(what, sizeof what, "%s: water in = dripped + held + evaporated (1 %%)", name);
    check_rel(what, o->dripped + o->held + o->evaporated, o->in, 0.01);
    snprintf(what, sizeof what, "%s: all of it drips off the edges (1 %%)", name);
    check_rel(what, o->dripped, o->in, 0.01);
    soak_rain_result_free(&r);
    surface_mesh_free(&m);
}

static void test_nusselt_planes(void)
{
    /* 30 deg slope, rain from straight above: E = cos 30. */
    check_plane(30.0, soak_v3(0, 0, 1), cos(SOAK_PI / 6.0), "plane at 30 deg");
    /* Vertical wall facing -y, rain from (0,-1,1): E = (1/sqrt2) / (1/sqrt2) = 1. */
    check_plane(90.0, soak_v3(0, -1, 1), 1.0, "vertical wall");
}

static void test_formula_edges(void)
{
    double q = 1e-6, h = cbrt(3.0 * MU * q / (RHO * G));
    check_rel("formula: vertical, q 1e-6 m^2/s", soak_rain_film_thickness(q, 1.0), h, 1e-12);
    check_rel("formula: h scales as (1/sin)^(1/3)", soak_rain_film_thickness(q, 0.125), 2.0 * h, 1e-12);
    check_close("formula: q 0", soak_rain_film_thickness(0.0, 1.0), 0.0, 0.0);
    check_close("formula: flat", soak_rain_film_thickness(q, 0.0), 0.0, 0.0);
    check_close("formula: NaN q", soak_rain_film_thickness(NAN, 1.0), 0.0, 0.0);
    check_close("formula: NaN slope", soak_rain_film_thickness(q, NAN), 0.0, 0.0);
    check_close("formula: huge q cut at the laminar limit", soak_rain_film_thickness(1.0, 1e-9), SOAK_RAIN_FILM_MAX,
                0.0);
    double u = soak_rain_film_surface_speed(h, 1.0);
    check_rel("surface speed: rho g h^2 / (2 mu)", u, RHO * G * h * h / (2.0 * MU), 1e-12);
    /* Identity: the mean velocity (2/3 of the surface's) times h carries q. */
    check_rel("surface speed: (2/3) u_s h = q", 2.0 / 3.0 * u * h, q, 1e-9);
}

/* ---- mass balance of the steady discharge ---- */

typedef struct flow_grid {
    unsigned char *covered, *adj;
    float *area, *drip;
    double *level, *source, *discharge;
} flow_grid;

static void grid_fill(flow_grid *d, int w, int h, soak_rng *r)
{
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = (size_t)y * w + x;
            double u = (double)x / w, v = (double)y / h;
            d->covered[i] = soak_rng_uniform(r) > 0.05;
            /* a slope with two dimples (pits) and noise */
            d->level[i] = 0.3 * v + 0.05 * exp(-40 * ((u - 0.3) * (u - 0.3) + (v - 0.5) * (v - 0.5))) -
                          0.08 * exp(-60 * ((u - 0.7) * (u - 0.7) + (v - 0.4) * (v - 0.4))) + 1e-4 * soak_rng_uniform(r);
            d->area[i] = (float)(1e-6 * (0.5 + soak_rng_uniform(r)));
            d->source[i] = 1e-9 * soak_rng_uniform(r);
            double q = soak_rng_uniform(r);
            d->drip[i] = q < 0.02 ? -1.0f : (q < 0.06 ? (float)(1e-3 * soak_rng_uniform(r)) : 0.0f);
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = (size_t)y * w + x;
            d->adj[i] = 0;
            for (int k = 0; k < 8; ++k) {
                int kx = x + SOAK_RAIN_DX[k], ky = y + SOAK_RAIN_DY[k];
                if (kx >= 0 && ky >= 0 && kx < w && ky < h && d->covered[i] && d->covered[(size_t)ky * w + kx])
                    d->adj[i] |= (unsigned char)(1u << k);
            }
        }
}

/* Inflow of every texel from its upstream neighbours' discharge, with the
 * routing's shares recomputed here (level drops to adjacent lower
 * neighbours and the drip edge). */
static void reference_inflow(const flow_grid *d, int w, int h, double *inflow, double *dripped, double *held)
{
    *dripped = *held = 0.0;
    for (size_t i = 0; i < (size_t)w * h; ++i) inflow[i] = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = (size_t)y * w + x;
            double q = d->discharge[i], diff[9], sum = 0.0;
            if (!d->covered[i] || !(q > 0.0)) continue;
            if (d->drip[i] < 0.0f) {
                *dripped += q;
                continue;
            }
            for (int k = 0; k < 8; ++k) {
                size_t j = (size_t)(y + SOAK_RAIN_DY[k]) * w + (size_t)(x + SOAK_RAIN_DX[k]);
                diff[k] = (d->adj[i] >> k & 1u) && d->level[i] > d->level[j] ? d->level[i] - d->level[j] : 0.0;
            }
            diff[8] = d->drip[i] > 0.0f ? d->drip[i] : 0.0;
            for (int k = 0; k < 9; ++k) sum += diff[k];
            if (sum == 0.0) {
                *held += q;
                continue;
            }
            for (int k = 0; k < 8; ++k)
                if (diff[k] > 0.0) inflow[(size_t)(y + SOAK_RAIN_DY[k]) * w + (size_t)(x + SOAK_RAIN_DX[k])] += q * diff[k] / sum;
            *dripped += q * diff[8] / sum;
        }
}

static void test_discharge_balance(void)
{
    const int w = 57, h = 43;
    size_t n = (size_t)w * h;
    flow_grid d = {calloc(n, 1), calloc(n, 1), calloc(n, sizeof(float)), calloc(n, sizeof(float)),
                   calloc(n, sizeof(double)), calloc(n, sizeof(double)), calloc(n, sizeof(double))};
    double *inflow = calloc(n, sizeof(double)), *retain = calloc(n, sizeof(double));
    soak_rng r;
    soak_rng_seed(&r, 37, 39);
    grid_fill(&d, w, h, &r);
    soak_rain_flow_grid g = {w, h, d.covered, d.adj, d.area, d.drip, d.level, retain, NULL};
    const double loss = 2e-4; /* m/s: a strong evaporation, so some texels run dry */
    soak_rain_flow_balance b;
    if (!check_status("discharge", soak_rain_flow_discharge(&g, d.source, loss, d.discharge, &b), SOAK_OK)) return;
    printf("discharge: in %.6g, dripped %.6g, held %.6g, evaporated %.6g m^3/s\n", b.in, b.dripped, b.held, b.lost);
    check_true("discharge: some water drips, some is held, some evaporates", b.dripped > 0 && b.held > 0 && b.lost > 0);
    check_rel("discharge: in = dripped + held + evaporated", b.dripped + b.held + b.lost, b.in, 1e-9);
    double dripped, held, worst = 0.0, lost = 0.0;
    reference_inflow(&d, w, h, inflow, &dripped, &held);
    for (size_t i = 0; i < n; ++i) {
        if (!d.covered[i]) continue;
        double got = d.source[i] + inflow[i], l = fmin(loss * d.area[i], got);
        lost += l;
        double e = fabs(d.discharge[i] - (got - l)) / fmax(got, 1e-30);
        worst = fmax(worst, e);
    }
    printf("discharge: worst relative continuity error %.3g\n", worst);
    check_true("discharge: every texel passes on what it receives minus evaporation (1e-9)", worst < 1e-9);
    check_rel("discharge: dripped vs shares recomputed here", b.dripped, dripped, 1e-9);
    check_rel("discharge: held vs shares recomputed here", b.held, held, 1e-9);
    check_rel("discharge: evaporated vs recomputed here", b.lost, lost, 1e-9);
    check_status("discharge: NaN loss", soak_rain_flow_discharge(&g, d.source, NAN, d.discharge, &b), SOAK_ERR_ARG);
    free(d.covered), free(d.adj), free(d.area), free(d.drip), free(d.level), free(d.source), free(d.discharge);
    free(inflow), free(retain);
}

/* The cascade on the same grid: volume before = volume after + dripped; a
 * fast texel with a lower neighbour ends at most at its retention; a texel
 * that is not fast loses nothing. */
static void test_cascade_balance(void)
{
    const int w = 57, h = 43;
    size_t n = (size_t)w * h, *order = NULL, count = 0;
    flow_grid d = {calloc(n, 1), calloc(n, 1), calloc(n, sizeof(float)), calloc(n, sizeof(float)),
                   calloc(n, sizeof(double)), calloc(n, sizeof(double)), calloc(n, sizeof(double))};
    double *retain = calloc(n, sizeof(double)), *depth = calloc(n, sizeof(double)), *before = calloc(n, sizeof(double));
    double *inflow = calloc(n, sizeof(double));
    unsigned char *fast = calloc(n, 1);
    soak_rng r;
    soak_rng_seed(&r, 37, 40);
    grid_fill(&d, w, h, &r);
    for (size_t i = 0; i < n; ++i) {
        retain[i] = 5e-5 * soak_rng_uniform(&r);
        depth[i] = before[i] = d.covered[i] ? 2e-4 * soak_rng_uniform(&r) : 0.0;
        fast[i] = soak_rng_uniform(&r) < 0.8;
    }
    soak_rain_flow_grid g = {w, h, d.covered, d.adj, d.area, d.drip, d.level, retain, NULL};
    double dripped = 0.0, v0 = 0.0, v1 = 0.0;
    if (!check_status("cascade order", soak_rain_flow_order(&g, &order, &count), SOAK_OK) ||
        !check_status("cascade", soak_rain_flow_cascade(&g, fast, order, count, depth, inflow, &dripped), SOAK_OK))
        return;
    int kept = 1;
    for (size_t i = 0; i < n; ++i) {
        if (!d.covered[i]) continue;
        v0 += before[i] * d.area[i];
        v1 += depth[i] * d.area[i];
        if (!fast[i] && depth[i] < before[i]) kept = 0;
    }
    printf("cascade: volume before %.6g, after %.6g, dripped %.6g m^3\n", v0, v1, dripped);
    check_true("cascade: some water drips, some stays", dripped > 0.0 && v1 > 0.0);
    check_rel("cascade: volume before = after + dripped", v1 + dripped, v0, 1e-12);
    check_true("cascade: a texel that is not fast loses nothing", kept);
    free(d.covered), free(d.adj), free(d.area), free(d.drip), free(d.level), free(d.source), free(d.discharge);
    free(retain), free(depth), free(before), free(inflow), free(fast), free(order);
}

/* ---- a bas-relief-like wall ---- */

static double smooth_step(double x, double a, double b)
{
    double t = fmin(fmax((x - a) / (b - a), 0.0), 1.0);
    return t * t * (3 - 2 * t);
}

/* 1.2 x 1.2 m wall facing -y, z up: a ledge at z 0.80-0.92 standing out
 * 0.06 m (underside facing down, top sloping back) and a dome at (0.6, 0.4). */
static void relief(double u, double v, double out[3])
{
    double x = 1.2 * u, z = 1.2 * v, r = hypot(x - 0.6, z - 0.4);
    double ledge = 0.06 * smooth_step(z, 0.80, 0.83) * (1 - smooth_step(z, 0.88, 0.92));
    double dome = 0.04 * (1 - smooth_step(r, 0.0, 0.2));
    out[0] = x;
    out[1] = -fmax(ledge, dome);
    out[2] = z;
}

static void relief_params(soak_rain_params *p)
{
    soak_rain_defaults(p);
    p->rays = 8;
    p->spread_deg = 15;
    p->rain_dir = soak_v3(0, -0.55, 1);
    p->duration = 600;
    p->steps = 16;
    p->flow_iterations = 16;
}

/* Lower half (z < 0.6: image rows N/2..N-1): share of texels with water
 * and film over 1 um, share whose water fills the film but for one step's
 * evaporation (evap, m), and the mean water depth. */
static void lower_half(const soak_rain_result *r, int N, double evap, double share[3], double *mean)
{
    long c = 0, wet = 0, film = 0, filled = 0;
    double sum = 0.0;
    for (int y = N / 2; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            size_t i = (size_t)y * N + x;
            ++c;
            wet += r->water.pixels[i] > 1e-6f;
            film += r->film.pixels[i] > 1e-6f;
            filled += r->water.pixels[i] >= r->film.pixels[i] - evap * 1.001;
            sum += r->water.pixels[i];
        }
    share[0] = (double)wet / c;
    share[1] = (double)film / c;
    share[2] = (double)filled / c;
    *mean = sum / c;
}

static void test_relief(void)
{
    const int N = 96;
    soak_mesh m;
    surface_mesh(&m, 96, 96, relief);
    soak_rain_params p;
    relief_params(&p);
    soak_rain_result on, two, off;
    char err[256] = "";
    soak_bake_exec e1 = {1, NULL, NULL}, e2 = {2, NULL, NULL};
    if (!check_status("relief, film", soak_bake_rain(&m, N, N, &p, &e1, &on, err, sizeof err), SOAK_OK)) return;
    double share[3], mean, evap = p.evaporation_mm_h / 3.6e6 * p.duration / p.steps;
    lower_half(&on, N, evap, share, &mean);
    printf("relief lower half, film on: %.3f wet, %.3f film, %.3f filled, mean water %.3g m\n", share[0], share[1],
           share[2], mean);
    check_true("relief: >= 95% of the lower half keeps a film", share[1] >= 0.95);
    check_true("relief: >= 95% of the lower half holds water", share[0] >= 0.95);
    check_true("relief: >= 95% of the lower half holds its film (but for a step's evaporation)", share[2] >= 0.95);
    const soak_rain_runoff *o = &on.runoff;
    printf("relief runoff: in %.4g, dripped %.4g, held %.4g, evaporated %.4g m^3/s\n", o->in, o->dripped, o->held,
           o->evaporated);
    check_rel("relief: water in = dripped + held + evaporated (1 %)", o->dripped + o->held + o->evaporated, o->in,
              0.01);
    /* Independent: every ray of the rain crossing the wall's rectangle
     * meets the relief once, so sum(E A) is the rectangle's, 1.44 m^2 times
     * mean(-u.y) / mean(u.z) over the cone = 0.55 / 1 (the cone's mean
     * cosine cancels). The map is as fine as the mesh: at 64 texels for 96
     * cells, texel-centre sampling of E A gives +1.9 %. */
    double want = p.rainfall_mm_h / 3.6e6 * 1.44 * 0.55;
    printf("relief: water in / (rainfall * 1.44 m^2 * 0.55) = %.5f\n", o->in / want);
    check_rel("relief: water in = rainfall * rectangle * 0.55 (1 %)", o->in, want, 0.01);
    p.film = 0;
    if (check_status("relief, no film", soak_bake_rain(&m, N, N, &p, &e1, &off, err, sizeof err), SOAK_OK)) {
        lower_half(&off, N, evap, share, &mean);
        check_true("relief: without the film no film map", share[1] == 0.0);
        check_true("relief: without the film no runoff totals", off.runoff.in == 0.0);
        soak_rain_result_free(&off);
    }
    p.film = 1;
    if (check_status("relief, 2 threads", soak_bake_rain(&m, N, N, &p, &e2, &two, err, sizeof err), SOAK_OK)) {
        size_t bytes = (size_t)N * N * sizeof(float);
        check_true("1 and 2 threads: identical film bytes", memcmp(on.film.pixels, two.film.pixels, bytes) == 0);
        check_true("1 and 2 threads: identical wetness bytes", memcmp(on.wetness.pixels, two.wetness.pixels, bytes) == 0);
        soak_rain_result_free(&two);
    }
    soak_rain_result_free(&on);
    p.film = 2;
    check_status("film flag 2 refused", soak_rain_check(&p), SOAK_ERR_ARG);
    surface_mesh_free(&m);
}

int main(void)
{
    test_formula_edges();
    test_nusselt_planes();
    test_discharge_balance();
    test_cascade_balance();
    test_relief();
    return check_finish();
}
