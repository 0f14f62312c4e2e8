/* POV-Ray df3 writer for parameter volumes (layout in soak/bake_volume.h).
 * df3 format (POV-Ray 3.7 reference, density_file): 3 big-endian uint16
 * dims (nx, ny, nz), then nx*ny*nz big-endian unsigned values of 1, 2 or 4
 * bytes, x fastest; POV-Ray reads value / (2^bits - 1). */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "soak/volume.h"
#include "soak/staged_files.h"

typedef struct channel_range {
    double offset, scale; /* real = offset + scale * stored, stored in [0,1] */
} channel_range;

static channel_range range_of(const float *plane, size_t n)
{
    double lo = plane[0], hi = plane[0];
    for (size_t i = 1; i < n; ++i) {
        if (plane[i] < lo) lo = plane[i];
        if (plane[i] > hi) hi = plane[i];
    }
    /* Non-negative channels keep offset 0 so that POV-Ray can use the stored
     * value directly as a density multiplier of a coefficient = scale. */
    channel_range r;
    r.offset = lo < 0.0 ? lo : 0.0;
    r.scale = hi - r.offset;
    return r;
}

static int clampi(int x, int lo, int hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

static soak_status write_df3_file(FILE *f, const soak_volume *v, const float *plane, channel_range r, int bits)
{
    int m[3] = {v->nx + 2, v->ny + 2, v->nz + 2};
    for (int a = 0; a < 3; ++a) {
        unsigned char hdr[2] = {(unsigned char)(m[a] >> 8), (unsigned char)(m[a] & 0xff)};
        fwrite(hdr, 1, 2, f);
    }
    int bytes = bits / 8;
    double maxraw = bits == 32 ? 4294967295.0 : (double)((1u << bits) - 1u);
    unsigned char *row = malloc((size_t)m[0] * (size_t)bytes);
    if (!row) return SOAK_ERR_NOMEM;
    for (int k = 0; k < m[2]; ++k)
        for (int j = 0; j < m[1]; ++j) {
            /* Stored voxel (i,j,k) = our voxel (i-1, j-1, k-1), edges replicated. */
            int sj = clampi(j - 1, 0, v->ny - 1), sk = clampi(k - 1, 0, v->nz - 1);
            for (int i = 0; i < m[0]; ++i) {
                int si = clampi(i - 1, 0, v->nx - 1);
                double val = plane[soak_volume_index(v, si, sj, sk)];
                double q = r.scale > 0.0 ? (val - r.offset) / r.scale : 0.0;
                q = q < 0.0 ? 0.0 : (q > 1.0 ? 1.0 : q);
                uint32_t raw = (uint32_t)floor(q * maxraw + 0.5);
                for (int b = 0; b < bytes; ++b) row[(size_t)i * bytes + b] = (unsigned char)(raw >> (8 * (bytes - 1 - b)));
            }
            fwrite(row, (size_t)bytes, (size_t)m[0], f);
        }
    free(row);
    return SOAK_OK;
}

static const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

/* POV-Ray identifier from the prefix's base name: letters, digits, '_',
 * leading letter. */
static void pov_ident(const char *prefix, char *out, size_t len)
{
    const char *b = base_name(prefix);
    size_t o = 0;
    if (!((b[0] >= 'a' && b[0] <= 'z') || (b[0] >= 'A' && b[0] <= 'Z')) && o + 1 < len) out[o++] = 'V';
    for (; *b && o + 1 < len; ++b) {
        char c = *b;
        int ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        out[o++] = ok ? c : '_';
    }
    out[o] = '\0';
}

static soak_status write_text(soak_staged *st, const char *path, const char *text, char *err, size_t errlen)
{
    FILE *f = NULL;
    soak_status s = soak_staged_open(st, path, &f, err, errlen);
    if (s != SOAK_OK) return s;
    fputs(text, f);
    return soak_staged_close(f, path, err, errlen);
}

static char *sidecar_json(const soak_volume *v, const char *prefix, int bits, const channel_range *r)
{
    int n[3] = {v->nx, v->ny, v->nz};
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "format", "soak-volume-df3");
    cJSON_AddNumberToObject(root, "version", 1);
    cJSON_AddItemToObject(root, "dims", cJSON_CreateIntArray(n, 3));
    int m[3] = {n[0] + 2, n[1] + 2, n[2] + 2};
    cJSON_AddItemToObject(root, "stored_dims", cJSON_CreateIntArray(m, 3));
    cJSON_AddNumberToObject(root, "border", 1);
    cJSON_AddItemToObject(root, "size", cJSON_CreateDoubleArray(v->size, 3));
    cJSON_AddNumberToObject(root, "bits", bits);
    cJSON_AddStringToObject(root, "value", "real = offset + scale * raw / (2^bits - 1)");
    double sc[3], tr1[3], tr0[3];
    for (int a = 0; a < 3; ++a) {
        sc[a] = (double)m[a] / n[a];
        tr1[a] = -0.5 / n[a];
        tr0[a] = -1.0 / n[a];
    }
    cJSON *t1 = cJSON_AddObjectToObject(root, "pov_transform_interpolate1");
    cJSON_AddItemToObject(t1, "scale", cJSON_CreateDoubleArray(sc, 3));
    cJSON_AddItemToObject(t1, "translate", cJSON_CreateDoubleArray(tr1, 3));
    cJSON *t0 = cJSON_AddObjectToObject(root, "pov_transform_interpolate0");
    cJSON_AddItemToObject(t0, "scale", cJSON_CreateDoubleArray(sc, 3));
    cJSON_AddItemToObject(t0, "translate", cJSON_CreateDoubleArray(tr0, 3));
    cJSON *ch = cJSON_AddObjectToObject(root, "channels");
    char file[4096];
    for (int c = 0; c < SOAK_VOL_NCHANNELS; ++c) {
        cJSON *o = cJSON_AddObjectToObject(ch, soak_volume_channel_name(c));
        snprintf(file, sizeof file, "%s_%s.df3", base_name(prefix), soak_volume_channel_name(c));
        cJSON_AddStringToObject(o, "file", file);
        cJSON_AddNumberToObject(o, "offset", r[c].offset);
        cJSON_AddNumberToObject(o, "scale", r[c].scale);
    }
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    return text;
}

/* Appends to a growing string; returns 0 on allocation failure. */
typedef struct strbuf {
    char *s;
    size_t len, cap;
} strbuf;

static int sb_printf(strbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static int sb_printf(strbuf *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int need = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (need < 0) return 0;
    if (b->len + (size_t)need + 1 > b->cap) {
        size_t cap = (b->cap ? 2 * b->cap : 1024) + (size_t)need;
        char *s = realloc(b->s, cap);
        if (!s) return 0;
        b->s = s;
        b->cap = cap;
    }
    va_start(ap, fmt);
    vsnprintf(b->s + b->len, b->cap - b->len, fmt, ap);
    va_end(ap);
    b->len += (size_t)need;
    return 1;
}

static char *pov_include(const soak_volume *v, const char *prefix, const channel_range *r)
{
    char id[256];
    pov_ident(prefix, id, sizeof id);
    int n[3] = {v->nx, v->ny, v->nz};
    strbuf b = {0};
    int ok = sb_printf(&b,
                       "// Soak parameter volume '%s' (soak bake volume). Values per voxel:\n"
                       "//   real = <name>_offset + <name>_scale * density value of <name>_file\n"
                       "// Densities cover the unit box; use the macro %s_density(File) inside media\n"
                       "// of a container box { 0, 1 } (interpolate 1 with the half-voxel transform,\n"
                       "// see soak/bake_volume.h) scaled by %s_size. Coefficients are per world unit.\n"
                       "// File names resolve against POV-Ray's current folder and +L paths.\n",
                       id, id, id);
    ok = ok && sb_printf(&b, "#declare %s_dims = <%d, %d, %d>;\n", id, n[0], n[1], n[2]);
    ok = ok && sb_printf(&b, "#declare %s_size = <%.17g, %.17g, %.17g>;\n", id, v->size[0], v->size[1], v->size[2]);
    for (int c = 0; c < SOAK_VOL_NCHANNELS && ok; ++c) {
        const char *cn = soak_volume_channel_name(c);
        ok = sb_printf(&b, "#declare %s_%s_file = \"%s_%s.df3\";\n", id, cn, base_name(prefix), cn) &&
             sb_printf(&b, "#declare %s_%s_offset = %.17g;\n", id, cn, r[c].offset) &&
             sb_printf(&b, "#declare %s_%s_scale = %.17g;\n", id, cn, r[c].scale);
    }
    ok = ok && sb_printf(&b,
                         "#macro %s_density(File)\n"
                         "  density { density_file df3 File interpolate 1\n"
                         "    scale <%.12g, %.12g, %.12g> translate <%.12g, %.12g, %.12g> }\n"
                         "#end\n",
                         id, (n[0] + 2.0) / n[0], (n[1] + 2.0) / n[1], (n[2] + 2.0) / n[2], -0.5 / n[0], -0.5 / n[1],
                         -0.5 / n[2]);
    if (!ok) {
        free(b.s);
        return NULL;
    }
    return b.s;
}

soak_status soak_volume_stage_df3(soak_staged *stage, const soak_volume *v, const char *prefix, int bits, char *err,
                                  size_t errlen)
{
    if (!v || !v->data || !prefix) return SOAK_ERR_NULL;
    if (bits != 8 && bits != 16 && bits != 32) return SOAK_ERR_ARG;
    if (v->nx + 2 > 65535 || v->ny + 2 > 65535 || v->nz + 2 > 65535) return SOAK_ERR_ARG;
    size_t n = soak_volume_count(v);
    channel_range r[SOAK_VOL_NCHANNELS];
    for (int c = 0; c < SOAK_VOL_NCHANNELS; ++c) r[c] = range_of(soak_volume_plane(v, c), n);

    soak_status st = SOAK_OK;
    char path[4096];
    for (int c = 0; c < SOAK_VOL_NCHANNELS && st == SOAK_OK; ++c) {
        snprintf(path, sizeof path, "%s_%s.df3", prefix, soak_volume_channel_name(c));
        FILE *f = NULL;
        st = soak_staged_open(stage, path, &f, err, errlen);
        if (st != SOAK_OK) break;
        st = write_df3_file(f, v, soak_volume_plane(v, c), r[c], bits);
        soak_status cs = soak_staged_close(f, path, err, errlen);
        if (st == SOAK_OK) st = cs;
    }
    char *json = st == SOAK_OK ? sidecar_json(v, prefix, bits, r) : NULL;
    char *inc = st == SOAK_OK ? pov_include(v, prefix, r) : NULL;
    if (st == SOAK_OK && (!json || !inc)) st = SOAK_ERR_NOMEM;
    if (st == SOAK_OK) {
        snprintf(path, sizeof path, "%s_df3.json", prefix);
        st = write_text(stage, path, json, err, errlen);
    }
    if (st == SOAK_OK) {
        snprintf(path, sizeof path, "%s.inc", prefix);
        st = write_text(stage, path, inc, err, errlen);
    }
    cJSON_free(json);
    free(inc);
    return st;
}

soak_status soak_volume_write_df3(const soak_volume *v, const char *prefix, int bits, char *err, size_t errlen)
{
    soak_staged stage;
    soak_staged_init(&stage);
    soak_status st = soak_volume_stage_df3(&stage, v, prefix, bits, err, errlen);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return st;
    }
    return soak_staged_commit(&stage, err, errlen);
}
