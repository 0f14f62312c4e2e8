/* Benchmark driver (not a test) for instruction counts of the rain bake
 * under valgrind --tool=callgrind, where wall time is too noisy: bakes a
 * bumpy N x N grid (z up, UVs over [0,1]^2, Gaussian bumps and dimples like
 * rain_mesh.py) at RES x RES with RAYS rays, one thread, default rain, and
 * prints the mean water depth as a checksum (two builds must print the same
 * number). Writes no image, so it can be linked against the static layer
 * libraries alone (see c_core/bench/results/perf_24.md).
 * usage: bench_rain_bake_ir [RES] [RAYS] [N] [DURATION] */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "soak/bake_rain.h"

#ifdef SOAK_BENCH_NO_IMAGE_IO
/* Built by hand against the static layer libraries for callgrind (valgrind
 * stops at an instruction in a library OpenImageIO loads): the image
 * functions the bake needs, without OpenImageIO; file I/O is refused. */
#include "soak/image.h"
soak_status soak_image_alloc(soak_image *img, int width, int height, int channels)
{
    img->pixels = calloc((size_t)width * height * channels, sizeof(float));
    img->width = width, img->height = height, img->channels = channels;
    return img->pixels ? SOAK_OK : SOAK_ERR_NOMEM;
}
void soak_image_free(soak_image *img)
{
    free(img->pixels);
    img->pixels = NULL;
}
soak_status soak_image_read(const char *path, soak_image *img, char *err, size_t errlen)
{
    (void)path, (void)img, (void)err, (void)errlen;
    return SOAK_ERR_UNSUPPORTED;
}
soak_status soak_image_write(const char *path, const soak_image *img, const soak_image_write_opts *opts, char *err,
                             size_t errlen)
{
    (void)path, (void)img, (void)opts, (void)err, (void)errlen;
    return SOAK_ERR_UNSUPPORTED;
}
soak_status soak_image_write_tx(const char *path, const soak_image *img, char *err, size_t errlen)
{
    (void)path, (void)img, (void)err, (void)errlen;
    return SOAK_ERR_UNSUPPORTED;
}
soak_status soak_image_stage(struct soak_staged *stage, const char *path, const soak_image *img,
                             const soak_image_write_opts *opts, char *err, size_t errlen)
{
    (void)stage, (void)path, (void)img, (void)opts, (void)err, (void)errlen;
    return SOAK_ERR_UNSUPPORTED;
}
soak_status soak_image_stage_tx(struct soak_staged *stage, const char *path, const soak_image *img, char *err,
                                size_t errlen)
{
    (void)stage, (void)path, (void)img, (void)err, (void)errlen;
    return SOAK_ERR_UNSUPPORTED;
}
int soak_path_same(const char *a, const char *b)
{
    (void)a, (void)b;
    return 0;
}
#endif

static double height(double x, double y)
{
    static const double bumps[6][4] = {{-0.5, -0.4, 0.15, 0.2},  {0.4, 0.3, 0.2, -0.25}, {0.1, -0.6, 0.1, 0.3},
                                       {-0.3, 0.5, 0.25, -0.15}, {0.7, -0.2, 0.12, 0.2}, {0.0, 0.0, 0.3, -0.2}};
    double z = 0.0;
    for (int k = 0; k < 6; ++k) {
        double dx = x - bumps[k][0], dy = y - bumps[k][1], s = bumps[k][2];
        z += bumps[k][3] * exp(-(dx * dx + dy * dy) / (2 * s * s));
    }
    return z;
}

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : 256, rays = argc > 2 ? atoi(argv[2]) : 4, n = argc > 3 ? atoi(argv[3]) : 64;
    double duration = argc > 4 ? atof(argv[4]) : 600.0;
    if (res < 1 || rays < 1 || n < 1) return 2;
    soak_mesh m = {0};
    m.n_vertices = (size_t)(n + 1) * (n + 1);
    m.n_triangles = 2 * (size_t)n * n;
    m.positions = malloc(3 * m.n_vertices * sizeof(double));
    m.uvs = malloc(2 * m.n_vertices * sizeof(double));
    m.indices = malloc(3 * m.n_triangles * sizeof(unsigned));
    if (!m.positions || !m.uvs || !m.indices) return 2;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            size_t v = (size_t)j * (n + 1) + i;
            double u = (double)i / n, w = (double)j / n, x = 2 * u - 1, y = 2 * w - 1;
            m.positions[3 * v] = x, m.positions[3 * v + 1] = y, m.positions[3 * v + 2] = height(x, y);
            m.uvs[2 * v] = u, m.uvs[2 * v + 1] = w;
        }
    size_t t = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            unsigned a = (unsigned)(j * (n + 1) + i), b = a + 1, c = a + (unsigned)(n + 1), d = c + 1;
            unsigned q[6] = {a, b, d, a, d, c};
            for (int k = 0; k < 6; ++k) m.indices[t++] = q[k];
        }
    soak_rain_params p;
    soak_rain_defaults(&p);
    p.rays = rays;
    p.duration = duration;
    soak_bake_exec ex = {1, NULL, NULL};
    soak_rain_result r;
    char err[256] = "";
    soak_status st = soak_bake_rain(&m, res, res, &p, &ex, &r, err, sizeof err);
    if (st != SOAK_OK) {
        fprintf(stderr, "bake failed: %s %s\n", soak_status_str(st), err);
        return 1;
    }
    double sum = 0.0;
    for (size_t i = 0; i < (size_t)res * res; ++i) sum += r.water.pixels[i];
    printf("mean water depth %.17g m\n", sum / ((double)res * res));
    soak_rain_result_free(&r);
    free(m.positions);
    free(m.uvs);
    free(m.indices);
    return 0;
}
