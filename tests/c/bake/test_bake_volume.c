/* Parameter volumes (soak/bake_volume.h): the penetration profile against
 * Simpson quadrature and its closed-form column integral delta/2, the
 * dry/wet interpolation, map orientation, and the three writers read back
 * by readers written here (df3 and raw bytes parsed by hand) or by OpenVDB. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cjson/cJSON.h>

#include "check.h"
#include "soak/bake_volume.h"
#include "soak/preset.h"
#include "soak/wetness.h"

static const char *dir = "test_tmp/bake_volume";

static double simpson_profile(double d0, double d1, double delta)
{
    int n = 2000;
    double h = (d1 - d0) / n, s = 0.0;
    for (int i = 0; i <= n; ++i) {
        double d = d0 + i * h, t = d / delta;
        double p = t >= 1.0 ? 0.0 : 1.0 - 3.0 * t * t + 2.0 * t * t * t; /* written out, not the library's */
        s += p * (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0));
    }
    return s * h / 3.0 / (d1 - d0);
}

static soak_vol_medium medium(double s, double a, double g1, double g2, double w)
{
    soak_vol_medium m = {{s, 1.5 * s, 2.0 * s}, {a, 0.5 * a, 0.25 * a}, g1, g2, w};
    return m;
}

static void test_profile(void)
{
    check_close("p(0) = 1", soak_wet_profile(0.0, 0.3), 1.0, 1e-15);
    check_close("p(delta/2) = 1/2", soak_wet_profile(0.15, 0.3), 0.5, 1e-15);
    check_close("p(delta) = 0", soak_wet_profile(0.3, 0.3), 0.0, 1e-15);
    check_close("p beyond delta = 0", soak_wet_profile(1.0, 0.3), 0.0, 0.0);
    check_close("delta = 0: dry", soak_wet_profile(0.0, 0.0), 0.0, 0.0);
    double worst = 0.0;
    double iv[][2] = {{0, 0.1}, {0.05, 0.2}, {0.1, 0.5}, {0.25, 0.35}, {0.0, 1.0}, {0.29, 0.31}};
    for (size_t i = 0; i < sizeof iv / sizeof iv[0]; ++i) {
        double d = fabs(soak_wet_profile_mean(iv[i][0], iv[i][1], 0.3) - simpson_profile(iv[i][0], iv[i][1], 0.3));
        if (d > worst) worst = d;
    }
    check_close("cell mean vs Simpson, max |diff|", worst, 0.0, 1e-9);
    check_close("zero-width cell = point value", soak_wet_profile_mean(0.1, 0.1, 0.3), soak_wet_profile(0.1, 0.3), 1e-15);
}

/* Column water = surface wetness * delta/2 at any resolution (delta < depth). */
static void test_column_integral(void)
{
    soak_vol_medium dry = medium(1, 0.1, 0.1, -0.05, 0.2), wet = medium(2, 0.2, 0.8, -0.1, 0.1);
    int nzs[] = {1, 3, 16, 57};
    double deltas[] = {0.01, 0.2, 0.49};
    double worst = 0.0;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 3; ++b) {
            soak_volume v;
            double size[3] = {1, 2, 0.5};
            soak_volume_alloc(&v, 2, 3, nzs[a], size);
            soak_volume_source src = {NULL, 0.7, deltas[b], NULL, NULL};
            if (!check_status("bake", soak_volume_bake(&v, (soak_vol_medium[2]){dry, wet}, 2, &src, NULL), SOAK_OK)) continue;
            double col = 0.0;
            for (int k = 0; k < v.nz; ++k) col += soak_volume_plane(&v, SOAK_VOL_WETNESS)[soak_volume_index(&v, 1, 2, k)];
            col *= 0.5 / v.nz;
            double d = fabs(col - 0.7 * deltas[b] / 2.0);
            if (d > worst) worst = d;
            soak_volume_free(&v);
        }
    check_close("column water vs 0.7 delta/2, max |diff| over nz and delta", worst, 0.0, 1e-6);
}

static void test_interpolation_and_orientation(void)
{
    soak_vol_medium dry = medium(1, 0.1, 0.05, -0.05, 0.2), wet = medium(3, 0.4, 0.8, -0.1, 0.1);
    soak_image map;
    soak_image_alloc(&map, 8, 4, 1);
    /* Top image rows (0, 1) wet on the left half only. */
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) map.pixels[y * 8 + x] = 1.0f;
    soak_volume v;
    double size[3] = {2, 1, 1};
    soak_volume_alloc(&v, 4, 2, 4, size);
    soak_volume_source src = {&map, 0.0, 0.5, NULL, NULL};
    check_status("bake from map", soak_volume_bake(&v, (soak_vol_medium[2]){dry, wet}, 2, &src, NULL), SOAK_OK);
    const float *wetp = soak_volume_plane(&v, SOAK_VOL_WETNESS);
    /* Top layer cell covers depth [0, 0.25] of delta 0.5: mean of p by Simpson. */
    double top = simpson_profile(0.0, 0.25, 0.5);
    check_close("wet column (x<1, y>0.5) top voxel", wetp[soak_volume_index(&v, 0, 1, 3)], top, 1e-6);
    check_close("dry column (x>1)", wetp[soak_volume_index(&v, 3, 1, 3)], 0.0, 1e-7);
    check_close("dry column (y<0.5: bottom image rows)", wetp[soak_volume_index(&v, 0, 0, 3)], 0.0, 1e-7);
    check_close("below the front", wetp[soak_volume_index(&v, 0, 1, 1)], 0.0, 1e-7);
    double worst = 0.0;
    size_t n = soak_volume_count(&v);
    for (size_t i = 0; i < n; ++i) {
        double w = wetp[i];
        double want[SOAK_VOL_NCHANNELS - 1] = {
            (1 - w) * dry.sigma_s.r + w * wet.sigma_s.r, (1 - w) * dry.sigma_s.g + w * wet.sigma_s.g,
            (1 - w) * dry.sigma_s.b + w * wet.sigma_s.b, (1 - w) * dry.sigma_a.r + w * wet.sigma_a.r,
            (1 - w) * dry.sigma_a.g + w * wet.sigma_a.g, (1 - w) * dry.sigma_a.b + w * wet.sigma_a.b,
            (1 - w) * dry.g1 + w * wet.g1, (1 - w) * dry.g2 + w * wet.g2, (1 - w) * dry.w + w * wet.w};
        for (int c = 0; c < SOAK_VOL_NCHANNELS - 1; ++c) {
            double d = fabs(soak_volume_plane(&v, c)[i] - want[c]) / (fabs(want[c]) + 1e-30);
            if (d > worst) worst = d;
        }
    }
    check_close("every channel = lerp(dry, wet, wetness), max rel diff", worst, 0.0, 1e-6);

    soak_volume_source none = {&map, 0.0, 0.0, NULL, NULL};
    soak_volume_bake(&v, (soak_vol_medium[2]){dry, wet}, 2, &none, NULL);
    double mx = 0.0;
    for (size_t i = 0; i < n; ++i) mx = wetp[i] > mx ? wetp[i] : mx;
    check_close("penetration depth 0: no voxel wet", mx, 0.0, 0.0);

    map.pixels[5] = NAN;
    check_status("NaN in the map", soak_volume_bake(&v, (soak_vol_medium[2]){dry, wet}, 2, &src, NULL), SOAK_ERR_ARG);
    soak_vol_medium bad = dry;
    bad.w = 1.5;
    check_status("w out of range", soak_volume_bake(&v, (soak_vol_medium[2]){bad, wet}, 2, &none, NULL), SOAK_ERR_ARG);
    bad = dry;
    bad.sigma_a.g = -1;
    check_status("negative sigma_a", soak_volume_bake(&v, (soak_vol_medium[2]){bad, wet}, 2, &none, NULL), SOAK_ERR_ARG);
    bad = dry;
    bad.g1 = 1.0;
    check_status("|g1| = 1", soak_volume_bake(&v, (soak_vol_medium[2]){bad, wet}, 2, &none, NULL), SOAK_ERR_ARG);
    soak_volume_source neg = {NULL, 1.0, -0.1, NULL, NULL};
    check_status("negative depth", soak_volume_bake(&v, (soak_vol_medium[2]){dry, wet}, 2, &neg, NULL), SOAK_ERR_ARG);
    soak_volume u;
    check_status("zero dim", soak_volume_alloc(&u, 0, 1, 1, size), SOAK_ERR_ARG);
    double nsize[3] = {1, NAN, 1};
    check_status("NaN size", soak_volume_alloc(&u, 1, 1, 1, nsize), SOAK_ERR_ARG);
    soak_image_free(&map);
    soak_volume_free(&v);
}

static double wet_x(void *ctx, double x, double y, double z)
{
    (void)ctx, (void)y, (void)z;
    return x / 2.0;
}

static void test_function(void)
{
    soak_vol_medium dry = medium(1, 0.1, 0.05, -0.05, 0.2), wet = medium(3, 0.4, 0.8, -0.1, 0.1);
    soak_volume v;
    double size[3] = {2, 1, 1};
    soak_volume_alloc(&v, 4, 2, 2, size);
    soak_volume_source src = {NULL, 0.0, 0.0, wet_x, NULL};
    check_status("bake 3D function", soak_volume_bake(&v, (soak_vol_medium[2]){dry, wet}, 2, &src, NULL), SOAK_OK);
    check_close("voxel i=2 centre x = 1.25 -> 0.625", soak_volume_plane(&v, SOAK_VOL_WETNESS)[soak_volume_index(&v, 2, 1, 0)],
                0.625, 1e-7);
    soak_volume_free(&v);

    /* 3D turbulence: every voxel holds the noise wetness at its centre, and
     * the bake is the same bytes on 1 and 2 threads. */
    soak_vol_turbulence turb;
    soak_turbulence_defaults(&turb.params);
    turb.params.seed = 42;
    turb.length = 2.0;
    check_status("turbulence params", soak_vol_turbulence_check(&turb), SOAK_OK);
    soak_volume a, b2;
    soak_volume_alloc(&a, 16, 9, 7, size);
    soak_volume_alloc(&b2, 16, 9, 7, size);
    soak_volume_source ts = {NULL, 0.0, 0.0, soak_vol_turbulence_wetness, &turb};
    soak_bake_exec one = {1, NULL, NULL}, two = {2, NULL, NULL};
    check_status("turbulence bake, 1 thread", soak_volume_bake(&a, (soak_vol_medium[2]){dry, wet}, 2, &ts, &one), SOAK_OK);
    check_status("turbulence bake, 2 threads", soak_volume_bake(&b2, (soak_vol_medium[2]){dry, wet}, 2, &ts, &two), SOAK_OK);
    check_true("1 and 2 threads: identical bytes",
               memcmp(a.data, b2.data, soak_volume_count(&a) * SOAK_VOL_NCHANNELS * sizeof(float)) == 0);
    double worst = 0.0, lo = 1.0, hi = 0.0;
    for (int k = 0; k < 7; ++k)
        for (int j = 0; j < 9; ++j)
            for (int i = 0; i < 16; ++i) {
                double want = soak_vol_turbulence_wetness(&turb, (i + 0.5) * 2.0 / 16, (j + 0.5) / 9.0, (k + 0.5) / 7.0);
                double got = soak_volume_plane(&a, SOAK_VOL_WETNESS)[soak_volume_index(&a, i, j, k)];
                worst = fmax(worst, fabs(got - want));
                lo = fmin(lo, got);
                hi = fmax(hi, got);
            }
    check_close("voxel = noise wetness at its centre, max |diff|", worst, 0.0, 1e-7);
    check_true("noise wetness spans a range inside [0,1]", lo >= 0.0 && hi <= 1.0 && hi - lo > 0.2);
    soak_volume_free(&a);
    soak_volume_free(&b2);
}

/* A preset's table: rows = soak_wetness_eval at w_i with 1/mm -> 1/m, and a
 * voxel of wetness between two rows gets their linear interpolation. */
static void test_preset(void)
{
    soak_preset_db *db = NULL;
    char err[512] = "";
    if (!check_status("load presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) {
        printf("%s\n", err);
        return;
    }
    const soak_preset *sand = soak_presets_find(db, "sand");
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    if (!check_true("sand and water presets", sand && water)) {
        soak_presets_free(db);
        return;
    }
    enum { N = 5 };
    soak_vol_medium rows[N];
    soak_vol_medium rows_mm[N];
    check_status("rows from preset, box in mm", soak_vol_rows_from_preset(sand, water, 1e-3, N, rows_mm), SOAK_OK);
    check_status("rows from preset, box in m", soak_vol_rows_from_preset(sand, water, 1.0, N, rows), SOAK_OK);
    double worst = 0.0, worst_mm = 0.0;
    for (int i = 0; i < N; ++i) {
        soak_wet_input in = soak_wet_input_steady(sand, i / (N - 1.0));
        soak_wet_params p;
        soak_wetness_eval(sand, water, &in, &p);
        worst = fmax(worst, fabs(rows[i].sigma_s.g - p.sigma_s_per_m.g) / p.sigma_s_per_m.g);
        worst = fmax(worst, fabs(rows[i].sigma_a.b - p.sigma_a_per_m.b) / (p.sigma_a_per_m.b + 1e-300));
        worst = fmax(worst, fabs(rows[i].g1 - p.phase.g1));
        worst_mm = fmax(worst_mm, fabs(1000.0 * rows_mm[i].sigma_s.g - p.sigma_s_per_m.g) / p.sigma_s_per_m.g);
        worst_mm = fmax(worst_mm, fabs(1000.0 * rows_mm[i].sigma_a.b - p.sigma_a_per_m.b) / (p.sigma_a_per_m.b + 1e-300));
    }
    check_close("preset rows (box in m) vs soak_wetness_eval (1/m), max rel diff", worst, 0.0, 1e-12);
    check_close("preset rows (box in mm) = 1/1000 of the chain's 1/m, max rel diff", worst_mm, 0.0, 1e-12);
    soak_vol_medium m = soak_vol_rows_eval(rows, N, 0.3); /* between rows 1 (0.25) and 2 (0.5) */
    check_close("w = 0.3: g1 = 0.8 row1 + 0.2 row2", m.g1, 0.8 * rows[1].g1 + 0.2 * rows[2].g1, 1e-12);
    check_close("w = 0.3: sigma_s.r", m.sigma_s.r, 0.8 * rows[1].sigma_s.r + 0.2 * rows[2].sigma_s.r, 1e-9);
    const soak_preset *cu = soak_presets_find(db, "copper");
    if (cu) check_status("conductor has no medium", soak_vol_rows_from_preset(cu, water, 1.0, N, rows), SOAK_ERR_ARG);
    soak_presets_free(db);
}

/* ---- readers written for the test ---- */

static unsigned char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *b = malloc((size_t)n + 1);
    *len = fread(b, 1, (size_t)n, f);
    b[*len] = 0;
    fclose(f);
    return b;
}

static int no_temporaries(const char *folder)
{
    DIR *d = opendir(folder);
    if (!d) return 0;
    struct dirent *e;
    int clean = 1;
    while ((e = readdir(d)))
        if (strstr(e->d_name, ".tmp")) clean = 0;
    closedir(d);
    return clean;
}

/* A volume with distinct values everywhere, including negative g2. */
static void fill_known(soak_volume *v)
{
    size_t n = soak_volume_count(v);
    for (int c = 0; c < SOAK_VOL_NCHANNELS; ++c)
        for (int k = 0; k < v->nz; ++k)
            for (int j = 0; j < v->ny; ++j)
                for (int i = 0; i < v->nx; ++i) {
                    double val = 0.1 * (c + 1) + 0.3 * i + 0.07 * j * j + 0.011 * k;
                    if (c == SOAK_VOL_G2) val = -0.5 + 0.01 * (i + j + k);
                    v->data[(size_t)c * n + soak_volume_index(v, i, j, k)] = (float)val;
                }
}

static void test_df3(int bits)
{
    soak_volume v;
    double size[3] = {1, 1, 0.5};
    soak_volume_alloc(&v, 5, 3, 4, size);
    fill_known(&v);
    char prefix[256], err[512] = "";
    snprintf(prefix, sizeof prefix, "%s/known%d", dir, bits);
    if (!check_status("write df3", soak_volume_write_df3(&v, prefix, bits, err, sizeof err), SOAK_OK)) {
        printf("%s\n", err);
        return;
    }
    char path[512];
    snprintf(path, sizeof path, "%s_df3.json", prefix);
    size_t len = 0;
    unsigned char *js = slurp(path, &len);
    cJSON *root = js ? cJSON_Parse((char *)js) : NULL;
    free(js);
    if (!check_true("sidecar JSON parses", root != NULL)) return;
    cJSON *chs = cJSON_GetObjectItem(root, "channels");
    double maxraw = bits == 32 ? 4294967295.0 : (double)((1u << bits) - 1);
    double worst_rel = 0.0;
    int layout_ok = 1, border_ok = 1;
    for (int c = 0; c < SOAK_VOL_NCHANNELS; ++c) {
        cJSON *o = cJSON_GetObjectItem(chs, soak_volume_channel_name(c));
        double off = cJSON_GetObjectItem(o, "offset")->valuedouble, sc = cJSON_GetObjectItem(o, "scale")->valuedouble;
        snprintf(path, sizeof path, "%s/%s", dir, cJSON_GetObjectItem(o, "file")->valuestring);
        unsigned char *b = slurp(path, &len);
        if (!b) {
            layout_ok = 0;
            continue;
        }
        int m[3];
        for (int a = 0; a < 3; ++a) m[a] = b[2 * a] << 8 | b[2 * a + 1]; /* big-endian uint16 */
        size_t bytes = (size_t)bits / 8, count = (size_t)m[0] * m[1] * m[2];
        if (m[0] != v.nx + 2 || m[1] != v.ny + 2 || m[2] != v.nz + 2 || len != 6 + count * bytes) {
            layout_ok = 0;
            free(b);
            continue;
        }
        for (int k = 0; k < m[2]; ++k)
            for (int j = 0; j < m[1]; ++j)
                for (int i = 0; i < m[0]; ++i) {
                    const unsigned char *p = b + 6 + (((size_t)k * m[1] + j) * m[0] + i) * bytes;
                    uint64_t raw = 0;
                    for (size_t q = 0; q < bytes; ++q) raw = raw << 8 | p[q];
                    double real = off + sc * (double)raw / maxraw;
                    int si = i == 0 ? 0 : (i > v.nx ? v.nx - 1 : i - 1);
                    int sj = j == 0 ? 0 : (j > v.ny ? v.ny - 1 : j - 1);
                    int sk = k == 0 ? 0 : (k > v.nz ? v.nz - 1 : k - 1);
                    double want = soak_volume_plane(&v, c)[soak_volume_index(&v, si, sj, sk)];
                    double e = fabs(real - want) / sc;
                    if (i == 0 || j == 0 || k == 0 || i > v.nx || j > v.ny || k > v.nz) {
                        if (e > 0.5 / maxraw + 1e-12) border_ok = 0;
                    } else if (e > worst_rel)
                        worst_rel = e;
                }
        free(b);
    }
    cJSON_Delete(root);
    char what[128];
    snprintf(what, sizeof what, "df3 %d-bit: dims N+2, file length 6 + count*%d", bits, bits / 8);
    check_true(what, layout_ok);
    snprintf(what, sizeof what, "df3 %d-bit: border replicates the edge voxels", bits);
    check_true(what, border_ok);
    snprintf(what, sizeof what, "df3 %d-bit: max |real - value| / scale (half a step)", bits);
    check_close(what, worst_rel, 0.0, 0.5 / maxraw + (bits == 32 ? 1e-7 : 1e-12)); /* float source for 32 bit */
    snprintf(path, sizeof path, "%s.inc", prefix);
    js = slurp(path, &len);
    check_true(".inc declares the scale of sigma_a_r", js && strstr((char *)js, "_sigma_a_r_scale = "));
    check_true(".inc has the density macro with translate -0.5/N",
               js && strstr((char *)js, "interpolate 1") && strstr((char *)js, "translate <-0.1, -0.16666"));
    free(js);
    soak_volume_free(&v);
}

static float le32(const unsigned char *p)
{
    uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
    float f;
    memcpy(&f, &u, 4);
    return f;
}

static void test_grid(void)
{
    soak_volume v;
    double size[3] = {3, 2, 1};
    soak_volume_alloc(&v, 6, 5, 4, size);
    fill_known(&v);
    soak_vol_medium dry = medium(1, 0.1, 0.05, -0.05, 0.2), wet = medium(3, 0.4, 0.8, -0.1, 0.1);
    char prefix[256], path[512], err[512] = "";
    snprintf(prefix, sizeof prefix, "%s/grid", dir);
    if (!check_status("write grid", soak_volume_write_grid(&v, prefix, (soak_vol_medium[2]){dry, wet}, 2, 0.1, err, sizeof err), SOAK_OK)) {
        printf("%s\n", err);
        return;
    }
    snprintf(path, sizeof path, "%s.json", prefix);
    size_t len;
    unsigned char *js = slurp(path, &len);
    cJSON *root = cJSON_Parse((char *)js);
    free(js);
    cJSON *dims = cJSON_GetObjectItem(root, "dims"), *chs = cJSON_GetObjectItem(root, "channels");
    int nx = cJSON_GetArrayItem(dims, 0)->valueint, ny = cJSON_GetArrayItem(dims, 1)->valueint,
        nz = cJSON_GetArrayItem(dims, 2)->valueint;
    check_true("grid dims", nx == 6 && ny == 5 && nz == 4);
    snprintf(path, sizeof path, "%s/%s", dir, cJSON_GetObjectItem(root, "data")->valuestring);
    unsigned char *raw = slurp(path, &len);
    size_t n = (size_t)nx * ny * nz;
    int nch = cJSON_GetArraySize(chs);
    check_true("raw length = channels * n * 4", raw && len == (size_t)nch * n * 4);
    double worst = 0.0;
    for (int q = 0; raw && q < nch && len == (size_t)nch * n * 4; ++q) {
        const char *name = cJSON_GetArrayItem(chs, q)->valuestring;
        int c = -1;
        for (int t = 0; t < SOAK_VOL_NCHANNELS; ++t)
            if (strcmp(name, soak_volume_channel_name(t)) == 0) c = t;
        if (c < 0) continue;
        for (size_t i = 0; i < n; ++i) {
            double d = fabs(le32(raw + 4 * ((size_t)q * n + i)) - soak_volume_plane(&v, c)[i]);
            if (d > worst) worst = d;
        }
    }
    check_close("raw float32le planes, max |diff|", worst, 0.0, 0.0);
    free(raw);
    cJSON_Delete(root);

    soak_volume back;
    snprintf(path, sizeof path, "%s.json", prefix);
    if (check_status("read grid", soak_volume_read_grid(path, &back, err, sizeof err), SOAK_OK)) {
        check_true("read grid: same data",
                   back.nx == 6 && memcmp(back.data, v.data, n * SOAK_VOL_NCHANNELS * sizeof(float)) == 0 &&
                       back.size[0] == 3.0);
        soak_volume_free(&back);
    }
    check_status("write into a missing folder",
                 soak_volume_write_grid(&v, "test_tmp/no_such_dir/x", NULL, 0, 0, err, sizeof err), SOAK_ERR_IO);
    check_true("message names the path", strstr(err, "no_such_dir") != NULL);
    soak_volume_free(&v);
}

static void test_vdb(void)
{
    if (!soak_volume_have_vdb()) {
        check_skip("OpenVDB round trip", "libsoak built without OpenVDB (SOAK_HAVE_OPENVDB)");
        return;
    }
    soak_volume v;
    double size[3] = {2, 1, 0.5};
    soak_volume_alloc(&v, 8, 4, 5, size);
    fill_known(&v);
    char path[256], err[512] = "";
    snprintf(path, sizeof path, "%s/known.vdb", dir);
    if (!check_status("write vdb", soak_volume_write_vdb(&v, path, err, sizeof err), SOAK_OK)) {
        printf("%s\n", err);
        return;
    }
    size_t n = soak_volume_count(&v);
    float *got = malloc(n * sizeof *got);
    double vs[3], org[3], worst = 0.0;
    int all = 1;
    for (int c = 0; c < SOAK_VOL_NCHANNELS; ++c) {
        if (soak_volume_read_vdb_grid(path, soak_volume_channel_name(c), 8, 4, 5, got, vs, org, err, sizeof err) !=
            SOAK_OK) {
            all = 0;
            continue;
        }
        for (size_t i = 0; i < n; ++i) worst = fmax(worst, fabs(got[i] - soak_volume_plane(&v, c)[i]));
    }
    check_true("every channel grid present", all);
    check_close("vdb channel grids, max |diff|", worst, 0.0, 0.0);
    check_close("voxel size x = 2/8", vs[0], 0.25, 1e-12);
    check_close("voxel size z = 0.5/5", vs[2], 0.1, 1e-12);
    check_close("voxel (0,0,0) centre x = half a voxel", org[0], 0.125, 1e-12);
    check_close("voxel (0,0,0) centre z", org[2], 0.05, 1e-12);
    /* density = mean(sigma_s + sigma_a) over RGB, computed here. */
    worst = 0.0;
    if (check_status("density grid", soak_volume_read_vdb_grid(path, "density", 8, 4, 5, got, vs, org, err, sizeof err),
                     SOAK_OK))
        for (size_t i = 0; i < n; ++i) {
            double want = 0.0;
            for (int c = 0; c < 6; ++c) want += soak_volume_plane(&v, c)[i];
            worst = fmax(worst, fabs(got[i] - want / 3.0));
        }
    check_close("density = mean extinction, max |diff|", worst, 0.0, 2e-6);
    check_status("missing grid", soak_volume_read_vdb_grid(path, "nope", 8, 4, 5, got, vs, org, err, sizeof err),
                 SOAK_ERR_NOT_FOUND);
    free(got);
    soak_volume_free(&v);
}

int main(void)
{
    mkdir("test_tmp", 0755);
    mkdir(dir, 0755);
    test_profile();
    test_column_integral();
    test_interpolation_and_orientation();
    test_function();
    test_preset();
    test_df3(8);
    test_df3(16);
    test_df3(32);
    test_grid();
    test_vdb();
    check_true("no temporary files left", no_temporaries(dir));
    return check_finish();
}
