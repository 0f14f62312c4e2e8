/* Per-vertex wetness as glTF 2.0 (.gltf with a base64 buffer, or .glb): the
 * mesh with COLOR_0 = (w, w, w, 1) and the application-specific attribute
 * _WETNESS = w (soak/bake_vertex.h). Structure as the glTF 2.0
 * specification (Khronos, 2021) requires: little-endian binary data, every
 * bufferView offset and length a multiple of 4, POSITION with min/max,
 * COLOR_0 linear FLOAT VEC4, NORMAL unit length, GLB chunks padded to 4
 * (JSON with spaces, BIN with zeros). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "soak/bake_vertex.h"
#include "soak/staged.h"

/* glTF 2.0 enumerations (specification, 5.1.3, 5.11.3, 5.24.3). */
#define GLTF_FLOAT 5126
#define GLTF_UNSIGNED_INT 5125
#define GLTF_ARRAY_BUFFER 34962
#define GLTF_ELEMENT_ARRAY_BUFFER 34963
#define GLTF_TRIANGLES 4
/* GLB header and chunk types (specification, 4.4). */
#define GLB_MAGIC 0x46546C67u
#define GLB_JSON 0x4E4F534Au
#define GLB_BIN 0x004E4942u

enum { V_POS, V_NRM, V_COL, V_WET, V_IDX, V_COUNT };

/* The binary buffer: one bufferView per attribute and the indices. */
typedef struct gltf_bin {
    unsigned char *data;
    size_t len, offset[V_COUNT], size[V_COUNT];
    int has_normals;
    float lo[3], hi[3]; /* POSITION min/max, of the stored floats */
} gltf_bin;

static void put_u32(unsigned char *p, uint32_t v)
{
    for (int k = 0; k < 4; ++k) p[k] = (unsigned char)(v >> (8 * k));
}

static void put_f32(unsigned char *p, float f)
{
    uint32_t v;
    memcpy(&v, &f, sizeof v);
    put_u32(p, v);
}

static soak_status fail(char *err, size_t errlen, soak_status st, const char *msg)
{
    if (err && errlen) snprintf(err, errlen, "%s", msg);
    return st;
}

/* 1 when every normal is finite and not zero (they are then written unit). */
static int normals_usable(const soak_mesh *m)
{
    if (!m->normals) return 0;
    for (size_t i = 0; i < m->n_vertices; ++i) {
        const double *n = m->normals + 3 * i;
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(soak_is_finite(len) && len > 1e-12)) return 0;
    }
    return 1;
}

static void layout(gltf_bin *b, const soak_mesh *m)
{
    size_t nv = m->n_vertices;
    b->size[V_POS] = 12 * nv;
    b->size[V_NRM] = b->has_normals ? 12 * nv : 0;
    b->size[V_COL] = 16 * nv;
    b->size[V_WET] = 4 * nv;
    b->size[V_IDX] = 12 * m->n_triangles;
    b->len = 0;
    for (int k = 0; k < V_COUNT; ++k) b->offset[k] = b->len, b->len += b->size[k]; /* all multiples of 4 */
}

static soak_status fill_vertices(gltf_bin *b, const soak_mesh *m, const float *values)
{
    for (int c = 0; c < 3; ++c) b->lo[c] = FLT_MAX, b->hi[c] = -FLT_MAX;
    for (size_t i = 0; i < m->n_vertices; ++i) {
        const double *p = m->positions + 3 * i;
        for (int c = 0; c < 3; ++c) {
            float f = (float)p[c];
            if (!isfinite(f)) return SOAK_ERR_NUMERIC;
            put_f32(b->data + b->offset[V_POS] + 12 * i + 4 * c, f);
            b->lo[c] = fminf(b->lo[c], f), b->hi[c] = fmaxf(b->hi[c], f);
        }
        if (b->has_normals) {
            const double *n = m->normals + 3 * i;
            double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (int c = 0; c < 3; ++c) put_f32(b->data + b->offset[V_NRM] + 12 * i + 4 * c, (float)(n[c] / len));
        }
        for (int c = 0; c < 4; ++c) put_f32(b->data + b->offset[V_COL] + 16 * i + 4 * c, c < 3 ? values[i] : 1.0f);
        put_f32(b->data + b->offset[V_WET] + 4 * i, values[i]);
    }
    for (size_t j = 0; j < 3 * m->n_triangles; ++j) put_u32(b->data + b->offset[V_IDX] + 4 * j, m->indices[j]);
    return SOAK_OK;
}

static soak_status build_bin(gltf_bin *b, const soak_mesh *m, const float *values, char *err, size_t errlen)
{
    memset(b, 0, sizeof *b);
    if (m->n_vertices > UINT32_MAX / 64 || m->n_triangles > UINT32_MAX / 16)
        return fail(err, errlen, SOAK_ERR_ARG, "mesh too large for a glTF buffer (4 GiB)");
    b->has_normals = normals_usable(m);
    layout(b, m);
    b->data = malloc(b->len);
    if (!b->data) return fail(err, errlen, SOAK_ERR_NOMEM, "out of memory for the glTF buffer");
    if (fill_vertices(b, m, values) != SOAK_OK) {
        free(b->data);
        b->data = NULL;
        return fail(err, errlen, SOAK_ERR_NUMERIC, "a vertex position is not finite as a 32-bit float");
    }
    return SOAK_OK;
}

/* Appends bufferView k and its accessor; returns the accessor's index. */
static int add_view(cJSON *views, cJSON *accessors, const gltf_bin *b, int k, size_t count, const char *type,
                    int component)
{
    cJSON *v = cJSON_CreateObject(), *a = cJSON_CreateObject();
    cJSON_AddItemToArray(views, v);
    cJSON_AddItemToArray(accessors, a);
    cJSON_AddNumberToObject(v, "buffer", 0);
    cJSON_AddNumberToObject(v, "byteOffset", (double)b->offset[k]);
    cJSON_AddNumberToObject(v, "byteLength", (double)b->size[k]);
    cJSON_AddNumberToObject(v, "target", k == V_IDX ? GLTF_ELEMENT_ARRAY_BUFFER : GLTF_ARRAY_BUFFER);
    cJSON_AddNumberToObject(a, "bufferView", cJSON_GetArraySize(views) - 1);
    cJSON_AddNumberToObject(a, "componentType", component);
    cJSON_AddNumberToObject(a, "count", (double)count);
    cJSON_AddStringToObject(a, "type", type);
    if (k == V_POS) {
        double lo[3] = {b->lo[0], b->lo[1], b->lo[2]}, hi[3] = {b->hi[0], b->hi[1], b->hi[2]};
        cJSON_AddItemToObject(a, "min", cJSON_CreateDoubleArray(lo, 3));
        cJSON_AddItemToObject(a, "max", cJSON_CreateDoubleArray(hi, 3));
    }
    return cJSON_GetArraySize(accessors) - 1;
}

static void add_primitive(cJSON *root, const gltf_bin *b, const soak_mesh *m)
{
    cJSON *views = cJSON_AddArrayToObject(root, "bufferViews");
    cJSON *accessors = cJSON_AddArrayToObject(root, "accessors");
    cJSON *prim = cJSON_CreateObject(), *attrs = cJSON_AddObjectToObject(prim, "attributes");
    size_t nv = m->n_vertices;
    cJSON_AddNumberToObject(attrs, "POSITION", add_view(views, accessors, b, V_POS, nv, "VEC3", GLTF_FLOAT));
    if (b->has_normals)
        cJSON_AddNumberToObject(attrs, "NORMAL", add_view(views, accessors, b, V_NRM, nv, "VEC3", GLTF_FLOAT));
    cJSON_AddNumberToObject(attrs, "COLOR_0", add_view(views, accessors, b, V_COL, nv, "VEC4", GLTF_FLOAT));
    cJSON_AddNumberToObject(attrs, "_WETNESS", add_view(views, accessors, b, V_WET, nv, "SCALAR", GLTF_FLOAT));
    cJSON_AddNumberToObject(prim, "indices",
                            add_view(views, accessors, b, V_IDX, 3 * m->n_triangles, "SCALAR", GLTF_UNSIGNED_INT));
    cJSON_AddNumberToObject(prim, "mode", GLTF_TRIANGLES);
    cJSON *mesh = cJSON_CreateObject();
    cJSON_AddStringToObject(mesh, "name", "soak_wetness");
    cJSON_AddItemToArray(cJSON_AddArrayToObject(mesh, "primitives"), prim);
    cJSON_AddItemToArray(cJSON_AddArrayToObject(root, "meshes"), mesh);
}

/* The glTF JSON; uri NULL for a GLB's own binary chunk. */
static cJSON *build_json(const gltf_bin *b, const soak_mesh *m, const char *uri)
{
    cJSON *root = cJSON_CreateObject();
    cJSON *asset = cJSON_AddObjectToObject(root, "asset");
    cJSON_AddStringToObject(asset, "version", "2.0");
    cJSON_AddStringToObject(asset, "generator", "soak bake rain --per-vertex");
    cJSON *extras = cJSON_AddObjectToObject(asset, "extras");
    cJSON_AddStringToObject(extras, "soak", "COLOR_0 = (w, w, w, 1), linear; _WETNESS = w: rain wetness in [0, 1]");
    cJSON_AddNumberToObject(root, "scene", 0);
    cJSON *node = cJSON_CreateObject();
    cJSON_AddStringToObject(node, "name", "soak_wetness");
    cJSON_AddNumberToObject(node, "mesh", 0);
    cJSON_AddItemToArray(cJSON_AddArrayToObject(root, "nodes"), node);
    cJSON *scene = cJSON_CreateObject();
    cJSON_AddItemToArray(cJSON_AddArrayToObject(scene, "nodes"), cJSON_CreateNumber(0));
    cJSON_AddItemToArray(cJSON_AddArrayToObject(root, "scenes"), scene);
    add_primitive(root, b, m);
    cJSON *buffer = cJSON_CreateObject();
    cJSON_AddNumberToObject(buffer, "byteLength", (double)b->len);
    if (uri) cJSON_AddStringToObject(buffer, "uri", uri);
    cJSON_AddItemToArray(cJSON_AddArrayToObject(root, "buffers"), buffer);
    return root;
}

/* RFC 4648 base64 of data, as a data URI; NULL when out of memory. */
static char *data_uri(const unsigned char *data, size_t len)
{
    static const char prefix[] = "data:application/octet-stream;base64,";
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t n = sizeof prefix - 1 + 4 * ((len + 2) / 3) + 1;
    char *out = malloc(n), *o = out + sizeof prefix - 1;
    if (!out) return NULL;
    memcpy(out, prefix, sizeof prefix - 1);
    for (size_t i = 0; i < len; i += 3) {
        uint32_t v =
            (uint32_t)data[i] << 16 | (i + 1 < len ? (uint32_t)data[i + 1] << 8 : 0) | (i + 2 < len ? data[i + 2] : 0);
        *o++ = digits[v >> 18 & 63], *o++ = digits[v >> 12 & 63];
        *o++ = i + 1 < len ? digits[v >> 6 & 63] : '=';
        *o++ = i + 2 < len ? digits[v & 63] : '=';
    }
    *o = '\0';
    return out;
}

/* The GLB file: header, JSON chunk (space-padded), BIN chunk (zero-padded). */
static unsigned char *glb_bytes(const char *json, const gltf_bin *b, size_t *len)
{
    size_t jl = strlen(json), jpad = (4 - jl % 4) % 4, bpad = (4 - b->len % 4) % 4;
    *len = 12 + 8 + jl + jpad + 8 + b->len + bpad;
    if (*len > UINT32_MAX) return NULL;
    unsigned char *out = calloc(1, *len), *p = out;
    if (!out) return NULL;
    put_u32(p, GLB_MAGIC), put_u32(p + 4, 2), put_u32(p + 8, (uint32_t)*len), p += 12;
    put_u32(p, (uint32_t)(jl + jpad)), put_u32(p + 4, GLB_JSON), p += 8;
    memcpy(p, json, jl), memset(p + jl, ' ', jpad), p += jl + jpad;
    put_u32(p, (uint32_t)(b->len + bpad)), put_u32(p + 4, GLB_BIN), p += 8;
    memcpy(p, b->data, b->len);
    return out;
}

/* The file's bytes: a .glb, or the .gltf's JSON with the buffer inline. */
static soak_status file_bytes(const gltf_bin *b, const soak_mesh *m, int glb, unsigned char **out, size_t *len)
{
    char *uri = glb ? NULL : data_uri(b->data, b->len);
    if (!glb && !uri) return SOAK_ERR_NOMEM;
    cJSON *root = build_json(b, m, uri);
    free(uri);
    char *json = root ? cJSON_PrintUnformatted(root) : NULL;
    cJSON_Delete(root);
    if (!json) return SOAK_ERR_NOMEM;
    if (glb) {
        *out = glb_bytes(json, b, len);
        cJSON_free(json);
        return *out ? SOAK_OK : SOAK_ERR_NOMEM;
    }
    *len = strlen(json);
    *out = (unsigned char *)json;
    return SOAK_OK;
}

soak_status soak_vertex_write_gltf(const char *path, const soak_mesh *m, const float *values, int glb, char *err,
                                   size_t errlen)
{
    gltf_bin b;
    soak_status st = build_bin(&b, m, values, err, errlen);
    if (st != SOAK_OK) return st;
    unsigned char *bytes = NULL;
    size_t len = 0;
    st = file_bytes(&b, m, glb, &bytes, &len);
    free(b.data);
    if (st != SOAK_OK) {
        if (err && errlen) snprintf(err, errlen, "%s: out of memory for the glTF file (or over 4 GiB)", path);
        return st;
    }
    soak_staged stage;
    soak_staged_init(&stage);
    st = soak_staged_write(&stage, path, bytes, len, err, errlen);
    if (glb) free(bytes);
    else cJSON_free(bytes);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return st;
    }
    return soak_staged_commit(&stage, err, errlen);
}
