/* Benchmark (not a test): a 4096 x 4096, 8-octave turbulence bake with the
 * default thread count. Prints wall seconds and Mpixel/s. Target: <= 2 s on
 * 2 cores. Usage: bench_bake_turbulence [threads] */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "soak/bake.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    soak_turbulence_params p;
    soak_turbulence_defaults(&p);
    p.sum = SOAK_NOISE_TURBULENCE;
    p.octaves = 8;
    p.frequency = 8;
    p.seed = 42;
    soak_bake_exec exec = {argc > 1 ? atoi(argv[1]) : 0, NULL, NULL};
    const int n = 4096;
    soak_image img;
    double t0 = now();
    soak_status st = soak_bake_turbulence(&p, n, n, &exec, &img);
    double t1 = now();
    if (st != SOAK_OK) {
        fprintf(stderr, "bake failed: %s\n", soak_status_str(st));
        return 1;
    }
    double sum = 0;
    for (size_t i = 0; i < (size_t)n * n; ++i) sum += img.pixels[i];
    soak_image_free(&img);
    printf("turbulence %dx%d, 8 octaves, %d threads: %.3f s wall, %.1f Mpixel/s (mean %.4f)\n", n, n,
           soak_bake_threads(&exec), t1 - t0, (double)n * n / (t1 - t0) / 1e6, sum / ((double)n * n));
    return 0;
}
