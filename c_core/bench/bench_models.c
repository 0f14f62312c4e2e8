/* Speed vs error of every model and fast path, measured in one run.
 * ns/eval: mean over many evaluations of a fixed set of random direction
 * pairs (one core). max rel err: against the exact peer on the fixed grid
 * theta_i, theta_o in 0..85 step 5 deg, phi in {0, 180}, where the exact
 * value exceeds 1e-4 of its grid maximum. Writes a Markdown table to stdout
 * (and to argv[1] when given). Not a test: nothing here asserts a time. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "soak/fresnel.h"
#include "soak/hg.h"
#include "soak/models.h"
#include "soak/ww.h"

#define NDIRS 4096

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* The fixed random direction pairs every timing loop evaluates. */
typedef struct dir_set {
    soak_vec3 wi[NDIRS], wo[NDIRS];
} dir_set;

static double rnd(uint64_t *rs)
{
    *rs ^= *rs << 13;
    *rs ^= *rs >> 7;
    *rs ^= *rs << 17;
    return (double)(*rs >> 11) * (1.0 / 9007199254740992.0);
}

static void make_dirs(dir_set *d)
{
    uint64_t rs = 12345;
    for (int i = 0; i < NDIRS; ++i) {
        double z1 = 0.02 + 0.98 * rnd(&rs), z2 = 0.02 + 0.98 * rnd(&rs), p1 = 2 * SOAK_PI * rnd(&rs),
               p2 = 2 * SOAK_PI * rnd(&rs);
        d->wi[i] = soak_v3(sqrt(1 - z1 * z1) * cos(p1), sqrt(1 - z1 * z1) * sin(p1), z1);
        d->wo[i] = soak_v3(sqrt(1 - z2 * z2) * cos(p2), sqrt(1 - z2 * z2) * sin(p2), z2);
    }
}

/* A table row to stdout and, when open, to the output file. */
static void emit(const char *line, FILE *out)
{
    fputs(line, stdout);
    if (out) fputs(line, out);
}

static double time_model(const dir_set *d, const soak_model *m, const soak_model_ctx *ctx)
{
    volatile double sink; /* keeps the loop's work */
    long reps = 1;
    for (;;) {
        double t0 = now(), acc = 0;
        for (long r = 0; r < reps; ++r)
            for (int i = 0; i < NDIRS; ++i) {
                double f;
                soak_model_eval(m, ctx, d->wi[i], d->wo[i], &f);
                acc += f;
            }
        double dt = now() - t0;
        sink = acc;
        (void)sink;
        if (dt > 0.3) return 1e9 * dt / (reps * (double)NDIRS);
        reps *= 2;
    }
}

static double max_rel_error(const soak_model *fast, const soak_model_ctx *fc, const soak_model *exact,
                            const soak_model_ctx *ec, int max_deg)
{
    double vals[2][18][18], peak = 0, worst = 0;
    for (int p = 0; p < 2; ++p)
        for (int a = 0; a < 18; ++a)
            for (int b = 0; b < 18; ++b) {
                soak_vec3 wi = soak_v3_polar(a * 5 * SOAK_PI / 180, 0);
                soak_vec3 wo = soak_v3_polar(b * 5 * SOAK_PI / 180, p * SOAK_PI);
                soak_model_eval(exact, ec, wi, wo, &vals[p][a][b]);
                peak = fmax(peak, vals[p][a][b]);
            }
    for (int p = 0; p < 2; ++p)
        for (int a = 0; a < 18; ++a)
            for (int b = 0; b < 18; ++b) {
                double ex = vals[p][a][b], f;
                if (ex < 1e-4 * peak || a * 5 > max_deg || b * 5 > max_deg) continue;
                soak_model_eval(fast, fc, soak_v3_polar(a * 5 * SOAK_PI / 180, 0), soak_v3_polar(b * 5 * SOAK_PI / 180, p * SOAK_PI), &f);
                worst = fmax(worst, fabs(f - ex) / ex);
            }
    return worst;
}

/* One row per model of the registry: its time and its error against its exact peer. */
static void bench_registry(const dir_set *d, const soak_model_params *p, FILE *out)
{
    size_t n;
    const soak_model *models = soak_models(&n);
    for (size_t i = 0; i < n; ++i) {
        soak_model_ctx ctx;
        if (models[i].setup(p, &ctx) != SOAK_OK) continue;
        double ns = time_model(d, &models[i], &ctx);
        char err[32] = "-", err60[32] = "-", line[256];
        if (models[i].exact) {
            const soak_model *ex = soak_model_find(models[i].exact);
            soak_model_ctx ectx;
            ex->setup(p, &ectx);
            snprintf(err, sizeof err, "%.3g", max_rel_error(&models[i], &ctx, ex, &ectx, 85));
            snprintf(err60, sizeof err60, "%.3g", max_rel_error(&models[i], &ctx, ex, &ectx, 60));
        }
        snprintf(line, sizeof line, "| %s | %.1f | %.1f | %s | %s | %s |\n", models[i].name, ns, 1e3 / ns,
                 models[i].exact ? models[i].exact : "-", err, err60);
        emit(line, out);
    }
}

/* The Tri-Ace fast path as a hot loop would call it: unchecked form,
 * directions already valid (the registry rows include argument checks on
 * every call). */
static void bench_triace_raw(const dir_set *d, const soak_model_params *p, FILE *out)
{
    soak_ww ww;
    soak_ww_default(&ww);
    ww.alpha = p->roughness;
    ww.kd = p->albedo;
    soak_ww_triace fast;
    if (soak_ww_triace_setup(&ww, &fast) != SOAK_OK) return;
    volatile double sink;
    long reps = 1;
    double dt = 0, acc = 0;
    for (;;) {
        double t0 = now();
        for (long r = 0; r < reps; ++r)
            for (int i = 0; i < NDIRS; ++i) acc += soak_ww_eval_triace_raw(&fast, d->wi[i], d->wo[i]);
        dt = now() - t0;
        if (dt > 0.3) break;
        reps *= 2;
    }
    sink = acc;
    (void)sink;
    double ns = 1e9 * dt / (reps * (double)NDIRS);
    char line[256];
    snprintf(line, sizeof line, "| ww-triace (unchecked _raw form) | %.1f | %.1f | ww | as above | as above |\n", ns,
             1e3 / ns);
    emit(line, out);
}

/* Fresnel: exact vs Schlick, same run. */
static void bench_fresnel(const dir_set *d, FILE *out)
{
    volatile double sink;
    double t0 = now(), acc = 0;
    const long N = 20000000;
    for (long i = 0; i < N; ++i) acc += soak_fresnel_dielectric_raw(d->wi[i & (NDIRS - 1)].z, 1.33, NULL);
    double ns_exact = 1e9 * (now() - t0) / N;
    double r0 = pow(0.33 / 2.33, 2), worst = 0, worst60 = 0;
    t0 = now();
    for (long i = 0; i < N; ++i) {
        double c = 1 - d->wi[i & (NDIRS - 1)].z, c2 = c * c;
        acc += r0 + (1 - r0) * c2 * c2 * c;
    }
    double ns_schlick = 1e9 * (now() - t0) / N;
    for (int a = 0; a <= 85; a += 5) {
        double c = cos(a * SOAK_PI / 180), R, S;
        soak_fresnel_dielectric(c, 1.33, &R, NULL);
        soak_fresnel_schlick(c, r0, &S);
        worst = fmax(worst, fabs(S - R) / R);
        if (a <= 60) worst60 = fmax(worst60, fabs(S - R) / R);
    }
    sink = acc;
    (void)sink;
    char line[256];
    snprintf(line, sizeof line,
             "| fresnel-dielectric (n=1.33) | %.1f | %.1f | - | - | - |\n"
             "| fresnel-schlick | %.1f | %.1f | fresnel-dielectric | %.3g | %.3g |\n",
             ns_exact, 1e3 / ns_exact, ns_schlick, 1e3 / ns_schlick, worst, worst60);
    emit(line, out);
}

int main(int argc, char **argv)
{
    if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {
        fprintf(stderr, "usage: bench_models [REPORT.md]\n"
                        "Times every model's checked evaluation on one core and prints a Markdown table\n"
                        "(also written to REPORT.md when given). A benchmark: it asserts nothing.\n");
        return argc == 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) ? 0 : 2;
    }
    FILE *out = NULL;
    if (argc == 2 && !(out = fopen(argv[1], "w"))) {
        fprintf(stderr, "bench_models: cannot write %s\n", argv[1]);
        return 1;
    }
    dir_set *d = malloc(sizeof *d);
    if (!d) {
        if (out) fclose(out);
        return 1;
    }
    make_dirs(d);
    emit("| model | ns/eval | M evals/s | exact peer | max rel err (0-85 deg) | max rel err (0-60 deg) |\n"
         "|---|---:|---:|---|---:|---:|\n",
         out);
    soak_model_params p;
    soak_model_params_default(&p);
    bench_registry(d, &p, out);
    bench_triace_raw(d, &p, out);
    bench_fresnel(d, out);
    free(d);
    if (out && fclose(out) != 0) {
        fprintf(stderr, "bench_models: writing %s failed\n", argv[1]);
        return 1;
    }
    return 0;
}
