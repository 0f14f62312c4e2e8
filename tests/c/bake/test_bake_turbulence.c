/* Gradient noise, fBm and turbulence: statistical and exact properties.
 * References: gradient noise vanishes on the lattice (exact); octaves have
 * independent seeds, so variances add with weights gain^(2o) (identity),
 * each octave having the variance of a single-octave bake at its frequency;
 * row power spectra measured with an FFT written here fall by gain^2 per
 * octave band; periodicity of tileable maps; bit-identical bakes for any
 * thread count. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "soak/bake.h"

#define PI 3.14159265358979323846
#define SQRT2 1.41421356237309505

static void stats(const soak_image *img, double *mean, double *var)
{
    size_t n = (size_t)img->width * img->height;
    double s = 0, s2 = 0;
    for (size_t i = 0; i < n; ++i) s += img->pixels[i];
    double m = s / n;
    for (size_t i = 0; i < n; ++i) s2 += (img->pixels[i] - m) * (img->pixels[i] - m);
    *mean = m;
    *var = s2 / n;
}

static soak_image bake(const soak_turbulence_params *p, int w, int h, int threads)
{
    soak_image img = {0, 0, 0, NULL};
    soak_bake_exec ex = {threads, NULL, NULL};
    soak_status st = soak_bake_turbulence(p, w, h, &ex, &img);
    if (!check_status("bake", st, SOAK_OK)) exit(1);
    return img;
}

/* In-place iterative radix-2 FFT (n a power of two). */
static void fft(double *re, double *im, int n)
{
    for (int i = 1, j = 0; i < n; ++i) {
        int bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) {
            double t = re[i];
            re[i] = re[j], re[j] = t;
            t = im[i], im[i] = im[j], im[j] = t;
        }
    }
    for (int len = 2; len <= n; len <<= 1) {
        double ang = -2 * PI / len;
        for (int i = 0; i < n; i += len)
            for (int k = 0; k < len / 2; ++k) {
                double wr = cos(ang * k), wi = sin(ang * k);
                double *ar = re + i + k, *ai = im + i + k, *br = re + i + k + len / 2, *bi = im + i + k + len / 2;
                double tr = *br * wr - *bi * wi, ti = *br * wi + *bi * wr;
                *br = *ar - tr, *bi = *ai - ti;
                *ar += tr, *ai += ti;
            }
    }
}

/* Adds the 2D power spectrum |F(kx, ky)|^2 of a square image into radial
 * bands: band o holds |k| in [f0 2^o / sqrt 2, f0 2^o sqrt 2) cycles per
 * width. */
static void radial_bands(const soak_image *img, double f0, double *band, int nbands)
{
    int n = img->width;
    double *re = malloc(sizeof(double) * n * n), *im = calloc((size_t)n * n, sizeof(double));
    double *cr = malloc(sizeof(double) * n), *ci = malloc(sizeof(double) * n);
    for (int i = 0; i < n * n; ++i) re[i] = img->pixels[i];
    for (int y = 0; y < n; ++y) fft(re + (size_t)y * n, im + (size_t)y * n, n);
    for (int x = 0; x < n; ++x) {
        for (int y = 0; y < n; ++y) cr[y] = re[(size_t)y * n + x], ci[y] = im[(size_t)y * n + x];
        fft(cr, ci, n);
        for (int y = 0; y < n; ++y) {
            int kx = x <= n / 2 ? x : x - n, ky = y <= n / 2 ? y : y - n;
            double k = sqrt((double)kx * kx + (double)ky * ky);
            for (int o = 0; o < nbands; ++o)
                if (k >= f0 * pow(2, o) / SQRT2 && k < f0 * pow(2, o) * SQRT2) band[o] += cr[y] * cr[y] + ci[y] * ci[y];
        }
    }
    free(re), free(im), free(cr), free(ci);
}

static void test_lattice_zero(void)
{
    double worst = 0, maxabs = 0;
    for (int i = -20; i <= 20; ++i)
        for (int j = -20; j <= 20; ++j) {
            worst = fmax(worst, fabs(soak_noise2(7, i, j, 0, 0)));
            worst = fmax(worst, fabs(soak_noise3(7, i, j, i - j, 0, 0, 0)));
        }
    check_close("gradient noise is 0 on the lattice (2D and 3D)", worst, 0.0, 0.0);
    for (int k = 0; k < 200000; ++k) {
        double x = 0.01 * k + 0.123, y = 0.0073 * k - 5.1;
        maxabs = fmax(maxabs, fabs(soak_noise2(3, x, y, 0, 0)));
    }
    check_true("2D noise within [-1, 1] (bound sqrt(2)*sqrt(2)/2)", maxabs <= 1.0 + 1e-12);
    check_true("2D noise uses most of its range (> 0.6)", maxabs > 0.6);
    double p = soak_noise2(9, 2.3, 4.7, 5, 7), q = soak_noise2(9, 2.3 + 5, 4.7 - 14, 5, 7);
    check_close("periodic noise repeats with its period", p, q, 1e-12);
}

static void test_mean_and_variance(void)
{
    const int w = 512, h = 512, octaves = 5;
    const double f0 = 16, gain = 0.6;
    soak_turbulence_params p;
    soak_turbulence_defaults(&p);
    p.seed = 11;
    p.frequency = f0;
    p.octaves = 1;
    soak_image one = bake(&p, w, h, 0);
    double m1, v1;
    stats(&one, &m1, &v1);
    soak_image_free(&one);
    printf("single octave at %g cells: mean %.4g variance %.5g\n", f0, m1, v1);
    /* Scale invariance: each octave on its own has the same variance. */
    double sum_w = 0, sum_w2 = 0, wgt = 1, f = f0;
    for (int o = 0; o < octaves; ++o, wgt *= gain, f *= 2) {
        p.frequency = f;
        p.seed = 100 + o;
        soak_image img = bake(&p, w, h, 0);
        double m, v;
        stats(&img, &m, &v);
        soak_image_free(&img);
        char what[96];
        snprintf(what, sizeof what, "octave at %g cells has the single-octave variance", f);
        check_rel(what, v, v1, 0.08);
        sum_w += wgt;
        sum_w2 += wgt * wgt;
    }
    p.frequency = f0;
    p.octaves = octaves;
    p.gain = gain;
    p.seed = 11;
    soak_image fbm = bake(&p, w, h, 0);
    double m, v;
    stats(&fbm, &m, &v);
    soak_image_free(&fbm);
    check_close("fBm mean ~ 0 (within 0.1 standard deviations)", m / sqrt(v), 0.0, 0.1);
    check_rel("fBm variance = var1 sum g^2o / (sum g^o)^2 (independent octaves)", v, v1 * sum_w2 / (sum_w * sum_w), 0.06);
}

static void test_spectrum(double gain)
{
    const int n = 512, octaves = 4, seeds = 6;
    const double f0 = 12;
    soak_turbulence_params p;
    soak_turbulence_defaults(&p);
    p.frequency = f0;
    p.gain = gain;
    /* Octave o of the sum is isolated exactly from the public bakes:
     * S_(o+1) fbm_(o+1) - S_o fbm_o = g^o n_o (octave seeds do not depend on
     * the octave count; S_k = sum of the first k weights). Its power in its
     * own band o then scales by g^2 per octave: every octave is the same
     * noise statistics at twice the frequency. */
    double band[4][4];
    memset(band, 0, sizeof band);
    soak_image prev = {0, 0, 0, NULL}, cur, oct;
    soak_image_alloc(&oct, n, n, 1);
    for (int s = 0; s < seeds; ++s) {
        p.seed = 5 + s;
        double S_prev = 0, S = 0, w = 1;
        for (int o = 0; o < octaves; ++o, w *= gain) {
            p.octaves = o + 1;
            S += w;
            cur = bake(&p, n, n, 0);
            for (int i = 0; i < n * n; ++i) oct.pixels[i] = (float)(S * cur.pixels[i] - (o ? S_prev * prev.pixels[i] : 0));
            radial_bands(&oct, f0, band[o], 4);
            soak_image_free(&prev);
            prev = cur;
            S_prev = S;
        }
        soak_image_free(&prev);
    }
    soak_image_free(&oct);
    for (int o = 0; o + 1 < octaves; ++o) {
        char what[112];
        snprintf(what, sizeof what, "gain %g: octave %d band power / octave %d band power = gain^2", gain, o + 1, o);
        check_rel(what, band[o + 1][o + 1] / band[o][o], gain * gain, 0.1);
    }
    /* An octave's power stays in its band and the next: little leaks two bands up. */
    check_true("octave 0 holds < 2% of its power two bands up", band[0][2] < 0.02 * band[0][0]);
}

static void test_tileable(void)
{
    const int w = 256, h = 192;
    soak_turbulence_params p;
    soak_turbulence_defaults(&p);
    p.seed = 21;
    p.frequency = 5.3; /* rounded to whole cells per octave */
    p.octaves = 5;
    p.tileable = 1;
    soak_image img = bake(&p, w, h, 0);
    double worst = 0;
    for (int y = 0; y < h; y += 7) {
        double v;
        soak_turbulence_eval(&p, w, h, -0.5, y + 0.5, &v); /* one texel left of column 0 */
        worst = fmax(worst, fabs(v - img.pixels[(size_t)y * w + w - 1]));
        soak_turbulence_eval(&p, w, h, y % w + 0.5, h + 0.5, &v); /* one texel below the last row */
        worst = fmax(worst, fabs(v - img.pixels[(size_t)(y % w)]));
    }
    check_close("tileable: value one texel past an edge = texel on the opposite edge", worst, 0.0, 1e-6);
    /* Statistics of the seam difference match the interior neighbour ones. */
    double seam = 0, inner = 0, seam_v = 0, inner_v = 0;
    for (int y = 0; y < h; ++y) {
        const float *r = img.pixels + (size_t)y * w;
        seam += fabs(r[0] - r[w - 1]);
        for (int x = 0; x + 1 < w; ++x) inner += fabs(r[x + 1] - r[x]);
    }
    for (int x = 0; x < w; ++x) {
        seam_v += fabs(img.pixels[x] - img.pixels[(size_t)(h - 1) * w + x]);
        for (int y = 0; y + 1 < h; ++y) inner_v += fabs(img.pixels[(size_t)(y + 1) * w + x] - img.pixels[(size_t)y * w + x]);
    }
    check_rel("mean |v(0,y) - v(W-1,y)| = mean interior neighbour difference", seam / h, inner / ((double)h * (w - 1)), 0.2);
    check_rel("mean |v(x,0) - v(x,H-1)| = mean interior neighbour difference", seam_v / w, inner_v / ((double)w * (h - 1)), 0.2);
    soak_image_free(&img);
    p.tileable = 0;
    img = bake(&p, w, h, 0);
    seam = inner = 0;
    for (int y = 0; y < h; ++y) {
        const float *r = img.pixels + (size_t)y * w;
        seam += fabs(r[0] - r[w - 1]);
        for (int x = 0; x + 1 < w; ++x) inner += fabs(r[x + 1] - r[x]);
    }
    check_true("not tileable: the seam is a jump (> 3x the neighbour difference)", seam / h > 3 * inner / ((double)h * (w - 1)));
    soak_image_free(&img);
}

static void test_determinism_and_modes(void)
{
    const int w = 300, h = 217;
    soak_turbulence_params p;
    soak_turbulence_defaults(&p);
    p.seed = 1234567890123ULL;
    p.sum = SOAK_NOISE_TURBULENCE;
    p.octaves = 7;
    p.use_3d = 1;
    p.z = 2.7;
    soak_image a = bake(&p, w, h, 1), b = bake(&p, w, h, 2), c = bake(&p, w, h, 5);
    check_true("threads 1 vs 2: identical bytes", memcmp(a.pixels, b.pixels, sizeof(float) * w * h) == 0);
    check_true("threads 1 vs 5: identical bytes", memcmp(a.pixels, c.pixels, sizeof(float) * w * h) == 0);
    double worst = 0, lo = 1e9;
    for (int y = 0; y < h; y += 13)
        for (int x = 0; x < w; x += 11) {
            double v;
            soak_turbulence_eval(&p, w, h, x + 0.5, y + 0.5, &v);
            worst = fmax(worst, fabs((float)v - a.pixels[(size_t)y * w + x]));
        }
    for (int i = 0; i < w * h; ++i) lo = fmin(lo, a.pixels[i]);
    check_close("point evaluation = baked texel", worst, 0.0, 0.0);
    check_true("turbulence >= 0", lo >= 0);
    soak_image_free(&b);
    p.seed += 1;
    b = bake(&p, w, h, 2);
    check_true("another seed gives another map", memcmp(a.pixels, b.pixels, sizeof(float) * w * h) != 0);
    soak_image_free(&b);
    p.seed -= 1;
    p.thresholded = 1;
    p.threshold = 0.3;
    p.softness = 0.05;
    b = bake(&p, w, h, 2);
    worst = 0;
    for (int i = 0; i < w * h; ++i)
        worst = fmax(worst, fabs(b.pixels[i] - soak_smoothstep(0.25, 0.35, (double)a.pixels[i])));
    check_close("threshold = smoothstep(T-S, T+S, value)", worst, 0.0, 1e-6);
    soak_image_free(&b);
    p.softness = 0;
    b = bake(&p, w, h, 2);
    int binary = 1;
    for (int i = 0; i < w * h; ++i) binary &= b.pixels[i] == 0.0f || b.pixels[i] == 1.0f;
    check_true("softness 0: a hard 0/1 mask", binary);
    soak_image_free(&a), soak_image_free(&b), soak_image_free(&c);
}

static void test_arguments(void)
{
    soak_turbulence_params p;
    soak_turbulence_defaults(&p);
    soak_image img = {0, 0, 0, NULL};
    check_status("width 0", soak_bake_turbulence(&p, 0, 10, NULL, &img), SOAK_ERR_ARG);
    check_status("height 16385", soak_bake_turbulence(&p, 10, 16385, NULL, &img), SOAK_ERR_ARG);
    check_status("NULL params", soak_bake_turbulence(NULL, 10, 10, NULL, &img), SOAK_ERR_NULL);
    soak_bake_exec ex = {65, NULL, NULL};
    check_status("65 threads", soak_bake_turbulence(&p, 10, 10, &ex, &img), SOAK_ERR_ARG);
    p.gain = NAN;
    check_status("gain NaN", soak_turbulence_check(&p), SOAK_ERR_ARG);
    soak_turbulence_defaults(&p);
    p.octaves = 0;
    check_status("0 octaves", soak_turbulence_check(&p), SOAK_ERR_ARG);
    soak_turbulence_defaults(&p);
    p.lacunarity = 0.5;
    check_status("lacunarity 0.5", soak_turbulence_check(&p), SOAK_ERR_ARG);
    soak_turbulence_defaults(&p);
    p.octaves = 24;
    p.lacunarity = 16;
    check_status("top octave finer than int lattice allows", soak_turbulence_check(&p), SOAK_ERR_ARG);
    soak_turbulence_defaults(&p);
    double v = 7;
    check_status("eval far outside", soak_turbulence_eval(&p, 10, 10, 1e30, 0, &v), SOAK_ERR_ARG);
    check_true("no output on error", v == 7);
    p.gain = 0; /* only octave 0 counts */
    check_status("gain 0 accepted", soak_turbulence_eval(&p, 10, 10, 3.3, 4.4, &v), SOAK_OK);
    check_true("gain 0 finite", soak_is_finite(v));
}

int main(void)
{
    test_lattice_zero();
    test_mean_and_variance();
    test_spectrum(0.5);
    test_spectrum(0.7);
    test_tileable();
    test_determinism_and_modes();
    test_arguments();
    return check_finish();
}
