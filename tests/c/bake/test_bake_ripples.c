/* Ripple flipbook against independent references: the group velocity
 * against a numerical derivative of this file's own dispersion relation
 * (and the textbook 0.231 m/s minimum phase speed), the ring radius read
 * from baked frames against c_g t, the loop (frame N = frame 0 within float
 * rounding), the tiling (impacts shifted by half a tile give the image
 * rolled by half its size), the impact count against n L^2 T, the distance
 * version's reduced slope variance, and 1 vs 2 threads bit for bit. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "soak/bake_drops.h"
#include "soak/bake_ripples.h"

#define PI 3.14159265358979323846

static double omega(double k)
{
    return sqrt(9.80665 * k + 0.0728 / 998.2 * k * k * k);
}

static void test_dispersion(void)
{
    double worst = 0;
    for (double k = 10; k < 5000; k *= 1.37) {
        double h = k * 1e-5, cg = (omega(k + h) - omega(k - h)) / (2 * h);
        worst = fmax(worst, fabs(soak_capillary_group_velocity(k) / cg - 1));
    }
    check_close("c_g = d omega / dk (central difference), worst relative error", worst, 0, 1e-7);
    double km = sqrt(998.2 * 9.80665 / 0.0728);
    check_rel("minimum phase speed 0.231 m/s at 1.71 cm (Lighthill 1978)", omega(km) / km, 0.231, 0.01);
    check_rel("c_g = c_p at the phase-speed minimum", soak_capillary_group_velocity(km), omega(km) / km, 1e-9);
}

static soak_ripples_params single_ring(void)
{
    soak_ripples_params p;
    soak_ripples_defaults(&p);
    p.size = 256;
    p.tile_m = 0.5;
    p.period = 10;
    p.frames = 100;
    p.lifetime = 2; /* 3 lifetimes < period: no earlier loop's ring on the tile */
    return p;
}

/* Slope squared from an encoded normal. */
static double slope2(const float *px)
{
    double nx = 2 * px[0] - 1, ny = 2 * px[1] - 1, nz = 2 * px[2] - 1;
    return (nx * nx + ny * ny) / (nz * nz);
}

/* Centroid in r of the angular mean of slope^2 about (cx, cy) texels. */
static double ring_radius(const soak_image *img, double cx, double cy)
{
    enum { BINS = 400 };
    double sum[BINS] = {0}, cnt[BINS] = {0};
    for (int y = 0; y < img->height; ++y)
        for (int x = 0; x < img->width; ++x) {
            double r = hypot(x + 0.5 - cx, y + 0.5 - cy);
            int b = (int)(r * 2);
            if (b < BINS) sum[b] += slope2(img->pixels + 4 * ((size_t)y * img->width + x)), cnt[b] += 1;
        }
    double m0 = 0, m1 = 0;
    for (int b = 0; b < BINS; ++b)
        if (cnt[b] > 0) m0 += sum[b] / cnt[b], m1 += (b + 0.5) / 2 * sum[b] / cnt[b];
    return m1 / m0;
}

static void test_ring_radius(void)
{
    soak_ripples_params p = single_ring();
    soak_ripple_impact one = {0.25, 0.25, 0};
    double texel = p.tile_m / p.size, k = 2 * PI / p.wavelength_m;
    double cg = (omega(k * (1 + 1e-6)) - omega(k * (1 - 1e-6))) / (2e-6 * k);
    double sx = 0, sy = 0, sxx = 0, sxy = 0, worst = 0;
    int n = 0;
    for (long f = 2; f <= 7; ++f) {
        soak_image img = {0, 0, 0, NULL};
        check_status("frame", soak_ripples_frame(&p, &one, 1, f, 0, NULL, &img, NULL), SOAK_OK);
        double t = f * p.period / p.frames, r = ring_radius(&img, 128, 128) * texel;
        worst = fmax(worst, fabs(r / (cg * t) - 1));
        sx += t, sy += r, sxx += t * t, sxy += t * r, ++n;
        soak_image_free(&img);
    }
    double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    printf("  ring speed %.4f m/s, c_g %.4f m/s, worst radius error %.3f\n", slope, cg, worst);
    check_rel("ring radius growth rate = group velocity (least squares over 6 frames)", slope, cg, 0.03);
    check_close("each frame's ring radius within 5 % of c_g t", worst, 0, 0.05);
}

static double max_abs_diff(const soak_image *a, const soak_image *b)
{
    double worst = 0;
    size_t n = (size_t)a->width * a->height * a->channels;
    for (size_t i = 0; i < n; ++i) worst = fmax(worst, fabs((double)a->pixels[i] - b->pixels[i]));
    return worst;
}

static void test_loop_and_tiling(void)
{
    soak_ripples_params p;
    soak_ripples_defaults(&p);
    p.size = 128;
    p.tile_m = 0.25;
    p.frames = 16;
    p.period = 0.8; /* shorter than 3 lifetimes: rings wrap round the loop */
    p.rate_mm_h = 30;
    soak_ripple_impact *v = NULL;
    size_t n = 0;
    check_status("impacts", soak_ripples_impacts(&p, &v, &n), SOAK_OK);
    double mean = soak_drop_flux(30, 1, 6) * p.tile_m * p.tile_m * p.period;
    check_close("ring impacts per loop: 4 sigma of n L^2 T", (n - mean) / sqrt(mean), 0, 4);
    soak_image first = {0, 0, 0, NULL}, wrapped = {0, 0, 0, NULL}, last = {0, 0, 0, NULL};
    check_status("frame 0", soak_ripples_frame(&p, v, n, 0, 0, NULL, &first, NULL), SOAK_OK);
    check_status("frame N", soak_ripples_frame(&p, v, n, p.frames, 0, NULL, &wrapped, NULL), SOAK_OK);
    check_status("frame N-1", soak_ripples_frame(&p, v, n, p.frames - 1, 0, NULL, &last, NULL), SOAK_OK);
    check_close("frame N = frame 0 (the loop closes) within float rounding", max_abs_diff(&first, &wrapped), 0, 1e-6);
    double step_last = 0, step_inner = 0;
    soak_image a = {0, 0, 0, NULL}, b = {0, 0, 0, NULL};
    check_status("frame 5", soak_ripples_frame(&p, v, n, 5, 0, NULL, &a, NULL), SOAK_OK);
    check_status("frame 6", soak_ripples_frame(&p, v, n, 6, 0, NULL, &b, NULL), SOAK_OK);
    for (int i = 0; i < p.size * p.size * 4; ++i)
        step_last += fabs(last.pixels[i] - first.pixels[i]), step_inner += fabs(a.pixels[i] - b.pixels[i]);
    printf("  mean change N-1 -> 0: %.5f, 5 -> 6: %.5f\n", step_last / (p.size * p.size * 4),
           step_inner / (p.size * p.size * 4));
    check_true("last -> first frame changes like any frame step (ratio in [0.5, 2])",
               step_last > 0.5 * step_inner && step_last < 2 * step_inner);
    /* Half a tile shift of every impact = the image rolled by half its size. */
    for (size_t i = 0; i < n; ++i) v[i].x = fmod(v[i].x + p.tile_m / 2, p.tile_m);
    soak_image shifted = {0, 0, 0, NULL};
    check_status("shifted", soak_ripples_frame(&p, v, n, 0, 0, NULL, &shifted, NULL), SOAK_OK);
    double worst = 0;
    for (int y = 0; y < p.size; ++y)
        for (int x = 0; x < p.size; ++x)
            for (int c = 0; c < 4; ++c) {
                double s = shifted.pixels[4 * (y * p.size + (x + p.size / 2) % p.size) + c];
                worst = fmax(worst, fabs(s - first.pixels[4 * (y * p.size + x) + c]));
            }
    check_close("tiles: shifted impacts give the rolled image (edges continue) within float rounding", worst, 0, 1e-5);
    soak_image one = {0, 0, 0, NULL}, two = {0, 0, 0, NULL}, far = {0, 0, 0, NULL}, sharp = {0, 0, 0, NULL};
    soak_bake_exec e1 = {1, NULL, NULL}, e2 = {2, NULL, NULL};
    check_status("1 thread", soak_ripples_frame(&p, v, n, 3, 0, &e1, &one, NULL), SOAK_OK);
    check_status("2 threads", soak_ripples_frame(&p, v, n, 3, 0, &e2, &two, NULL), SOAK_OK);
    check_true("1 and 2 threads bit for bit", max_abs_diff(&one, &two) == 0);
    check_status("far", soak_ripples_frame(&p, v, n, 3, 4, NULL, &sharp, &far), SOAK_OK);
    double s_sharp = 0, s_far = 0;
    for (int i = 0; i < p.size * p.size; ++i) s_sharp += slope2(one.pixels + 4 * i), s_far += slope2(far.pixels + 4 * i);
    printf("  mean slope^2 sharp %.5f, far %.5f\n", s_sharp / (p.size * p.size), s_far / (p.size * p.size));
    check_true("distance version: mean slope^2 below a quarter of the sharp one", s_far < 0.25 * s_sharp);
    check_true("the sharp map made with the distance version = the sharp map alone", max_abs_diff(&sharp, &one) == 0);
    check_status("bad filter", soak_ripples_frame(&p, v, n, 3, -1, NULL, &sharp, &far), SOAK_ERR_ARG);
    p.rate_mm_h = NAN;
    check_status("NaN rate", soak_ripples_check(&p), SOAK_ERR_ARG);
    soak_image *all[] = {&first, &wrapped, &last, &a, &b, &shifted, &one, &two, &far, &sharp};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i) soak_image_free(all[i]);
    free(v);
}

int main(void)
{
    test_dispersion();
    test_ring_radius();
    test_loop_and_tiling();
    return check_finish();
}
