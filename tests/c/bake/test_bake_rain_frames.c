/* The rain bake's frame sequences (soak/bake_rain.h step 5):
 *  - the implicit step's cubic: area h + c h^3 = volume to rounding;
 *  - the film on a 30 deg plane at steady state against Nusselt's formula
 *    evaluated here (q = rainfall * E * length above, E = cos 30 exactly);
 *  - the film while it rises against the kinematic wave's exact solution
 *    on a plane (Woolhiser & Liggett 1967): h = min(r t, h_s(x)), the front
 *    (where they meet) at x = K r^2 t^3;
 *  - the film draining after the rain against the characteristics of the
 *    steady profile (x = x0 + 3 K h_s(x0)^2 tau, solved here by bisection)
 *    and, long after, Jeffreys' (1930) h = sqrt(nu x / (g sin theta tau));
 *  - the water balance of every frame on the plane and in a bowl with
 *    evaporation: in = dripped + held + evaporated (1 %), and `in` against
 *    rainfall * E * area * min(t, duration) computed here;
 *  - wetness 1 where the film runs, 1 - exp(-depth / saturation) elsewhere;
 *  - bytes identical at 1 and 2 threads, and a frame asked alone, after
 *    others or after a later one identical (chunks equal one run);
 *  - bad input: duration 0, negative, NaN and huge times. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_rain_wave.h"
#include "check.h"
#include "surface_mesh.h"
#include "soak/bake_rain.h"

/* Water at 20 C (CRC Handbook) and standard gravity, written out here. */
static const double MU = 1.002e-3, RHO = 998.2, G = 9.80665;
enum { N = 64 };

/* 1 m square rising with v at 30 deg; normal (0, -sin, cos). */
static const double SIN30 = 0.5, COS30 = 0.86602540378443865;
static void plane30(double u, double v, double out[3])
{
    out[0] = u;
    out[1] = v * COS30;
    out[2] = v * SIN30;
}

/* A bowl: the rain collects at its bottom. */
static void bowl(double u, double v, double out[3])
{
    out[0] = u;
    out[1] = v;
    out[2] = 0.3 * ((u - 0.5) * (u - 0.5) + (v - 0.5) * (v - 0.5));
}

static void params(soak_rain_params *p, double duration, int steps, double evaporation)
{
    soak_rain_defaults(p);
    p->rays = 1; /* spread 0: E = n.rain_dir / rain_dir.up exactly */
    p->spread_deg = 0;
    p->duration = duration;
    p->steps = steps;
    p->evaporation_mm_h = evaporation;
    p->rainfall_mm_h = 20;
    p->gutter = 0;
    p->retention = 0; /* a face is the film's where its film exceeds the static one: every face here */
}

/* The plane's film down the centre column at time t; 1 on success. */
static int plane_film(const soak_rain_params *p, const double *times, int n_times, double *film /* n_times * N */)
{
    soak_mesh m;
    surface_mesh(&m, N, N, plane30);
    soak_rain_frames *f = NULL;
    char err[256] = "";
    int ok = check_status("plane: frames created", soak_rain_frames_create(&m, N, N, p, NULL, &f, err, sizeof err),
                          SOAK_OK);
    for (int k = 0; k < n_times && ok; ++k) {
        soak_rain_frame fr;
        ok = check_status("plane: frame", soak_rain_frames_at(f, times[k], NULL, &fr, err, sizeof err), SOAK_OK);
        for (int y = 0; y < N && ok; ++y) film[k * N + y] = fr.film.pixels[(size_t)y * N + N / 2];
        if (ok) soak_rain_frame_free(&fr);
    }
    soak_rain_frames_destroy(f);
    surface_mesh_free(&m);
    return ok;
}

static double nusselt(double q)
{
    return cbrt(3.0 * MU * q / (RHO * G * SIN30));
}

static void test_cubic(void)
{
    const double area[3] = {1e-4, 1.0, 3e-7}, c[4] = {0.0, 1e-3, 1e5, 1e12}, vol[3] = {0.0, 1e-12, 2e-6};
    double worst = 0.0;
    for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 4; ++k)
            for (int v = 0; v < 3; ++v) {
                double h = soak_rain_wave_depth(area[a], c[k], vol[v]);
                double r = vol[v] > 0.0 ? fabs(area[a] * h + c[k] * h * h * h - vol[v]) / vol[v] : h;
                worst = r > worst ? r : worst;
            }
    check_close("implicit step: area h + c h^3 = volume (worst relative residual)", worst, 0.0, 1e-13);
    check_close("implicit step: NaN volume gives 0", soak_rain_wave_depth(1.0, 1.0, NAN), 0.0, 0.0);
}

static void test_steady(void)
{
    soak_rain_params p;
    params(&p, 120, 120, 0);
    double t = 120, film[N], a = 1.0 / N, r = p.rainfall_mm_h / 3.6e6 * COS30;
    if (!plane_film(&p, &t, 1, film)) return;
    int rows[4] = {0, 7, 31, 63};
    char what[160];
    for (int k = 0; k < 4; ++k) {
        snprintf(what, sizeof what, "steady film %.4f m below the top vs Nusselt", a * (rows[k] + 1));
        check_rel(what, film[rows[k]], nusselt(r * a * (rows[k] + 1)), 1e-4);
    }
}

/* Woolhiser & Liggett's rising limb on the plane, steps of 0.25 s. The
 * front is where r t meets h_s(x); the kink is smoothed by the implicit
 * step, so the point measured is where the film is 10 % below the steady
 * one, which the exact solution puts at r t = 0.9 h_s(x), x = x_c / 0.9^3. */
static void test_front(void)
{
    soak_rain_params p;
    params(&p, 60, 240, 0);
    double a = 1.0 / N, r = p.rainfall_mm_h / 3.6e6 * COS30, K = RHO * G * SIN30 / (3.0 * MU);
    const double xc[2] = {0.3, 0.5};
    double times[2], film[2 * N];
    for (int k = 0; k < 2; ++k) times[k] = cbrt(xc[k] / (K * r * r));
    if (!plane_film(&p, times, 2, film)) return;
    char what[160];
    for (int k = 0; k < 2; ++k) {
        int front = N;
        for (int y = 0; y < N && front == N; ++y)
            if (film[k * N + y] < 0.9 * nusselt(r * a * (y + 1))) front = y;
        snprintf(what, sizeof what, "front at t = %.2f s (film 10 %% below the steady one) vs K r^2 t^3 / 0.729 (m)",
                 times[k]);
        check_close(what, a * (front + 0.5), xc[k] / 0.729, 1.5 * a);
    }
    double t = times[1];
    check_rel("rising film at 0.25 m: the steady film", film[N + N / 4 - 1], nusselt(r * 0.25), 0.03);
    check_rel("rising film at 0.9 m: r t", film[N + (int)(0.9 * N) - 1], r * t, 0.03);
}

/* Depth at x, tau after steady rain r stopped: h_s(x0) with x0 + 3 K
 * h_s(x0)^2 tau = x (the characteristics), by bisection. */
static double drained(double x, double tau, double r, double K)
{
    double lo = 0.0, hi = x;
    for (int k = 0; k < 200; ++k) {
        double x0 = 0.5 * (lo + hi), h = cbrt(r * x0 / K);
        if (x0 + 3.0 * K * h * h * tau > x) hi = x0;
        else lo = x0;
    }
    return cbrt(r * 0.5 * (lo + hi) / K);
}

static void test_drainage(void)
{
    soak_rain_params p;
    params(&p, 120, 240, 0);
    double a = 1.0 / N, r = p.rainfall_mm_h / 3.6e6 * COS30, K = RHO * G * SIN30 / (3.0 * MU), nu = MU / RHO;
    double times[2] = {120 + 30, 120 + 600}, film[2 * N];
    if (!plane_film(&p, times, 2, film)) return;
    int rows[3] = {15, 31, 63};
    char what[160];
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 3; ++j) {
            double x = a * (rows[j] + 1), tau = times[k] - 120;
            snprintf(what, sizeof what, "drained film at %.3f m, %.0f s after the rain vs the characteristics", x, tau);
            check_rel(what, film[k * N + rows[j]], drained(x, tau, r, K), 0.05);
        }
    double x = 1.0, tau = 600;
    check_rel("drained film at 1 m, 600 s after the rain vs Jeffreys sqrt(nu x / (g sin theta tau))", film[N + N - 1],
              sqrt(nu * x / (G * SIN30 * tau)), 0.05);
}


/* A film fed at the top of a dry strip (a wall below a ledge): the front
 * is a shock moving at q / h_s = (2/3) u_s, continuity across it. One
 * column of texels on a vertical face through the wave step itself. */
static void test_shock(void)
{
    enum { ROWS = 400 };
    const double a = 0.0025, q = 2e-6 * 0.1; /* m, m^2/s: 0.2 cm^2/s per unit width */
    unsigned char covered[ROWS], adj[ROWS];
    float area[ROWS], drip[ROWS];
    double level[ROWS], retain[ROWS], kappa[ROWS], source[ROWS], depth[ROWS], inflow[ROWS];
    size_t order[ROWS];
    for (int y = 0; y < ROWS; ++y) {
        covered[y] = 1;
        adj[y] = (unsigned char)((y + 1 < ROWS ? 1u << 6 : 0u) | (y > 0 ? 1u << 2 : 0u)); /* down, up */
        area[y] = (float)(a * a);
        drip[y] = y + 1 == ROWS ? (float)a : 0.0f; /* the foot: an open edge */
        level[y] = -a * y;
        retain[y] = 0.0;
        kappa[y] = soak_rain_wave_kappa(sqrt(area[y]), 1.0);
        source[y] = y == 0 ? q * sqrt(area[0]) : 0.0;
        depth[y] = 0.0;
        order[y] = (size_t)y;
    }
    soak_rain_flow_grid g = {1, ROWS, covered, adj, area, drip, level, retain, NULL};
    double hs = cbrt(3.0 * MU * q / (RHO * G)), U = q / hs, us = RHO * G * hs * hs / (2.0 * MU);
    double t = 0.6 * ROWS * a / U, dt = t / 2000, dripped = 0.0, out = 0.0;
    for (int k = 0; k < 2000; ++k) {
        soak_rain_wave_step(&g, order, ROWS, kappa, source, dt, depth, inflow, NULL, &dripped);
        out += dripped;
    }
    int front = ROWS;
    for (int y = 0; y < ROWS && front == ROWS; ++y)
        if (depth[y] < 0.5 * hs) front = y;
    check_rel("shock onto a dry face: front at q t / h_s", a * front, U * t, 0.05);
    check_rel("shock speed q / h_s is (2/3) u_s", U, 2.0 / 3.0 * us, 1e-12);
    double held = 0.0;
    for (int y = 0; y < ROWS; ++y) held += depth[y] * area[y];
    check_rel("strip: fed = held + dripped", held + out, source[0] * t, 1e-9);
    check_rel("strip: film behind the front is Nusselt's", depth[front / 2], hs, 0.01);
}

static int frame_at(soak_rain_frames *f, double t, int threads, soak_rain_frame *fr)
{
    char err[256] = "";
    soak_bake_exec exec = {threads, NULL, NULL};
    return soak_rain_frames_at(f, t, &exec, fr, err, sizeof err) == SOAK_OK;
}

static int same_frame(const soak_rain_frame *x, const soak_rain_frame *y)
{
    size_t bytes = (size_t)x->wetness.width * x->wetness.height * sizeof(float);
    return !memcmp(x->wetness.pixels, y->wetness.pixels, bytes) && !memcmp(x->film.pixels, y->film.pixels, bytes) &&
           !memcmp(x->water.pixels, y->water.pixels, bytes) && !memcmp(&x->balance, &y->balance, sizeof x->balance);
}

/* Balance of every frame; in against the rain computed here. */
static void check_balance(const char *name, soak_rain_frames *f, double rain_area, double duration)
{
    char what[200];
    double worst = 0.0, worst_in = 0.0;
    for (double t = 0; t <= 3 * duration; t += duration / 4) {
        soak_rain_frame fr;
        if (!check_true("frame made", frame_at(f, t, 2, &fr))) return;
        const soak_rain_balance *b = &fr.balance;
        double want_in = rain_area * (t < duration ? t : duration);
        if (want_in > 0.0) {
            double e = fabs(b->in - (b->dripped + b->held + b->evaporated)) / b->in, ei = fabs(b->in / want_in - 1.0);
            worst = e > worst ? e : worst;
            worst_in = ei > worst_in ? ei : worst_in;
        }
        soak_rain_frame_free(&fr);
    }
    snprintf(what, sizeof what, "%s: in = dripped + held + evaporated, every frame (worst relative error)", name);
    check_close(what, worst, 0.0, 0.01);
    snprintf(what, sizeof what, "%s: in = rainfall * E * area * min(t, duration) (worst relative error)", name);
    check_close(what, worst_in, 0.0, 0.01);
}

static void test_balance_threads_chunks(void)
{
    soak_rain_params p;
    params(&p, 60, 30, 5);
    p.retention = 0.0002; /* the bowl keeps some, its floor is flat enough for the sweeps */
    surface_fn shapes[2] = {plane30, bowl};
    const char *names[2] = {"plane 30 deg", "bowl"};
    for (int s = 0; s < 2; ++s) {
        soak_mesh m;
        surface_mesh(&m, N, N, shapes[s]);
        soak_rain_frames *f = NULL, *g = NULL;
        char err[256] = "";
        soak_bake_exec one = {1, NULL, NULL};
        if (!check_status("frames created", soak_rain_frames_create(&m, N, N, &p, &one, &f, err, sizeof err), SOAK_OK) ||
            !check_status("frames created", soak_rain_frames_create(&m, N, N, &p, &one, &g, err, sizeof err), SOAK_OK)) {
            soak_rain_frames_destroy(f);
            surface_mesh_free(&m);
            continue;
        }
        /* Rain through the face's horizontal projection: the plane's is 1 x cos 30, the bowl's 1 x 1. */
        check_balance(names[s], f, p.rainfall_mm_h / 3.6e6 * (s == 0 ? COS30 : 1.0), p.duration);
        soak_rain_frame x, y, z;
        int ok = frame_at(f, 37.3, 1, &x); /* f went to 180 s: asking 37.3 s again starts over */
        ok = ok && frame_at(g, 20.0, 2, &y) && frame_at(g, 37.3, 2, &z);
        char what[160];
        snprintf(what, sizeof what, "%s: frame at 37.3 s alone on 1 thread = after 20 s on 2 threads", names[s]);
        check_true(what, ok && same_frame(&x, &z));
        if (ok) {
            soak_rain_frame_free(&x);
            soak_rain_frame_free(&y);
            soak_rain_frame_free(&z);
        }
        soak_rain_frames_destroy(f);
        soak_rain_frames_destroy(g);
        surface_mesh_free(&m);
    }
}

/* w = 1 where the film runs (>= 1 um), 1 - exp(-depth / saturation) elsewhere. */
static void test_wetness(void)
{
    soak_rain_params p;
    params(&p, 60, 30, 0.5);
    soak_mesh m;
    surface_mesh(&m, N, N, plane30);
    soak_rain_frames *f = NULL;
    char err[256] = "";
    soak_rain_frame fr;
    if (check_status("plane frames", soak_rain_frames_create(&m, N, N, &p, NULL, &f, err, sizeof err), SOAK_OK) &&
        frame_at(f, 30, 1, &fr)) {
        int running = 0, under = 0, worst_off = 0;
        for (size_t i = 0; i < (size_t)N * N; ++i) {
            double w = fr.wetness.pixels[i], d = fr.water.pixels[i];
            if (fr.film.pixels[i] >= 1e-6) {
                ++running;
                under += w == 1.0;
            } else if (fabs(w - (1.0 - exp(-d / p.saturation_depth))) > 1e-6)
                ++worst_off;
        }
        check_true("the whole plane carries a running film at 30 s", running == N * N);
        check_true("wetness 1 under the running film", under == running);
        check_true("elsewhere 1 - exp(-depth / saturation)", worst_off == 0);
        soak_rain_frame_free(&fr);
    }
    soak_rain_frames_destroy(f);
    surface_mesh_free(&m);
}

static void test_bad_input(void)
{
    soak_rain_params p;
    params(&p, 0, 30, 0);
    soak_mesh m;
    surface_mesh(&m, 8, 8, plane30);
    soak_rain_frames *f = NULL;
    char err[256] = "";
    check_status("duration 0: no frames", soak_rain_frames_create(&m, 8, 8, &p, NULL, &f, err, sizeof err), SOAK_ERR_ARG);
    check_true("duration 0: the message says so", strstr(err, "duration") != NULL);
    p.duration = 60;
    if (check_status("frames", soak_rain_frames_create(&m, 8, 8, &p, NULL, &f, err, sizeof err), SOAK_OK)) {
        soak_rain_frame fr;
        const double bad[3] = {-1.0, NAN, 1e300};
        for (int k = 0; k < 3; ++k)
            check_status("negative, NaN or huge time refused", soak_rain_frames_at(f, bad[k], NULL, &fr, err, sizeof err),
                         SOAK_ERR_ARG);
    }
    soak_rain_frames_destroy(f);
    surface_mesh_free(&m);
}

int main(void)
{
    test_cubic();
    test_steady();
    test_front();
    test_drainage();
    test_shock();
    test_balance_threads_chunks();
    test_wetness();
    test_bad_input();
    return check_finish();
}
