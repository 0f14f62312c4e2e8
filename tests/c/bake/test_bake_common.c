/* Shared bake plumbing: frame-path patterns, smoothstep, row scheduling
 * (every row exactly once on any thread count), hash uniformity (chi-square
 * against the uniform distribution), output checks and writers. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "soak/bake.h"

static void test_patterns(void)
{
    char out[64];
    check_status("%04d", soak_bake_frame_path("wet.%04d.exr", 7, out, sizeof out), SOAK_OK);
    check_true("wet.%04d.exr, 7 -> wet.0007.exr", strcmp(out, "wet.0007.exr") == 0);
    check_status("%d", soak_bake_frame_path("a/%d.png", 120, out, sizeof out), SOAK_OK);
    check_true("a/%d.png, 120 -> a/120.png", strcmp(out, "a/120.png") == 0);
    check_status("%%", soak_bake_frame_path("100%%_%3d.tif", 5, out, sizeof out), SOAK_OK);
    check_true("100%%_%3d.tif, 5 -> 100%_  5.tif", strcmp(out, "100%_  5.tif") == 0);
    check_true("no conversion -> kind 0", soak_bake_pattern_kind("wet.exr") == 0);
    check_true("one conversion -> kind 1", soak_bake_pattern_kind("wet.%04d.exr") == 1);
    check_true("%s is malformed", soak_bake_pattern_kind("wet.%s.exr") == -1);
    check_true("two conversions are malformed", soak_bake_pattern_kind("%d.%d.exr") == -1);
    check_true("trailing % is malformed", soak_bake_pattern_kind("wet%") == -1);
    check_status("too short a buffer", soak_bake_frame_path("wet.%04d.exr", 7, out, 8), SOAK_ERR_ARG);
    check_status("negative frame", soak_bake_frame_path("wet.%04d.exr", -1, out, sizeof out), SOAK_ERR_ARG);
}

static void test_smoothstep(void)
{
    check_close("smoothstep below", soak_smoothstep(1, 2, 0.5), 0.0, 0.0);
    check_close("smoothstep above", soak_smoothstep(1, 2, 2.5), 1.0, 0.0);
    check_close("smoothstep mid = 1/2", soak_smoothstep(1, 2, 1.5), 0.5, 1e-15);
    check_close("smoothstep at 1/4 = 3/16 - 2/64", soak_smoothstep(0, 4, 1), 3.0 / 16 - 2.0 / 64, 1e-15);
    check_close("zero width: step at e0 (x = e0)", soak_smoothstep(1, 1, 1), 1.0, 0.0);
    check_close("zero width: step at e0 (x < e0)", soak_smoothstep(1, 1, 0.999), 0.0, 0.0);
    check_close("NaN gives 0", soak_smoothstep(0, 1, NAN), 0.0, 0.0);
}

typedef struct rows_ctx {
    int hits[1000];
    int bad_thread;
    int threads;
} rows_ctx;

static void count_row(void *vctx, int row, int thread)
{
    rows_ctx *c = vctx;
    c->hits[row] += 1; /* each row is handed out once: no race */
    if (thread < 0 || thread >= c->threads) c->bad_thread = 1;
}

static void note_progress(void *user, double f)
{
    double *last = user;
    if (f < *last) *last = -1; /* must not go backwards */
    else if (*last >= 0) *last = f;
}

static void test_rows(void)
{
    const int counts[] = {1, 2, 3, 8, 64};
    for (int k = 0; k < 5; ++k) {
        rows_ctx c;
        memset(&c, 0, sizeof c);
        double last = 0;
        soak_bake_exec ex = {counts[k], note_progress, &last};
        c.threads = soak_bake_threads(&ex);
        check_status("parallel rows", soak_parallel_rows(1000, &ex, count_row, &c, 0.25, 0.75), SOAK_OK);
        int once = 1;
        for (int i = 0; i < 1000; ++i) once &= c.hits[i] == 1;
        char what[80];
        snprintf(what, sizeof what, "%d threads: every row exactly once, thread ids in range", counts[k]);
        check_true(what, once && !c.bad_thread);
        check_close("progress ends at progress_hi, never goes back", last, 0.75, 0.0);
    }
    soak_bake_exec bad = {65, NULL, NULL};
    rows_ctx c;
    check_status("65 threads rejected", soak_parallel_rows(10, &bad, count_row, &c, 0, 1), SOAK_ERR_ARG);
    check_true("default thread count >= 1", soak_bake_threads(NULL) >= 1);
}

static void test_hash(void)
{
    /* Chi-square of 2^16 hashes of lattice neighbours over 64 bins: with 63
     * degrees of freedom the 99.9% quantile is 103.4. */
    int bins[64] = {0};
    const int n = 1 << 16;
    for (int i = 0; i < n; ++i) bins[(int)(soak_hash_unit(42, i & 255, i >> 8, 3) * 64)]++;
    double chi2 = 0, e = n / 64.0;
    for (int b = 0; b < 64; ++b) chi2 += (bins[b] - e) * (bins[b] - e) / e;
    printf("hash chi-square over 64 bins: %.1f\n", chi2);
    check_true("hash of neighbouring lattice points is uniform (chi2 < 103.4)", chi2 < 103.4);
    check_true("hash depends on the seed", soak_hash3(1, 2, 3, 4) != soak_hash3(2, 2, 3, 4));
    check_true("derived seeds differ", soak_seed_derive(1, 0) != soak_seed_derive(1, 1));
}

static void test_outputs(void)
{
    mkdir("test_tmp", 0755);
    char err[512] = "";
    soak_image img;
    soak_image_alloc(&img, 9, 7, 1);
    for (int i = 0; i < 63; ++i) img.pixels[i] = (float)(i / 62.0 * 1.3 - 0.1);
    check_status("float EXR", soak_bake_write("test_tmp/bake_common.exr", &img, 1, err, sizeof err), SOAK_OK);
    soak_image back;
    double worst = 0;
    if (check_status("read back", soak_image_read("test_tmp/bake_common.exr", &back, err, sizeof err), SOAK_OK)) {
        for (int i = 0; i < 63; ++i) worst = fmax(worst, fabs(back.pixels[i] - img.pixels[i]));
        soak_image_free(&back);
    }
    check_close("32-bit EXR round trip is exact", worst, 0.0, 0.0);
    check_status("tx", soak_bake_write("test_tmp/bake_common.tx", &img, 0, err, sizeof err), SOAK_OK);
    check_status("tx readable", soak_image_read("test_tmp/bake_common.tx", &back, err, sizeof err), SOAK_OK);
    check_true("tx keeps the size", back.width == 9 && back.height == 7);
    soak_image_free(&back);
    check_status("unsupported extension", soak_bake_write("test_tmp/x.jpg", &img, 0, err, sizeof err), SOAK_ERR_ARG);
    const char *inputs[] = {"test_tmp/bake_common.exr"};
    check_status("output = input", soak_bake_check_output("test_tmp/bake_common.exr", inputs, 1, err, sizeof err),
                 SOAK_ERR_ARG);
    check_status("output = input by another path",
                 soak_bake_check_output("test_tmp/../test_tmp/bake_common.exr", inputs, 1, err, sizeof err), SOAK_ERR_ARG);
    check_status("missing folder", soak_bake_check_output("test_tmp/nope/x.exr", inputs, 1, err, sizeof err), SOAK_ERR_IO);
    check_true("message names the folder", strstr(err, "test_tmp/nope") != NULL);
    check_status("fine output", soak_bake_check_output("test_tmp/other.exr", inputs, 1, err, sizeof err), SOAK_OK);
    soak_image_free(&img);
}

int main(void)
{
    test_patterns();
    test_smoothstep();
    test_rows();
    test_hash();
    test_outputs();
    return check_finish();
}
