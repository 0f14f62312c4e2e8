/* The picture denoiser (soak/denoise.h) against references it does not
 * make:
 *  - a Lambertian plane lit by a sphere light, seen from straight above at
 *    2 samples a pixel: each pixel's radiance is known in closed form,
 *    albedo/pi E with E = pi L (r/D)^2 cos = pi L r^2 h / D^3 (the sphere
 *    wholly above the plane's horizon; test_render_lights checks the
 *    tracer against it). The filtered image's RMS error against it must
 *    fall below a third of the noisy render's, and its mean stay within 4
 *    standard errors of the closed form's (the filter neither adds nor
 *    removes light on a smooth field);
 *  - a firefly planted in the closed-form image (1000x one pixel) is
 *    removed: the pixel returns within 5 % of its value and its neighbours
 *    stay within 1 %; the clean image has no firefly;
 *  - an edge: a step 0.2 | 0.8 with Gaussian noise (sigma 0.05, variance
 *    given) stays one pixel sharp through the colour term alone (the
 *    columns beside it within 0.02 of their sides) while the noise falls;
 *    a step 0.5 | 0.55, inside the noise, stays sharp when the object ids
 *    differ across it (the feature term) and is blurred without them. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "soak/denoise.h"
#include "soak/image.h"
#include "soak/render.h"
#include "soak/rng.h"
#include "soak/scene.h"

#define N 96
#define TAN20 0.36397023426620234

static const char *const PLANE =
    "{\"render\": {\"width\": 96, \"height\": 96},"
    " \"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0], \"fov\": 40},"
    " \"lights\": [{\"type\": \"sphere\", \"center\": [0, 0, 8], \"radius\": 2, \"radiance\": 3}],"
    " \"materials\": {\"m\": {\"type\": \"lambert\", \"albedo\": 0.6}},"
    " \"objects\": [{\"type\": \"plane\", \"size\": [1000, 1000], \"material\": \"m\"}]}";

/* The closed form averaged over the pixel (4 x 4 points): the camera looks
 * down -z with right = +x and up = +y, so the pixel's ray meets the plane
 * at 5 (sx, sy). */
static double plane_radiance(int x, int y)
{
    double sum = 0;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
            double sx = (2 * (x + (a + 0.5) / 4) / N - 1) * TAN20, sy = (1 - 2 * (y + (b + 0.5) / 4) / N) * TAN20;
            double px = 5 * sx, py = 5 * sy, h = 8, dx = px;
            double D = sqrt(dx * dx + py * py + h * h);
            sum += 0.6 * 3 * 4 * h / (D * D * D);
        }
    return sum / 16;
}

static double rms_error(const soak_image *img, const double *ref)
{
    double s = 0;
    for (int i = 0; i < N * N; ++i) {
        double y = soak_rgb_luminance(soak_rgb3(img->pixels[3 * i], img->pixels[3 * i + 1], img->pixels[3 * i + 2]));
        s += (y - ref[i]) * (y - ref[i]);
    }
    return sqrt(s / (N * N));
}

static double mean_lum(const soak_image *img)
{
    double s = 0;
    for (int i = 0; i < img->width * img->height; ++i)
        s += soak_rgb_luminance(soak_rgb3(img->pixels[3 * i], img->pixels[3 * i + 1], img->pixels[3 * i + 2]));
    return s / (img->width * img->height);
}

static void test_plane(double *ref)
{
    soak_scene sc;
    char err[1024] = "";
    if (!check_status("plane scene", soak_scene_parse(PLANE, "plane", ".", &sc, err, sizeof err), SOAK_OK)) return;
    soak_render_options opt;
    soak_render_options_default(&opt);
    opt.threads = 2;
    opt.spp = 2;
    opt.seed = 5;
    soak_image img = {0}, var = {0};
    opt.variance = &var;
    soak_render_stats st;
    soak_denoise_features f = {0};
    if (check_status("render", soak_render(&sc, &opt, &img, &st, err, sizeof err), SOAK_OK) &&
        check_status("features", soak_render_features(&sc, N, N, 4, &f, err, sizeof err), SOAK_OK)) {
        double ref_mean = 0, var_sum = 0;
        for (int i = 0; i < N * N; ++i) {
            ref_mean += ref[i] / (N * N);
            var_sum += var.pixels[i];
        }
        double se = sqrt(var_sum) / (N * N), e0 = rms_error(&img, ref), m0 = mean_lum(&img);
        soak_denoise_options o;
        soak_denoise_options_default(&o);
        soak_denoise_stats ds;
        if (check_status("denoise", soak_denoise(&img, &var, &f, &o, &ds, err, sizeof err), SOAK_OK)) {
            double e1 = rms_error(&img, ref), m1 = mean_lum(&img);
            printf("  plane: RMS error %.5f noisy -> %.5f filtered; mean %.6f closed form, %.6f noisy, %.6f filtered "
                   "(se %.6f); %ld fireflies\n",
                   e0, e1, ref_mean, m0, m1, se, ds.fireflies);
            check_true("filtered RMS error < 1/3 of the noisy render's", e1 < e0 / 3);
            check_close("filtered mean = closed form's (energy)", m1, ref_mean, 4 * se);
        }
    }
    soak_denoise_features_free(&f);
    soak_image_free(&img);
    soak_image_free(&var);
    soak_scene_free(&sc);
}

static void test_firefly(const double *ref)
{
    soak_image img = {0}, var = {0};
    if (soak_image_alloc(&img, N, N, 3) != SOAK_OK || soak_image_alloc(&var, N, N, 1) != SOAK_OK) {
        check_true("alloc", 0);
        return;
    }
    for (int i = 0; i < N * N; ++i) {
        for (int ch = 0; ch < 3; ++ch) img.pixels[3 * i + ch] = (float)ref[i];
        var.pixels[i] = (float)(1e-4 * ref[i] * ref[i]);
    }
    soak_denoise_options o;
    soak_denoise_options_default(&o);
    soak_denoise_stats ds;
    char err[256];
    soak_image clean = {0};
    soak_image_alloc(&clean, N, N, 3);
    memcpy(clean.pixels, img.pixels, sizeof(float) * 3 * N * N);
    check_status("denoise clean", soak_denoise(&clean, &var, NULL, &o, &ds, err, sizeof err), SOAK_OK);
    check_true("no firefly in the clean image", ds.fireflies == 0);
    soak_image_free(&clean);
    const int p = 40 * N + 50;
    for (int ch = 0; ch < 3; ++ch) img.pixels[3 * p + ch] *= 1000;
    var.pixels[p] = (float)(1000 * ref[p] * 1000 * ref[p] / 2);
    if (check_status("denoise firefly", soak_denoise(&img, &var, NULL, &o, &ds, err, sizeof err), SOAK_OK)) {
        check_true("one firefly found", ds.fireflies == 1);
        check_rel("the firefly's pixel back to its value", img.pixels[3 * p + 1], ref[p], 0.05);
        check_rel("its neighbour untouched", img.pixels[3 * (p + 1) + 1], ref[p + 1], 0.01);
        check_rel("its neighbour below untouched", img.pixels[3 * (p + N) + 1], ref[p + N], 0.01);
    }
    soak_image_free(&img);
    soak_image_free(&var);
}

/* Column means of a filtered noisy step lo | hi at x = N/2, and the noise
 * (standard deviation) left in the left half's inner columns. */
static void step_filtered(double lo, double hi, double sigma, const soak_denoise_features *f, double *left,
                          double *right, double *noise_before, double *noise_after)
{
    soak_image img = {0}, var = {0};
    soak_image_alloc(&img, N, N, 3);
    soak_image_alloc(&var, N, N, 1);
    soak_rng rng;
    soak_rng_seed(&rng, 7, 1);
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            double u1 = fmax(soak_rng_uniform(&rng), 1e-12), u2 = soak_rng_uniform(&rng);
            double g = sqrt(-2 * log(u1)) * cos(2 * SOAK_PI * u2); /* Box-Muller */
            double v = (x < N / 2 ? lo : hi) + sigma * g;
            for (int ch = 0; ch < 3; ++ch) img.pixels[3 * (y * N + x) + ch] = (float)v;
            var.pixels[y * N + x] = (float)(sigma * sigma);
        }
    double s = 0, s2 = 0;
    for (int y = 0; y < N; ++y)
        for (int x = 8; x < N / 2 - 8; ++x) {
            s += img.pixels[3 * (y * N + x)];
            s2 += img.pixels[3 * (y * N + x)] * img.pixels[3 * (y * N + x)];
        }
    int n = N * (N / 2 - 16);
    *noise_before = sqrt(fmax(0.0, s2 / n - (s / n) * (s / n)));
    soak_denoise_options o;
    soak_denoise_options_default(&o);
    char err[256];
    check_status("denoise step", soak_denoise(&img, &var, f, &o, NULL, err, sizeof err), SOAK_OK);
    *left = *right = s = s2 = 0;
    for (int y = 0; y < N; ++y) {
        *left += img.pixels[3 * (y * N + N / 2 - 1)] / N;
        *right += img.pixels[3 * (y * N + N / 2)] / N;
        for (int x = 8; x < N / 2 - 8; ++x) {
            s += img.pixels[3 * (y * N + x)];
            s2 += img.pixels[3 * (y * N + x)] * img.pixels[3 * (y * N + x)];
        }
    }
    *noise_after = sqrt(fmax(0.0, s2 / n - (s / n) * (s / n)));
    soak_image_free(&img);
    soak_image_free(&var);
}

static void test_edges(void)
{
    double l, r, n0, n1;
    step_filtered(0.2, 0.8, 0.05, NULL, &l, &r, &n0, &n1);
    printf("  step 0.2 | 0.8: columns beside it %.4f | %.4f; noise %.4f -> %.4f\n", l, r, n0, n1);
    check_close("left of a contrasted edge stays 0.2", l, 0.2, 0.02);
    check_close("right of a contrasted edge stays 0.8", r, 0.8, 0.02);
    check_true("noise at least halved", n1 < n0 / 2);

    soak_denoise_features f = {N, N, NULL, NULL, NULL, calloc(N * N, sizeof(int)), NULL};
    if (!f.object) return;
    for (int i = 0; i < N * N; ++i) f.object[i] = (i % N) < N / 2 ? 1 : 2;
    step_filtered(0.5, 0.55, 0.05, &f, &l, &r, &n0, &n1);
    printf("  step 0.5 | 0.55, object ids: %.4f | %.4f; noise %.4f -> %.4f\n", l, r, n0, n1);
    check_close("left of a faint edge between objects stays 0.5", l, 0.5, 0.005);
    check_close("right of it stays 0.55", r, 0.55, 0.005);
    check_true("noise at least halved", n1 < n0 / 2);
    double lb, rb;
    step_filtered(0.5, 0.55, 0.05, NULL, &lb, &rb, &n0, &n1);
    printf("  the same without features: %.4f | %.4f\n", lb, rb);
    check_true("without the ids the faint edge blurs (the feature term is what keeps it)", rb - lb < 0.5 * (r - l));
    free(f.object);
}

int main(void)
{
    double *ref = malloc(sizeof(double) * N * N);
    if (!ref) return 1;
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) ref[y * N + x] = plane_radiance(x, y);
    test_plane(ref);
    test_firefly(ref);
    test_edges();
    soak_image img = {0}, var = {0};
    soak_denoise_options o;
    soak_denoise_options_default(&o);
    soak_image_alloc(&img, 4, 4, 3);
    soak_image_alloc(&var, 4, 3, 1);
    char err[256] = "";
    check_true("a variance of another size is refused",
               soak_denoise(&img, &var, NULL, &o, NULL, err, sizeof err) == SOAK_ERR_ARG && strstr(err, "variance"));
    soak_image_free(&var);
    soak_image_alloc(&var, 4, 4, 1);
    o.sigma_colour = NAN;
    check_true("a NaN option is refused", soak_denoise(&img, &var, NULL, &o, NULL, err, sizeof err) == SOAK_ERR_ARG);
    soak_image_free(&img);
    soak_image_free(&var);
    free(ref);
    return check_finish();
}
