/* Benchmark (not a test; issue 47 item 6): soak_mesh_load of one mesh
 * file through soak's native reader (SOAK_MESH_READER=auto) and through
 * Assimp alone (=assimp), interleaved, REPS times each. Prints min and
 * median CPU seconds (user + sys of this process and its contained reader
 * child, getrusage) and the vertex and triangle counts of each reader.
 *   bench_mesh_read MESH [REPS] */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "soak/geometry.h"

#define MAX_REPS 64

static double cpu_now(void)
{
    struct rusage s, c;
    getrusage(RUSAGE_SELF, &s);
    getrusage(RUSAGE_CHILDREN, &c);
    return (double)(s.ru_utime.tv_sec + s.ru_stime.tv_sec + c.ru_utime.tv_sec + c.ru_stime.tv_sec) +
           1e-6 * (double)(s.ru_utime.tv_usec + s.ru_stime.tv_usec + c.ru_utime.tv_usec + c.ru_stime.tv_usec);
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* One load through reader: its CPU seconds, or -1 on failure. */
static double load_once(const char *path, const char *reader, size_t *nv, size_t *nt)
{
    setenv("SOAK_MESH_READER", reader, 1);
    soak_mesh m = {0};
    char err[512] = "";
    double t0 = cpu_now();
    soak_status st = soak_mesh_load(path, 0, &m, err, sizeof err);
    double t = cpu_now() - t0;
    if (st != SOAK_OK) {
        fprintf(stderr, "bench_mesh_read: %s through %s: %s\n", path, reader, err);
        return -1;
    }
    *nv = m.n_vertices, *nt = m.n_triangles;
    soak_mesh_free(&m);
    return t;
}

int main(int argc, char **argv)
{
    int reps = argc > 2 ? atoi(argv[2]) : 5;
    if (argc < 2 || !(reps >= 1 && reps <= MAX_REPS)) {
        fprintf(stderr, "usage: bench_mesh_read MESH [REPS 1..%d]\n", MAX_REPS);
        return 2;
    }
    static const char *const readers[2] = {"auto", "assimp"};
    double t[2][MAX_REPS];
    size_t nv[2] = {0, 0}, nt[2] = {0, 0};
    for (int r = 0; r < reps; ++r)
        for (int k = 0; k < 2; ++k)
            if ((t[k][r] = load_once(argv[1], readers[k], &nv[k], &nt[k])) < 0) return 1;
    printf("| reader | vertices | triangles | CPU min / median (s) |\n|---|---|---|---|\n");
    for (int k = 0; k < 2; ++k) {
        qsort(t[k], (size_t)reps, sizeof t[k][0], by_value);
        printf("| %s | %zu | %zu | %.3f / %.3f |\n", readers[k], nv[k], nt[k], t[k][0], t[k][(reps - 1) / 2]);
    }
    return 0;
}
