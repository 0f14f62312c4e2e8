/* Soak grid format (<prefix>.json + <prefix>.raw), specified in
 * soak/bake_volume.h next to soak_volume_write_grid. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cjson/cJSON.h>

#include "soak/volume.h"
#include "soak/input_file.h"
#include "soak/staged_files.h"

static void set_err(char *err, size_t errlen, const char *fmt, const char *a, const char *b)
{
    if (err && errlen) snprintf(err, errlen, fmt, a, b);
}

static const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

static cJSON *medium_json(const soak_vol_medium *m, double wetness)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "wetness", wetness);
    double s[3] = {m->sigma_s.r, m->sigma_s.g, m->sigma_s.b}, a[3] = {m->sigma_a.r, m->sigma_a.g, m->sigma_a.b};
    cJSON_AddItemToObject(o, "sigma_s", cJSON_CreateDoubleArray(s, 3));
    cJSON_AddItemToObject(o, "sigma_a", cJSON_CreateDoubleArray(a, 3));
    cJSON_AddNumberToObject(o, "g1", m->g1);
    cJSON_AddNumberToObject(o, "g2", m->g2);
    cJSON_AddNumberToObject(o, "w", m->w);
    return o;
}

static void put_le32(unsigned char *p, float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    for (int b = 0; b < 4; ++b) p[b] = (unsigned char)(u >> (8 * b));
}

static float get_le32(const unsigned char *p)
{
    uint32_t u = 0;
    for (int b = 0; b < 4; ++b) u |= (uint32_t)p[b] << (8 * b);
    float f;
    memcpy(&f, &u, 4);
    return f;
}

soak_status soak_volume_stage_grid(soak_staged *stage, const soak_volume *v, const char *prefix,
                                   const soak_vol_medium *rows, int n_rows, double penetration_depth, char *err,
                                   size_t errlen)
{
    if (!v || !v->data || !prefix) return SOAK_ERR_NULL;
    char json_path[4096], raw_path[4096];
    snprintf(json_path, sizeof json_path, "%s.json", prefix);
    snprintf(raw_path, sizeof raw_path, "%s.raw", prefix);

    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "format", "soak-volume-grid");
    cJSON_AddNumberToObject(root, "version", 1);
    int dims[3] = {v->nx, v->ny, v->nz};
    cJSON_AddItemToObject(root, "dims", cJSON_CreateIntArray(dims, 3));
    cJSON_AddItemToObject(root, "size", cJSON_CreateDoubleArray(v->size, 3));
    cJSON_AddBoolToObject(root, "cell_centered", 1);
    cJSON_AddStringToObject(root, "order", "x fastest, then y, then z");
    cJSON_AddStringToObject(root, "dtype", "float32le");
    cJSON_AddStringToObject(root, "data", base_name(raw_path));
    cJSON *ch = cJSON_AddArrayToObject(root, "channels");
    for (int c = 0; c < SOAK_VOL_NCHANNELS; ++c) cJSON_AddItemToArray(ch, cJSON_CreateString(soak_volume_channel_name(c)));
    cJSON_AddStringToObject(root, "units", "sigma per length unit of size");
    if (rows && n_rows >= 2) {
        cJSON *model = cJSON_AddObjectToObject(root, "model");
        cJSON *table = cJSON_AddArrayToObject(model, "wetness_table");
        for (int i = 0; i < n_rows; ++i) cJSON_AddItemToArray(table, medium_json(&rows[i], (double)i / (n_rows - 1)));
        cJSON_AddNumberToObject(model, "penetration_depth", penetration_depth);
        cJSON_AddStringToObject(model, "profile", "p(d) = 1 - S(d/delta), S(t) = 3t^2 - 2t^3, cell averaged");
    }
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text) return SOAK_ERR_NOMEM;

    FILE *f = NULL;
    soak_status st = soak_staged_open(stage, raw_path, &f, err, errlen);
    if (st == SOAK_OK) {
        size_t n = soak_volume_count(v) * SOAK_VOL_NCHANNELS;
        unsigned char buf[4096];
        for (size_t i = 0; i < n;) {
            size_t m = 0;
            for (; m < sizeof buf / 4 && i < n; ++m, ++i) put_le32(buf + 4 * m, v->data[i]);
            fwrite(buf, 4, m, f);
        }
        st = soak_staged_close(f, raw_path, err, errlen);
    }
    if (st == SOAK_OK) st = soak_staged_open(stage, json_path, &f, err, errlen);
    if (st == SOAK_OK) {
        fputs(text, f);
        fputc('\n', f);
        st = soak_staged_close(f, json_path, err, errlen);
    }
    cJSON_free(text);
    return st;
}

soak_status soak_volume_write_grid(const soak_volume *v, const char *prefix, const soak_vol_medium *rows, int n_rows,
                                   double penetration_depth, char *err, size_t errlen)
{
    soak_staged stage;
    soak_staged_init(&stage);
    soak_status st = soak_volume_stage_grid(&stage, v, prefix, rows, n_rows, penetration_depth, err, errlen);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return st;
    }
    return soak_staged_commit(&stage, err, errlen);
}

/* soak/input_file.h: a grid header is read like a scene file. */
static char *read_text(const char *path, char *err, size_t errlen)
{
    char *text = NULL;
    return soak_input_read(path, SOAK_INPUT_SCENE, &text, NULL, err, errlen) == SOAK_OK ? text : NULL;
}

static int json_int3(const cJSON *a, int lo, int hi, int out[3])
{
    if (!cJSON_IsArray(a) || cJSON_GetArraySize(a) != 3) return 0;
    for (int i = 0; i < 3; ++i) {
        const cJSON *x = cJSON_GetArrayItem(a, i);
        if (!cJSON_IsNumber(x) || !(x->valuedouble >= lo && x->valuedouble <= hi) ||
            x->valuedouble != (double)(int)x->valuedouble)
            return 0;
        out[i] = (int)x->valuedouble;
    }
    return 1;
}

static int json_pos3(const cJSON *a, double out[3])
{
    if (!cJSON_IsArray(a) || cJSON_GetArraySize(a) != 3) return 0;
    for (int i = 0; i < 3; ++i) {
        const cJSON *x = cJSON_GetArrayItem(a, i);
        if (!cJSON_IsNumber(x) || !(x->valuedouble > 0.0 && soak_is_finite(x->valuedouble))) return 0;
        out[i] = x->valuedouble;
    }
    return 1;
}

/* Raw path: the "data" name resolved against the header's folder. */
static void data_path(const char *json_path, const char *name, char *out, size_t len)
{
    const char *slash = strrchr(json_path, '/');
    int dirlen = slash ? (int)(slash - json_path + 1) : 0;
    snprintf(out, len, "%.*s%s", dirlen, json_path, name);
}

static soak_status parse_header(const cJSON *root, const char *path, int dims[3], double size[3], int map[], int *nch,
                                const char **data, char *err, size_t errlen)
{
    const cJSON *fmt = cJSON_GetObjectItemCaseSensitive(root, "format");
    const cJSON *ver = cJSON_GetObjectItemCaseSensitive(root, "version");
    const cJSON *dt = cJSON_GetObjectItemCaseSensitive(root, "dtype");
    const cJSON *ch = cJSON_GetObjectItemCaseSensitive(root, "channels");
    const cJSON *dn = cJSON_GetObjectItemCaseSensitive(root, "data");
    if (!cJSON_IsString(fmt) || strcmp(fmt->valuestring, "soak-volume-grid") != 0 || !cJSON_IsNumber(ver) ||
        ver->valuedouble != 1.0) {
        set_err(err, errlen, "%s: not a soak-volume-grid version 1 header%s", path, "");
        return SOAK_ERR_PARSE;
    }
    if (!json_int3(cJSON_GetObjectItemCaseSensitive(root, "dims"), 1, SOAK_VOLUME_MAX_DIM, dims) ||
        !json_pos3(cJSON_GetObjectItemCaseSensitive(root, "size"), size)) {
        set_err(err, errlen, "%s: bad %s", path, "\"dims\" or \"size\"");
        return SOAK_ERR_PARSE;
    }
    if (!cJSON_IsString(dt) || strcmp(dt->valuestring, "float32le") != 0 || !cJSON_IsString(dn) ||
        strchr(dn->valuestring, '/') || !cJSON_IsArray(ch)) {
        set_err(err, errlen, "%s: bad %s", path, "\"dtype\", \"data\" or \"channels\"");
        return SOAK_ERR_PARSE;
    }
    *nch = cJSON_GetArraySize(ch);
    if (*nch < 1 || *nch > 64) {
        set_err(err, errlen, "%s: bad %s", path, "\"channels\" count");
        return SOAK_ERR_PARSE;
    }
    for (int c = 0; c < SOAK_VOL_NCHANNELS; ++c) map[c] = -1;
    for (int k = 0; k < *nch; ++k) {
        const cJSON *s = cJSON_GetArrayItem(ch, k);
        if (!cJSON_IsString(s)) continue;
        for (int c = 0; c < SOAK_VOL_NCHANNELS; ++c)
            if (strcmp(s->valuestring, soak_volume_channel_name(c)) == 0) map[c] = k;
    }
    for (int c = 0; c < SOAK_VOL_NCHANNELS; ++c)
        if (map[c] < 0) {
            set_err(err, errlen, "%s: channel '%s' missing", path, soak_volume_channel_name(c));
            return SOAK_ERR_PARSE;
        }
    *data = dn->valuestring;
    return SOAK_OK;
}

/* What a grid header says, and where its payload is. */
typedef struct grid_header {
    int dims[3], map[SOAK_VOL_NCHANNELS], nch; /* map: file channel of each volume channel */
    double size[3];
    char raw[4096];
} grid_header;

static soak_status read_header(const char *json_path, grid_header *h, char *err, size_t errlen)
{
    char *text = read_text(json_path, err, errlen);
    if (!text) return SOAK_ERR_IO;
    cJSON *root = cJSON_Parse(text);
    free(text);
    if (!root) {
        set_err(err, errlen, "%s: malformed JSON%s", json_path, "");
        return SOAK_ERR_PARSE;
    }
    const char *name = NULL;
    h->nch = 0;
    soak_status st = parse_header(root, json_path, h->dims, h->size, h->map, &h->nch, &name, err, errlen);
    if (st == SOAK_OK) data_path(json_path, name, h->raw, sizeof h->raw);
    cJSON_Delete(root);
    return st;
}

/* Opens the payload (*f, to be closed by the caller) after checking it is a
 * regular file of exactly the header's size: memory is bounded by the file
 * on disk, before anything is allocated. */
static soak_status open_payload(const grid_header *h, const char *json_path, FILE **f, char *err, size_t errlen)
{
    const char *raw = h->raw;
    char role[1200];
    snprintf(role, sizeof role, "grid payload named by %s", json_path);
    long long total = 0;
    soak_status st = soak_input_check_part(raw, SOAK_INPUT_VOLUME, role, &total, err, errlen);
    if (st != SOAK_OK) return st;
    *f = fopen(raw, "rb");
    if (!*f) {
        /* The payload's name comes from the header: name both. */
        if (err && errlen)
            snprintf(err, errlen, "%s: cannot open the payload named by %s: %s", raw, json_path, strerror(errno));
        return SOAK_ERR_IO;
    }
    size_t n = (size_t)h->dims[0] * (size_t)h->dims[1] * (size_t)h->dims[2];
    long long want = (long long)n * h->nch * 4, have = fseek(*f, 0, SEEK_END) == 0 ? (long long)ftell(*f) : -1;
    if (have != want) {
        char msg[256];
        snprintf(msg, sizeof msg, "%lld bytes, but dims %dx%dx%d with %d channels of float32 need %lld", have,
                 h->dims[0], h->dims[1], h->dims[2], h->nch, want);
        if (err && errlen)
            snprintf(err, errlen, "%s: size does not match the header: %s (header %s)", raw, msg, json_path);
        return SOAK_ERR_PARSE;
    }
    return SOAK_OK;
}

static soak_status alloc_grid(const grid_header *h, const char *json_path, soak_volume *v, char *err, size_t errlen)
{
    soak_status st = soak_volume_alloc(v, h->dims[0], h->dims[1], h->dims[2], h->size);
    if (st != SOAK_OK)
        set_err(err, errlen, "%s: dims: %s", json_path,
                st == SOAK_ERR_NOMEM ? "out of memory for the grid" : "too many voxels (at most 2^31 / 10 in all)");
    return st;
}

/* Reads every channel the volume has from its place in the payload; values must be finite. */
static soak_status read_channels(FILE *f, const grid_header *h, soak_volume *v, char *err, size_t errlen)
{
    const char *raw = h->raw;
    size_t n = (size_t)h->dims[0] * (size_t)h->dims[1] * (size_t)h->dims[2];
    unsigned char *buf = malloc(n * 4);
    soak_status st = buf ? SOAK_OK : SOAK_ERR_NOMEM;
    if (!buf) set_err(err, errlen, "%s: out of memory reading %s", raw, "the grid");
    for (int c = 0; c < SOAK_VOL_NCHANNELS && st == SOAK_OK; ++c) {
        if (fseek(f, (long)((size_t)h->map[c] * n * 4), SEEK_SET) != 0 || fread(buf, 4, n, f) != n) {
            set_err(err, errlen, "%s: read failed%s", raw, "");
            st = SOAK_ERR_IO;
            break;
        }
        float *plane = soak_volume_plane(v, c);
        for (size_t i = 0; i < n; ++i) {
            float x = get_le32(buf + 4 * i);
            if (!soak_is_finite(x)) {
                set_err(err, errlen, "%s: non-finite value in channel %s", raw, soak_volume_channel_name(c));
                st = SOAK_ERR_PARSE;
                break;
            }
            plane[i] = x;
        }
    }
    free(buf);
    return st;
}

static soak_status read_grid(const char *json_path, soak_volume *v, char *err, size_t errlen)
{
    if (!json_path || !v) return SOAK_ERR_NULL;
    memset(v, 0, sizeof *v);
    grid_header h;
    soak_status st = read_header(json_path, &h, err, errlen);
    if (st != SOAK_OK) return st;
    FILE *f = NULL;
    size_t voxels = (size_t)h.dims[0] * (size_t)h.dims[1] * (size_t)h.dims[2];
    if (voxels > ((size_t)1 << 31) / SOAK_VOL_NCHANNELS) /* soak_volume_alloc's limit, before the payload is opened */
        return alloc_grid(&h, json_path, v, err, errlen);
    st = open_payload(&h, json_path, &f, err, errlen);
    if (st == SOAK_OK) st = alloc_grid(&h, json_path, v, err, errlen);
    if (st == SOAK_OK) st = read_channels(f, &h, v, err, errlen);
    if (f) fclose(f);
    if (st != SOAK_OK) soak_volume_free(v);
    return st;
}

soak_status soak_volume_read_grid(const char *json_path, soak_volume *v, char *err, size_t errlen)
{
    soak_status st = read_grid(json_path, v, err, errlen);
    /* Names and values echoed from the header may hold any byte. */
    if (st != SOAK_OK && err && errlen) soak_message_printable(err);
    return st;
}
