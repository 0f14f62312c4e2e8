/* Per-texel operations on maps: max, min, multiply, add, clamp, remap, and a
 * separable Gaussian blur. Inputs must have the same width, height and
 * channel count and finite texels; arithmetic in double, results stored as
 * float (saturated to the float range). */
#include "soak/bake.h"

#include <math.h>
#include <stdlib.h>

static soak_status check_image(const soak_image *img)
{
    if (!img || !img->pixels) return SOAK_ERR_NULL;
    if (soak_bake_check_size(img->width, img->height) != SOAK_OK || !(img->channels >= 1 && img->channels <= 4))
        return SOAK_ERR_ARG;
    size_t n = (size_t)img->width * img->height * img->channels;
    for (size_t i = 0; i < n; ++i)
        if (!soak_is_finite(img->pixels[i])) return SOAK_ERR_ARG;
    return SOAK_OK;
}

static size_t count(const soak_image *img)
{
    return (size_t)img->width * img->height * img->channels;
}

soak_status soak_map_combine(soak_combine_op op, const soak_image *a, const soak_image *b, soak_image *out)
{
    if (!out) return SOAK_ERR_NULL;
    soak_status st = check_image(a);
    if (st == SOAK_OK) st = check_image(b);
    if (st != SOAK_OK) return st;
    if (a->width != b->width || a->height != b->height || a->channels != b->channels) return SOAK_ERR_ARG;
    if (!(op >= SOAK_COMBINE_MAX && op <= SOAK_COMBINE_ADD)) return SOAK_ERR_ARG;
    if ((st = soak_image_alloc(out, a->width, a->height, a->channels)) != SOAK_OK) return st;
    size_t n = count(a);
    for (size_t i = 0; i < n; ++i) {
        double x = a->pixels[i], y = b->pixels[i], r;
        switch (op) {
        case SOAK_COMBINE_MAX: r = x > y ? x : y; break;
        case SOAK_COMBINE_MIN: r = x < y ? x : y; break;
        case SOAK_COMBINE_MULTIPLY: r = x * y; break;
        default: r = x + y; break;
        }
        /* float overflow of a sum or product of finite floats saturates. */
        out->pixels[i] = (float)fmax(-3.4e38, fmin(3.4e38, r));
    }
    return SOAK_OK;
}

soak_status soak_map_clamp(const soak_image *in, double lo, double hi, soak_image *out)
{
    if (!out) return SOAK_ERR_NULL;
    soak_status st = check_image(in);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(lo, -3.4e38, 3.4e38) || !soak_in_range(hi, lo, 3.4e38)) return SOAK_ERR_ARG;
    if ((st = soak_image_alloc(out, in->width, in->height, in->channels)) != SOAK_OK) return st;
    size_t n = count(in);
    for (size_t i = 0; i < n; ++i) out->pixels[i] = (float)fmin(hi, fmax(lo, (double)in->pixels[i]));
    return SOAK_OK;
}

soak_status soak_map_remap(const soak_image *in, double in_lo, double in_hi, double out_lo, double out_hi, int clamp,
                           soak_image *out)
{
    if (!out) return SOAK_ERR_NULL;
    soak_status st = check_image(in);
    if (st != SOAK_OK) return st;
    const double big = 1e30;
    if (!soak_in_range(in_lo, -big, big) || !soak_in_range(in_hi, -big, big) || !soak_in_range(out_lo, -big, big) ||
        !soak_in_range(out_hi, -big, big) || in_lo == in_hi)
        return SOAK_ERR_ARG;
    double scale = (out_hi - out_lo) / (in_hi - in_lo);
    if (!soak_is_finite(scale)) return SOAK_ERR_ARG;
    double lo = fmin(out_lo, out_hi), hi = fmax(out_lo, out_hi);
    if ((st = soak_image_alloc(out, in->width, in->height, in->channels)) != SOAK_OK) return st;
    size_t n = count(in);
    for (size_t i = 0; i < n; ++i) {
        double v = out_lo + (in->pixels[i] - in_lo) * scale;
        if (clamp) v = fmin(hi, fmax(lo, v));
        out->pixels[i] = (float)fmax(-3.4e38, fmin(3.4e38, v));
    }
    return SOAK_OK;
}

typedef struct blur_ctx {
    const soak_image *in;
    double *tmp; /* horizontal pass, same layout as the image */
    float *out;
    const double *w; /* weights, index -radius..radius at w[k + radius] */
    int radius, wrap;
} blur_ctx;

static int edge_index(int i, int n, int wrap)
{
    if (wrap) {
        int r = i % n;
        return r < 0 ? r + n : r;
    }
    return i < 0 ? 0 : (i >= n ? n - 1 : i);
}

static void blur_row(void *vctx, int y, int thread)
{
    (void)thread;
    blur_ctx *b = vctx;
    int W = b->in->width, C = b->in->channels;
    const float *src = b->in->pixels + (size_t)y * W * C;
    double *dst = b->tmp + (size_t)y * W * C;
    for (int x = 0; x < W; ++x)
        for (int c = 0; c < C; ++c) {
            double s = 0;
            for (int k = -b->radius; k <= b->radius; ++k)
                s += b->w[k + b->radius] * src[(size_t)edge_index(x + k, W, b->wrap) * C + c];
            dst[(size_t)x * C + c] = s;
        }
}

static void blur_column_pass(void *vctx, int y, int thread)
{
    (void)thread;
    blur_ctx *b = vctx;
    int W = b->in->width, H = b->in->height, C = b->in->channels;
    size_t row = (size_t)W * C;
    float *dst = b->out + (size_t)y * row;
    for (size_t i = 0; i < row; ++i) {
        double s = 0;
        for (int k = -b->radius; k <= b->radius; ++k) s += b->w[k + b->radius] * b->tmp[(size_t)edge_index(y + k, H, b->wrap) * row + i];
        dst[i] = (float)s;
    }
}

soak_status soak_map_blur(const soak_image *in, double sigma, int wrap, const soak_bake_exec *exec, soak_image *out)
{
    if (!out) return SOAK_ERR_NULL;
    soak_status st = check_image(in);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(sigma, 1e-6, SOAK_BLUR_MAX_SIGMA) || soak_bake_threads(exec) == 0) return SOAK_ERR_ARG;
    int radius = (int)ceil(3 * sigma);
    double *w = malloc(sizeof(double) * (2 * radius + 1));
    double *tmp = malloc(sizeof(double) * count(in));
    if (!w || !tmp) {
        free(w), free(tmp);
        return SOAK_ERR_NOMEM;
    }
    double sum = 0;
    for (int k = -radius; k <= radius; ++k) sum += w[k + radius] = exp(-0.5 * (k / sigma) * (k / sigma));
    for (int k = 0; k <= 2 * radius; ++k) w[k] /= sum;
    if ((st = soak_image_alloc(out, in->width, in->height, in->channels)) != SOAK_OK) {
        free(w), free(tmp);
        return st;
    }
    blur_ctx b = {in, tmp, out->pixels, w, radius, wrap != 0};
    st = soak_parallel_rows(in->height, exec, blur_row, &b, 0, 0.5);
    if (st == SOAK_OK) st = soak_parallel_rows(in->height, exec, blur_column_pass, &b, 0.5, 1);
    free(w), free(tmp);
    if (st != SOAK_OK) soak_image_free(out);
    return st;
}
