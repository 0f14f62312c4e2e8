/* Malformed-file sweep (issue 21, "Done when"): every format Soak reads --
 * meshes (OBJ, ASCII and binary PLY and STL, OFF, glTF, GLB), images (PNG,
 * EXR, TIFF, HDR, JPEG, PPM), volumes (grid header and payload, df3,
 * OpenVDB), scene JSON and the materials JSON -- cut at every tenth of its
 * length (0/10 .. 9/10) through the reader Soak itself uses. Every case
 * must be refused with a message that is printable text naming the file,
 * never by the mesh reader's time limit; a cut that happens to leave a valid
 * file (an OBJ or ASCII PLY/STL/OFF cut between records, a text scene never)
 * is counted and printed as read. The whole sweep runs under ctest's
 * TIMEOUT of 60 s (tests/fuzz/CMakeLists.txt); its wall time is printed.
 *   usage: sweep_malformed SOURCE_DIR */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "soak/geometry.h"
#include "soak/image.h"
#include "soak/preset.h"
#include "soak/scene.h"
#include "soak/volume.h"
#include "soak/volume_check.h"

typedef enum kind { MESH, IMAGE, SCENE, PRESETS, GRID_HEADER, GRID_RAW, DF3, VDB } kind;

typedef struct source {
    const char *label;
    kind kind;
    char path[1024]; /* the whole file */
    int may_read;    /* a cut can leave a valid file of this format */
} source;

static char tmp[256];
static int failures, cases, read_ok;

static unsigned char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t cap = 1 << 16;
    unsigned char *b = malloc(cap);
    *n = 0;
    size_t got;
    while (b && (got = fread(b + *n, 1, cap - *n, f)) > 0) {
        *n += got;
        if (*n == cap) {
            unsigned char *c = realloc(b, cap *= 2);
            if (!c) free(b);
            b = c;
        }
    }
    fclose(f);
    return b;
}

static int spill(const char *path, const unsigned char *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f) return 0;
    int ok = (n == 0 || fwrite(data, 1, n, f) == n);
    return fclose(f) == 0 && ok;
}

/* A corpus seed without its first (format-selecting) byte. */
static int seed(source *s, const char *root, const char *corpus, const char *name, const char *ext)
{
    char from[1024];
    snprintf(from, sizeof from, "%s/tests/fuzz/corpus/%s/%s", root, corpus, name);
    size_t n;
    unsigned char *b = slurp(from, &n);
    snprintf(s->path, sizeof s->path, "%s/src_%s.%s", tmp, name, ext);
    int ok = b && n > 1 && spill(s->path, b + 1, n - 1);
    free(b);
    return ok;
}

static void check_message(const source *s, int k, const char *file, const char *other, soak_status st,
                          const char *err)
{
    ++cases;
    if (st == SOAK_OK) {
        ++read_ok;
        if (!s->may_read) {
            ++failures;
            printf("FAIL %s cut at %d/10: accepted\n", s->label, k);
        }
        return;
    }
    const char *why = NULL;
    if (!err[0]) why = "empty message";
    for (const unsigned char *c = (const unsigned char *)err; !why && *c; ++c)
        if ((*c < 0x20 && *c != '\n' && *c != '\t') || *c == 0x7f) why = "control bytes in the message";
    if (!why && !strstr(err, file) && !(other && strstr(err, other))) why = "message does not name the file";
    if (!why && strstr(err, "did not finish within")) why = "refused by the time limit, not a check";
    if (why) {
        ++failures;
        printf("FAIL %s cut at %d/10: %s: %s\n", s->label, k, why, err);
    } else {
        printf("ok   %s cut at %d/10: %.160s\n", s->label, k, err);
    }
}

/* Reads the cut file with the format's reader. */
static soak_status read_cut(const source *s, const char *cut, char *err, size_t errlen)
{
    switch (s->kind) {
    case MESH: {
        soak_mesh m = {0};
        soak_status st = soak_mesh_load(cut, 0, &m, err, errlen);
        if (st == SOAK_OK) soak_mesh_free(&m);
        return st;
    }
    case IMAGE: {
        soak_image img;
        soak_status st = soak_image_read(cut, &img, err, errlen);
        if (st == SOAK_OK) soak_image_free(&img);
        return st;
    }
    case SCENE: {
        soak_scene sc;
        soak_status st = soak_scene_load(cut, &sc, err, errlen);
        if (st == SOAK_OK) soak_scene_free(&sc);
        return st;
    }
    case PRESETS: {
        soak_preset_db *db = NULL;
        soak_status st = soak_presets_load(cut, &db, err, errlen);
        if (st == SOAK_OK) soak_presets_free(db);
        return st;
    }
    case GRID_HEADER:
    case GRID_RAW: {
        soak_volume v;
        char json[1100];
        snprintf(json, sizeof json, "%s/vol.json", tmp);
        soak_status st = soak_volume_read_grid(json, &v, err, errlen);
        if (st == SOAK_OK) soak_volume_free(&v);
        return st;
    }
    case DF3: {
        soak_df3 d;
        soak_status st = soak_df3_read(cut, &d, err, errlen);
        if (st == SOAK_OK) soak_df3_free(&d);
        return st;
    }
    case VDB: {
        float values[8];
        double vs[3], o[3];
        return soak_volume_read_vdb_grid(cut, "density", 2, 2, 2, values, vs, o, err, errlen);
    }
    }
    return SOAK_ERR_ARG;
}

static void sweep(const source *s)
{
    size_t n;
    unsigned char *whole = slurp(s->path, &n);
    if (!whole) {
        ++failures;
        printf("FAIL %s: cannot read the source %s\n", s->label, s->path);
        return;
    }
    const char *ext = strrchr(s->path, '.');
    for (int k = 0; k < 10; ++k) {
        char cut[1100];
        /* The grid's two files keep their names: the header names the payload. */
        if (s->kind == GRID_HEADER) snprintf(cut, sizeof cut, "%s/vol.json", tmp);
        else if (s->kind == GRID_RAW) snprintf(cut, sizeof cut, "%s/vol.raw", tmp);
        else snprintf(cut, sizeof cut, "%s/cut_%d%s", tmp, k, ext ? ext : "");
        size_t len = n * (size_t)k / 10;
        char err[4352] = "";
        if (!spill(cut, whole, len)) {
            ++failures;
            printf("FAIL %s: cannot write %s\n", s->label, cut);
            continue;
        }
        soak_status st = read_cut(s, cut, err, sizeof err);
        char json[1100];
        snprintf(json, sizeof json, "%s/vol.json", tmp);
        check_message(s, k, cut, s->kind == GRID_RAW ? json : NULL, st, err);
        if (s->kind != GRID_HEADER && s->kind != GRID_RAW) unlink(cut);
        else spill(cut, whole, n); /* restore for the other file's sweep */
    }
    free(whole);
}

/* A small volume written by Soak's own writers: grid, df3 and (when built
 * with OpenVDB) vdb sources. */
static int volume_sources(source *v, int *count)
{
    soak_volume vol;
    double size[3] = {1, 1, 0.5};
    if (soak_volume_alloc(&vol, 3, 3, 2, size) != SOAK_OK) return 0;
    for (size_t i = 0; i < soak_volume_count(&vol) * SOAK_VOL_NCHANNELS; ++i) vol.data[i] = (float)(i % 7) * 0.25f;
    char prefix[512], err[4352];
    int ok = 1;
    snprintf(prefix, sizeof prefix, "%s/vol", tmp);
    ok &= soak_volume_write_grid(&vol, prefix, NULL, 0, 0.01, err, sizeof err) == SOAK_OK;
    v[*count] = (source){"grid header", GRID_HEADER, "", 0};
    snprintf(v[(*count)++].path, sizeof v->path, "%s/vol.json", tmp);
    v[*count] = (source){"grid payload", GRID_RAW, "", 0};
    snprintf(v[(*count)++].path, sizeof v->path, "%s/vol.raw", tmp);
    snprintf(prefix, sizeof prefix, "%s/d", tmp);
    ok &= soak_volume_write_df3(&vol, prefix, 16, err, sizeof err) == SOAK_OK;
    v[*count] = (source){"df3", DF3, "", 0};
    snprintf(v[(*count)++].path, sizeof v->path, "%s/d_wetness.df3", tmp);
    if (soak_volume_have_vdb()) {
        snprintf(prefix, sizeof prefix, "%s/src.vdb", tmp);
        ok &= soak_volume_write_vdb(&vol, prefix, err, sizeof err) == SOAK_OK;
        v[*count] = (source){"OpenVDB", VDB, "", 0};
        snprintf(v[(*count)++].path, sizeof v->path, "%s", prefix);
    } else {
        printf("SKIPPED: this build has no OpenVDB (OpenVDB sweep)\n");
    }
    soak_volume_free(&vol);
    if (!ok) printf("FAIL writing the volume sources: %s\n", err);
    return ok;
}

/* Binary PLY and STL triangles (the corpus holds the ASCII ones). */
static int binary_meshes(source *s, int *count)
{
    static const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    static const char head[] = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                               "property float y\nproperty float z\nelement face 1\n"
                               "property list uchar int vertex_indices\nend_header\n";
    unsigned char buf[256];
    size_t n = strlen(head);
    memcpy(buf, head, n);
    memcpy(buf + n, tri, sizeof tri);
    n += sizeof tri;
    buf[n++] = 3;
    for (int i = 0; i < 3; ++i, n += 4) memcpy(buf + n, &i, 4);
    s[*count] = (source){"binary PLY", MESH, "", 0};
    snprintf(s[*count].path, sizeof s->path, "%s/bin.ply", tmp);
    int ok = spill(s[(*count)++].path, buf, n);
    memset(buf, 0, 84);
    unsigned one = 1;
    memcpy(buf + 80, &one, 4);
    float normal[3] = {0, 0, 1};
    memcpy(buf + 84, normal, 12);
    memcpy(buf + 96, tri, sizeof tri);
    buf[132] = buf[133] = 0;
    s[*count] = (source){"binary STL", MESH, "", 0};
    snprintf(s[*count].path, sizeof s->path, "%s/bin.stl", tmp);
    return ok && spill(s[(*count)++].path, buf, 134);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: sweep_malformed SOURCE_DIR\n");
        return 2;
    }
    const char *root = argv[1];
    snprintf(tmp, sizeof tmp, "%s/soak_sweep.XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    if (!mkdtemp(tmp)) return 1;
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);

    source src[40];
    int n = 0, ok = 1;
    static const struct { const char *name, *ext, *label; int may_read; } mesh_seeds[] = {
        {"obj_quad", "obj", "OBJ", 1},        {"ply_ascii", "ply", "ASCII PLY", 1}, {"stl_ascii", "stl", "ASCII STL", 1},
        {"off_tri", "off", "OFF", 1},         {"gltf_tri", "gltf", "glTF", 0},      {"glb_tri", "glb", "GLB", 0}};
    for (size_t i = 0; i < sizeof mesh_seeds / sizeof mesh_seeds[0]; ++i) {
        src[n] = (source){mesh_seeds[i].label, MESH, "", mesh_seeds[i].may_read};
        ok &= seed(&src[n++], root, "mesh", mesh_seeds[i].name, mesh_seeds[i].ext);
    }
    ok &= binary_meshes(src, &n);
    static const char *const images[] = {"png", "exr", "tif", "hdr", "jpg", "ppm"};
    for (size_t i = 0; i < 6; ++i) {
        src[n] = (source){images[i], IMAGE, "", 0};
        ok &= seed(&src[n++], root, "image", images[i], images[i]);
    }
    src[n] = (source){"scene JSON", SCENE, "", 0};
    snprintf(src[n++].path, sizeof src->path, "%s/scenes/sand.json", root);
    src[n] = (source){"materials JSON", PRESETS, "", 0};
    snprintf(src[n++].path, sizeof src->path, "%s/c_core/data/materials.json", root);
    ok &= volume_sources(src, &n);
    if (!ok) {
        printf("FAIL could not prepare every source\n");
        ++failures;
    }
    for (int i = 0; i < n; ++i) sweep(&src[i]);

    clock_gettime(CLOCK_MONOTONIC, &t1);
    printf("%d formats, %d cases (%d read as valid prefixes), %d failures, %.1f s wall\n", n, cases, read_ok, failures,
           (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    if (system(cmd) != 0) printf("note: could not remove %s\n", tmp);
    return failures || cases == 0 ? 1 : 0;
}
