/* Benchmark driver (not a test): n calls of soak_model_eval (the checked
 * public entry) of one model at soak_model_params_default over 256 fixed
 * random direction pairs, for instruction counts under valgrind --tool=callgrind
 * (instructions per eval = (Ir(n) - Ir(0)) / n), where the shared machine
 * makes wall time too noisy. Uses only libsoak_models and libsoak_core, so it
 * can be linked without OpenImageIO (whose libhwy start-up valgrind cannot
 * run):
 *   cc -O2 -I c_core/models/include -I c_core/core/include bench_models_ir.c \
 *      BUILD/c_core/libsoak_models.a BUILD/c_core/libsoak_core.a -lm
 * usage: bench_models_ir MODEL N */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "soak/models.h"

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: bench_models_ir MODEL N\n");
        return 2;
    }
    const soak_model *m = soak_model_find(argv[1]);
    long n = atol(argv[2]);
    if (!m || n < 0) return 2;
    soak_model_params p;
    soak_model_params_default(&p);
    soak_model_ctx ctx;
    if (m->setup(&p, &ctx) != SOAK_OK) return 1;
    enum { NDIRS = 256 };
    soak_vec3 wi[NDIRS], wo[NDIRS];
    unsigned long long s = 12345;
    for (int i = 0; i < NDIRS; ++i) {
        double r[4];
        for (int k = 0; k < 4; ++k) {
            s = s * 6364136223846793005ULL + 1442695040888963407ULL;
            r[k] = (double)(s >> 11) * (1.0 / 9007199254740992.0);
        }
        double z1 = 0.02 + 0.98 * r[0], z2 = 0.02 + 0.98 * r[1], p1 = 2 * SOAK_PI * r[2], p2 = 2 * SOAK_PI * r[3];
        wi[i] = soak_v3(sqrt(1 - z1 * z1) * cos(p1), sqrt(1 - z1 * z1) * sin(p1), z1);
        wo[i] = soak_v3(sqrt(1 - z2 * z2) * cos(p2), sqrt(1 - z2 * z2) * sin(p2), z2);
    }
    double sum = 0.0;
    for (long k = 0; k < n; ++k) {
        double f = 0.0;
        if (soak_model_eval(m, &ctx, wi[k % NDIRS], wo[k % NDIRS], &f) != SOAK_OK) return 1;
        sum += f;
    }
    printf("%s %ld checksum %.17g\n", argv[1], n, sum);
    return 0;
}
