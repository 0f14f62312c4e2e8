/* Map operations against per-texel expectations computed here, and the
 * separable blur against a direct 2D Gaussian convolution. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "soak/bake.h"

static soak_image random_image(int w, int h, int c, unsigned seed)
{
    soak_image img;
    soak_image_alloc(&img, w, h, c);
    for (int i = 0; i < w * h * c; ++i) {
        seed = seed * 1664525u + 1013904223u;
        img.pixels[i] = (float)((seed >> 8) / 16777216.0 * 3 - 1); /* [-1, 2) */
    }
    return img;
}

static void test_pointwise(void)
{
    const int w = 37, h = 23, c = 3, n = w * h * c;
    soak_image a = random_image(w, h, c, 1), b = random_image(w, h, c, 2), out;
    const char *names[] = {"max", "min", "multiply", "add"};
    for (int op = SOAK_COMBINE_MAX; op <= SOAK_COMBINE_ADD; ++op) {
        check_status(names[op], soak_map_combine((soak_combine_op)op, &a, &b, &out), SOAK_OK);
        double worst = 0;
        for (int i = 0; i < n; ++i) {
            double x = a.pixels[i], y = b.pixels[i];
            double want = op == 0 ? (x > y ? x : y) : op == 1 ? (x < y ? x : y) : op == 2 ? x * y : x + y;
            worst = fmax(worst, fabs(out.pixels[i] - (float)want));
        }
        char what[64];
        snprintf(what, sizeof what, "%s per texel", names[op]);
        check_close(what, worst, 0.0, 0.0);
        soak_image_free(&out);
    }
    check_status("clamp", soak_map_clamp(&a, 0.2, 0.7, &out), SOAK_OK);
    double worst = 0;
    for (int i = 0; i < n; ++i) {
        double x = a.pixels[i], want = x < 0.2 ? 0.2 : (x > 0.7 ? 0.7 : x);
        worst = fmax(worst, fabs(out.pixels[i] - (float)want));
    }
    check_close("clamp to [0.2, 0.7] per texel", worst, 0.0, 0.0);
    soak_image_free(&out);
    check_status("remap", soak_map_remap(&a, -1, 2, 1, 0, 0, &out), SOAK_OK);
    worst = 0;
    for (int i = 0; i < n; ++i) worst = fmax(worst, fabs(out.pixels[i] - (2 - a.pixels[i]) / 3.0));
    check_close("remap [-1,2] -> [1,0] = (2 - x)/3", worst, 0.0, 1e-7);
    soak_image_free(&out);
    check_status("remap clamped", soak_map_remap(&a, 0, 1, 0.25, 0.75, 1, &out), SOAK_OK);
    worst = 0;
    for (int i = 0; i < n; ++i) {
        double v = 0.25 + 0.5 * a.pixels[i];
        worst = fmax(worst, fabs(out.pixels[i] - fmin(0.75, fmax(0.25, v))));
    }
    check_close("remap [0,1] -> [0.25,0.75] clamped", worst, 0.0, 1e-7);
    soak_image_free(&out);

    soak_image small = random_image(w - 1, h, c, 3), gray = random_image(w, h, 1, 4);
    check_status("different widths rejected", soak_map_combine(SOAK_COMBINE_MAX, &a, &small, &out), SOAK_ERR_ARG);
    check_status("different channel counts rejected", soak_map_combine(SOAK_COMBINE_ADD, &a, &gray, &out), SOAK_ERR_ARG);
    check_status("clamp lo > hi rejected", soak_map_clamp(&a, 1, 0, &out), SOAK_ERR_ARG);
    check_status("remap empty input range rejected", soak_map_remap(&a, 1, 1, 0, 1, 0, &out), SOAK_ERR_ARG);
    b.pixels[5] = NAN;
    out.pixels = NULL;
    check_status("NaN texel rejected", soak_map_combine(SOAK_COMBINE_MAX, &a, &b, &out), SOAK_ERR_ARG);
    check_true("no output on error", out.pixels == NULL);
    soak_image_free(&a), soak_image_free(&b), soak_image_free(&small), soak_image_free(&gray);
}

static int clampi(int i, int n)
{
    return i < 0 ? 0 : (i >= n ? n - 1 : i);
}

static void test_blur(void)
{
    const int w = 29, h = 21, c = 2;
    const double sigma = 1.7;
    const int R = (int)ceil(3 * sigma);
    soak_image a = random_image(w, h, c, 9), out;
    soak_bake_exec two = {2, NULL, NULL};
    for (int wrap = 0; wrap < 2; ++wrap) {
        check_status("blur", soak_map_blur(&a, sigma, wrap, &two, &out), SOAK_OK);
        /* Direct 2D convolution with the normalised truncated Gaussian. */
        double norm = 0;
        for (int j = -R; j <= R; ++j)
            for (int i = -R; i <= R; ++i) norm += exp(-(i * i + j * j) / (2 * sigma * sigma));
        double worst = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int k = 0; k < c; ++k) {
                    double s = 0;
                    for (int j = -R; j <= R; ++j)
                        for (int i = -R; i <= R; ++i) {
                            int xx = wrap ? ((x + i) % w + w) % w : clampi(x + i, w);
                            int yy = wrap ? ((y + j) % h + h) % h : clampi(y + j, h);
                            s += exp(-(i * i + j * j) / (2 * sigma * sigma)) * a.pixels[(yy * w + xx) * c + k];
                        }
                    worst = fmax(worst, fabs(out.pixels[(y * w + x) * c + k] - s / norm));
                }
        check_close(wrap ? "blur (wrap) = direct 2D Gaussian convolution" : "blur (clamp) = direct 2D Gaussian convolution",
                    worst, 0.0, 2e-6);
        if (wrap) {
            double s0 = 0, s1 = 0;
            for (int i = 0; i < w * h * c; ++i) s0 += a.pixels[i], s1 += out.pixels[i];
            check_close("wrapped blur keeps the total", s1 - s0, 0.0, 1e-4);
        }
        soak_image_free(&out);
    }
    soak_image one;
    soak_image_alloc(&one, 1, 1, 1);
    one.pixels[0] = 0.625f;
    check_status("blur of a 1x1 map", soak_map_blur(&one, 40, 0, NULL, &out), SOAK_OK);
    check_close("blur of a 1x1 map is the map", out.pixels[0], 0.625, 1e-7);
    soak_image_free(&out);
    check_status("sigma 0 rejected", soak_map_blur(&a, 0, 0, NULL, &out), SOAK_ERR_ARG);
    check_status("sigma NaN rejected", soak_map_blur(&a, NAN, 0, NULL, &out), SOAK_ERR_ARG);
    soak_image_free(&one), soak_image_free(&a);
}

int main(void)
{
    test_pointwise();
    test_blur();
    return check_finish();
}
