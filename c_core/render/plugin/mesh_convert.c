/* See mesh_convert.h. UTF-16 (Unicode 15, sec. 3.10: a byte-order mark
 * FE FF is big-endian, FF FE little-endian; surrogate pairs D800-DBFF then
 * DC00-DFFF) to UTF-8 (RFC 3629). glTF 1.0 binary (Khronos
 * KHR_binary_glTF: a 20-byte header "glTF", version 1, length, content
 * length, content format 0; the JSON scene; then the body, the buffer
 * "binary_glTF") to a glTF 1.0 JSON whose one buffer is a base64 data URI
 * (RFC 4648) of the body; images, shaders and techniques, which a bake
 * does not read, are dropped. */
#define _POSIX_C_SOURCE 200809L
#include "mesh_convert.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <cjson/cJSON.h>

#define CONVERT_MAX (512L << 20) /* larger files are left to Assimp as they are */

static char *read_all(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *buf = NULL;
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (size >= 0 && size <= CONVERT_MAX && fseek(f, 0, SEEK_SET) == 0) buf = malloc((size_t)size + 1);
    if (buf && fread(buf, 1, (size_t)size, f) != (size_t)size) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    if (buf) buf[size] = '\0', *n = (size_t)size;
    return buf;
}

static size_t put_utf8(unsigned char *o, uint32_t c)
{
    if (c < 0x80) return o[0] = (unsigned char)c, 1;
    if (c < 0x800) return o[0] = (unsigned char)(0xC0 | c >> 6), o[1] = (unsigned char)(0x80 | (c & 63)), 2;
    if (c < 0x10000)
        return o[0] = (unsigned char)(0xE0 | c >> 12), o[1] = (unsigned char)(0x80 | (c >> 6 & 63)),
               o[2] = (unsigned char)(0x80 | (c & 63)), 3;
    o[0] = (unsigned char)(0xF0 | c >> 18), o[1] = (unsigned char)(0x80 | (c >> 12 & 63));
    o[2] = (unsigned char)(0x80 | (c >> 6 & 63)), o[3] = (unsigned char)(0x80 | (c & 63));
    return 4;
}

/* UTF-16 text after its BOM to UTF-8; 0 on a broken surrogate pair. */
static int utf16_to_utf8(const unsigned char *in, size_t n, int big, soak_mesh_text *out)
{
    unsigned char *o = malloc(n / 2 * 3 + 4), *w = o;
    if (!o) return 0;
    for (size_t i = 2; i + 1 < n; i += 2) {
        uint32_t c = big ? (uint32_t)in[i] << 8 | in[i + 1] : (uint32_t)in[i + 1] << 8 | in[i];
        if (c >= 0xD800 && c <= 0xDBFF && i + 3 < n) {
            uint32_t d = big ? (uint32_t)in[i + 2] << 8 | in[i + 3] : (uint32_t)in[i + 3] << 8 | in[i + 2];
            if (!(d >= 0xDC00 && d <= 0xDFFF)) break;
            c = 0x10000 + ((c - 0xD800) << 10) + (d - 0xDC00);
            i += 2;
        } else if (c >= 0xD800 && c <= 0xDFFF) {
            break;
        }
        w += put_utf8(w, c);
    }
    out->data = (char *)o;
    out->size = (size_t)(w - o);
    return 1;
}

static char *base64(const unsigned char *in, size_t n)
{
    static const char tab[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    static const char head[] = "data:application/octet-stream;base64,";
    char *o = malloc(sizeof head + (n + 2) / 3 * 4), *w = o;
    if (!o) return NULL;
    memcpy(w, head, sizeof head - 1);
    w += sizeof head - 1;
    for (size_t i = 0; i < n; i += 3) {
        uint32_t v = (uint32_t)in[i] << 16 | (i + 1 < n ? (uint32_t)in[i + 1] << 8 : 0) | (i + 2 < n ? in[i + 2] : 0);
        *w++ = tab[v >> 18 & 63];
        *w++ = tab[v >> 12 & 63];
        *w++ = i + 1 < n ? tab[v >> 6 & 63] : '=';
        *w++ = i + 2 < n ? tab[v & 63] : '=';
    }
    *w = '\0';
    return o;
}

static uint32_t le32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

/* The JSON of a glTF 1.0 binary file with its body as one data URI. */
static int glb1_to_gltf(const unsigned char *in, size_t n, soak_mesh_text *out, char *why, size_t whylen)
{
    uint32_t content = le32(in + 12);
    if (le32(in + 16) != 0 || (size_t)content > n - 20) {
        snprintf(why, whylen, "glTF 1.0 binary file whose scene (%u bytes, format %u) does not fit its %zu bytes",
                 content, le32(in + 16), n);
        return -1;
    }
    cJSON *j = cJSON_ParseWithLength((const char *)in + 20, content);
    if (!cJSON_IsObject(j)) {
        cJSON_Delete(j);
        snprintf(why, whylen, "glTF 1.0 binary file whose scene is not a JSON object");
        return -1;
    }
    static const char *const unread[] = {"images",   "textures",   "samplers",      "shaders",
                                         "programs", "techniques", "extensionsUsed"};
    for (size_t k = 0; k < sizeof unread / sizeof *unread; ++k) cJSON_DeleteItemFromObjectCaseSensitive(j, unread[k]);
    cJSON *m, *views = cJSON_GetObjectItemCaseSensitive(j, "bufferViews"), *v;
    cJSON_ArrayForEach(m, cJSON_GetObjectItemCaseSensitive(j, "materials"))
    {
        cJSON_DeleteItemFromObjectCaseSensitive(m, "technique");
        cJSON_DeleteItemFromObjectCaseSensitive(m, "values");
    }
    cJSON_ArrayForEach(v, views)
    {
        cJSON *b = cJSON_GetObjectItemCaseSensitive(v, "buffer");
        if (cJSON_IsString(b) && !strcmp(b->valuestring, "binary_glTF"))
            cJSON_ReplaceItemInObjectCaseSensitive(v, "buffer", cJSON_CreateString("soak_body"));
    }
    cJSON *buffers = cJSON_GetObjectItemCaseSensitive(j, "buffers");
    char *uri = base64(in + 20 + content, n - 20 - content);
    cJSON *body = cJSON_CreateObject();
    if (cJSON_IsObject(buffers) && uri && body) {
        cJSON_DeleteItemFromObjectCaseSensitive(buffers, "binary_glTF");
        cJSON_AddNumberToObject(body, "byteLength", (double)(n - 20 - content));
        cJSON_AddStringToObject(body, "type", "arraybuffer");
        cJSON_AddStringToObject(body, "uri", uri);
        cJSON_AddItemToObject(buffers, "soak_body", body);
        body = NULL;
    }
    cJSON_Delete(body);
    free(uri);
    out->data = cJSON_PrintUnformatted(j);
    cJSON_Delete(j);
    if (!out->data) {
        snprintf(why, whylen, "glTF 1.0 binary file: out of memory converting it");
        return -1;
    }
    out->size = strlen(out->data);
    out->hint = "gltf";
    return 1;
}

static const char *ext_of(const char *path)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    return dot && (!slash || dot > slash) ? dot + 1 : "";
}

int soak_mesh_convert(const char *path, soak_mesh_text *out, char *why, size_t whylen)
{
    const char *ext = ext_of(path);
    int obj = !strcasecmp(ext, "obj"), glb = !strcasecmp(ext, "glb");
    memset(out, 0, sizeof *out);
    if (!obj && !glb) return 0;
    size_t n = 0;
    unsigned char *in = (unsigned char *)read_all(path, &n);
    int r = 0;
    if (in && obj && n >= 2 && ((in[0] == 0xFE && in[1] == 0xFF) || (in[0] == 0xFF && in[1] == 0xFE))) {
        r = utf16_to_utf8(in, n, in[0] == 0xFE, out) ? 1 : -1;
        out->hint = "obj";
        if (r < 0) snprintf(why, whylen, "OBJ in UTF-16 that is not valid UTF-16");
    } else if (in && glb && n >= 20 && !memcmp(in, "glTF", 4) && le32(in + 4) == 1) {
        r = glb1_to_gltf(in, n, out, why, whylen);
    }
    free(in);
    return r;
}
