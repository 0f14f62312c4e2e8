/* Cheap structural checks on a mesh file before Assimp sees it.
 *
 * Assimp 5.2 loops for minutes or aborts on some malformed files (a PLY
 * header without end_header, an OFF whose counts exceed the file). These
 * checks read the header (and for OBJ/ASCII formats scan the file once) and
 * refuse, in well under a second, any file whose header is incomplete or
 * claims more data than the file holds:
 *  - PLY: "ply" magic, a format line, end_header within the first 64 KiB;
 *    element counts below 2^31; the bytes the elements need at least
 *    (binary: fixed property sizes, one count per list; ASCII: two bytes per
 *    value) fit in the rest of the file;
 *  - OFF: [C][N][ST]OFF magic, vertex and face counts below 2^31, at least
 *    6 bytes per vertex and 8 per face in the rest of the file, one face;
 *  - STL: binary when 84 + 50 n equals the file size; else "solid" ... with
 *    "endsolid" at the end (ASCII); anything else is a truncated binary;
 *  - OBJ: every face index non-zero and within the file's vertex, texture
 *    and normal counts (negative ones relative), at least one face;
 *  - GLB: "glTF" magic, version 2, declared length equal to the file size,
 *    chunks inside it; glTF: a JSON object that parses completely. */
#define _GNU_SOURCE
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <cjson/cJSON.h>

#include "mesh_import.h"

#define HEADER_MAX 65536
#define COUNT_MAX 2147483647LL

static soak_status refuse(char *err, size_t errlen, const char *path, const char *why)
{
    if (err && errlen) snprintf(err, errlen, "%s: malformed mesh file: %s", path, why);
    return SOAK_ERR_PARSE;
}

static const char *ext_of(const char *path)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    return dot && (!slash || dot > slash) ? dot + 1 : "";
}

/* Size in bytes of a PLY scalar type, 0 when unknown. */
static int ply_type_size(const char *t)
{
    static const char *const names[] = {"char", "int8", "uchar", "uint8", "short", "int16", "ushort", "uint16",
                                        "int",  "int32", "uint", "uint32", "float", "float32", "double", "float64"};
    static const int sizes[] = {1, 1, 1, 1, 2, 2, 2, 2, 4, 4, 4, 4, 4, 4, 8, 8};
    for (size_t i = 0; i < sizeof sizes / sizeof *sizes; ++i)
        if (!strcmp(t, names[i])) return sizes[i];
    return 0;
}

static soak_status check_ply(const char *path, const char *buf, size_t n, long long size, char *err, size_t errlen)
{
    if (n < 4 || memcmp(buf, "ply", 3) != 0 || (buf[3] != '\n' && buf[3] != '\r'))
        return refuse(err, errlen, path, "PLY without the 'ply' magic line");
    const char *end = NULL;
    for (const char *p = buf; p + 10 <= buf + n; ++p)
        if ((p == buf || p[-1] == '\n') && !memcmp(p, "end_header", 10)) {
            end = p;
            break;
        }
    if (!end) return refuse(err, errlen, path, "PLY header without end_header in its first 64 KiB (truncated?)");
    const char *body = memchr(end, '\n', (size_t)(buf + n - end));
    if (!body) return refuse(err, errlen, path, "PLY header ends without a newline after end_header");
    long long data = size - (long long)(body + 1 - buf);
    int binary = -1, have_vertex = 0;
    long long need = 0, count = 0, row = 0;
    char line[256], msg[256];
    for (const char *p = buf; p < end;) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        size_t len = (size_t)((nl ? nl : end) - p);
        snprintf(line, sizeof line, "%.*s", (int)(len < sizeof line ? len : sizeof line - 1), p);
        p = nl ? nl + 1 : end;
        char a[64] = "", b[64] = "", c[64] = "";
        long long k = -1;
        if (sscanf(line, "format %63s", a) == 1) {
            binary = !strcmp(a, "ascii") ? 0 : (!strcmp(a, "binary_little_endian") || !strcmp(a, "binary_big_endian")) ? 1 : -2;
            if (binary == -2) return refuse(err, errlen, path, "PLY format is not ascii or binary");
        } else if (sscanf(line, "element %63s %lld", a, &k) == 2) {
            if (k < 0 || k > COUNT_MAX) {
                snprintf(msg, sizeof msg, "PLY element '%s' count %lld is outside 0..2^31-1", a, k);
                return refuse(err, errlen, path, msg);
            }
            need += count * row;
            count = k, row = 0;
            have_vertex |= !strcmp(a, "vertex");
        } else if (sscanf(line, "property list %63s %63s %63s", a, b, c) == 3) {
            int s = ply_type_size(a);
            if (!s || !ply_type_size(b)) return refuse(err, errlen, path, "PLY list property of an unknown type");
            row += binary == 1 ? s : 2;
        } else if (sscanf(line, "property %63s %63s", a, b) == 2) {
            int s = ply_type_size(a);
            if (!s) {
                snprintf(msg, sizeof msg, "PLY property '%s' of unknown type '%s'", b, a);
                return refuse(err, errlen, path, msg);
            }
            row += binary == 1 ? s : 2;
        }
    }
    need += count * row;
    if (binary < 0) return refuse(err, errlen, path, "PLY header without a format line");
    if (!have_vertex) return refuse(err, errlen, path, "PLY header without a vertex element");
    if (binary == 0) need -= need > 0; /* the last value needs no separator */
    if (need > data) {
        snprintf(msg, sizeof msg, "the PLY header's elements need at least %lld bytes, the file has %lld after the header (truncated?)",
                 need, data);
        return refuse(err, errlen, path, msg);
    }
    return SOAK_OK;
}

/* Next whitespace-separated token of an OFF file, skipping # comments. */
static const char *off_token(const char **p, const char *end, size_t *len)
{
    const char *s = *p;
    for (;;) {
        while (s < end && isspace((unsigned char)*s)) ++s;
        if (s < end && *s == '#') {
            while (s < end && *s != '\n') ++s;
            continue;
        }
        break;
    }
    const char *t = s;
    while (s < end && !isspace((unsigned char)*s) && *s != '#') ++s;
    *p = s;
    *len = (size_t)(s - t);
    return *len ? t : NULL;
}

static soak_status check_off(const char *path, const char *buf, size_t n, long long size, char *err, size_t errlen)
{
    const char *p = buf, *end = buf + n;
    size_t len;
    const char *t = off_token(&p, end, &len);
    if (!t || len < 3 || len > 8 || memcmp(t + len - 3, "OFF", 3) != 0)
        return refuse(err, errlen, path, "OFF without the 'OFF' magic word");
    long long counts[3] = {-1, -1, 0};
    for (int i = 0; i < 3; ++i) {
        if (i == 2) { /* the edge count is optional: only on the faces' line */
            const char *q = p;
            while (q < end && (*q == ' ' || *q == '\t')) ++q;
            if (q >= end || !isdigit((unsigned char)*q)) break;
        }
        t = off_token(&p, end, &len);
        char num[32], *e = NULL;
        if (!t || len >= sizeof num) break;
        snprintf(num, sizeof num, "%.*s", (int)len, t);
        errno = 0;
        counts[i] = strtoll(num, &e, 10);
        if (*e || errno) counts[i] = -1;
    }
    char msg[256];
    if (counts[0] < 0 || counts[1] < 0 || counts[2] < 0 || counts[0] > COUNT_MAX || counts[1] > COUNT_MAX)
        return refuse(err, errlen, path, "OFF header needs its counts (vertices faces [edges]) in 0..2^31-1");
    if (counts[1] == 0 || counts[0] < 3) return refuse(err, errlen, path, "OFF file declares no faces or fewer than 3 vertices");
    long long need = 6 * counts[0] + 8 * counts[1] - 1, left = size - (long long)(p - buf);
    if (need > left) {
        snprintf(msg, sizeof msg, "the OFF header claims %lld vertices and %lld faces (at least %lld bytes), the file has %lld after it (truncated?)",
                 counts[0], counts[1], need, left);
        return refuse(err, errlen, path, msg);
    }
    return SOAK_OK;
}

static int has_token_near_end(FILE *f, long long size, const char *word)
{
    char tail[1025];
    long long from = size > 1024 ? size - 1024 : 0;
    if (fseeko(f, from, SEEK_SET) != 0) return 0;
    size_t got = fread(tail, 1, sizeof tail - 1, f);
    tail[got] = '\0';
    for (size_t i = 0; i < got; ++i)
        if (tail[i] == '\0') tail[i] = ' ';
    return strstr(tail, word) != NULL;
}

static soak_status check_stl(const char *path, FILE *f, const char *buf, size_t n, long long size, char *err,
                             size_t errlen)
{
    char msg[256];
    if (n >= 84) {
        uint32_t tris = (uint32_t)(unsigned char)buf[80] | (uint32_t)(unsigned char)buf[81] << 8 |
                        (uint32_t)(unsigned char)buf[82] << 16 | (uint32_t)(unsigned char)buf[83] << 24;
        if (84 + 50 * (long long)tris == size) {
            if (tris == 0) return refuse(err, errlen, path, "binary STL with no triangles");
            return SOAK_OK;
        }
    }
    const char *p = buf;
    while (p < buf + n && isspace((unsigned char)*p)) ++p;
    if ((size_t)(buf + n - p) >= 5 && !strncasecmp(p, "solid", 5)) {
        if (!has_token_near_end(f, size, "endsolid"))
            return refuse(err, errlen, path, "ASCII STL without 'endsolid' at its end (truncated?)");
        return SOAK_OK;
    }
    if (n < 84) {
        snprintf(msg, sizeof msg, "binary STL of %lld bytes, shorter than its 84-byte header", size);
        return refuse(err, errlen, path, msg);
    }
    uint32_t tris = (uint32_t)(unsigned char)buf[80] | (uint32_t)(unsigned char)buf[81] << 8 |
                    (uint32_t)(unsigned char)buf[82] << 16 | (uint32_t)(unsigned char)buf[83] << 24;
    snprintf(msg, sizeof msg, "binary STL header claims %u triangles (84 + 50 x %u = %lld bytes), the file has %lld",
             tris, tris, 84 + 50 * (long long)tris, size);
    return refuse(err, errlen, path, msg);
}

/* One OBJ face index: non-zero, within +-count. */
static int obj_index_ok(const char *s, long long count)
{
    /* By hand, not strtoll: this runs for every corner of every face, and
     * strtoll was a ninth of a 1 M-triangle bake's main thread. The digits
     * after a sign, as strtoll reads them (k <= count keeps 10 k from
     * overflowing: count is a number of lines). */
    if (*s == '-' || *s == '+') ++s;
    long long k = 0;
    int digits = 0;
    for (; *s >= '0' && *s <= '9'; ++s, ++digits) {
        k = 10 * k + (*s - '0');
        if (k > count) return 0;
    }
    return digits > 0 && k != 0;
}

/* The end of a plain decimal at s ([+-]digits[.digits], under 300 digits,
 * followed by a blank, the line's end or '#'): finite without strtod (7 %
 * of a 1 M-triangle OBJ bake's main thread). NULL for anything else
 * (exponents, nan, inf): left to strtod. */
static const char *plain_decimal_end(const char *s)
{
    int digits = 0;
    if (*s == '-' || *s == '+') ++s;
    for (; *s >= '0' && *s <= '9'; ++s) ++digits;
    if (*s == '.')
        for (++s; *s >= '0' && *s <= '9'; ++s) ++digits;
    int ends = !*s || *s == ' ' || *s == '\t' || *s == '\r' || *s == '\n' || *s == '#';
    return digits > 0 && digits < 300 && ends ? s : NULL;
}

/* The numbers of a v, vt or vn line: Assimp reads "nan" and "inf" as 0. */
static int obj_numbers_finite(const char *s, long long lineno, char *msg, size_t n)
{
    char *end = NULL;
    for (;;) {
        while (*s == ' ' || *s == '\t') ++s;
        if (!*s || *s == '\r' || *s == '\n' || *s == '#') return 1;
        const char *plain = plain_decimal_end(s);
        if (plain) {
            s = plain;
            continue;
        }
        double x = strtod(s, &end);
        if (end == s) return 1; /* not a number: left to Assimp */
        if (!isfinite(x)) {
            snprintf(msg, n, "line %lld: '%.*s' is not a finite number", lineno, (int)(end - s), s);
            return 0;
        }
        s = end;
    }
}

static soak_status check_obj(const char *path, FILE *f, char *err, size_t errlen)
{
    long long nv = 0, nt = 0, nn = 0, faces = 0, lineno = 0;
    char line[4096], msg[320];
    for (int pass = 0; pass < 2; ++pass) {
        rewind(f);
        lineno = 0;
        while (fgets(line, sizeof line, f)) {
            ++lineno;
            size_t len = strlen(line);
            int cut = len == sizeof line - 1 && line[len - 1] != '\n';
            if (pass == 0) {
                int is_v = !strncmp(line, "v ", 2) || !strncmp(line, "v\t", 2);
                int is_vt = !strncmp(line, "vt", 2) && isspace((unsigned char)line[2]);
                int is_vn = !strncmp(line, "vn", 2) && isspace((unsigned char)line[2]);
                nv += is_v, nt += is_vt, nn += is_vn;
                if ((is_v || is_vt || is_vn) && !cut && !obj_numbers_finite(line + (is_v ? 1 : 2), lineno, msg, sizeof msg))
                    return refuse(err, errlen, path, msg);
            } else if (line[0] == 'f' && isspace((unsigned char)line[1])) {
                if (cut) continue; /* a face longer than the buffer: left to Assimp */
                int refs = 0;
                for (char *tok = strtok(line + 1, " \t\r\n"); tok; tok = strtok(NULL, " \t\r\n")) {
                    char *slot[3] = {tok, NULL, NULL};
                    char *s1 = strchr(tok, '/');
                    if (s1) {
                        *s1 = '\0', slot[1] = s1 + 1;
                        char *s2 = strchr(slot[1], '/');
                        if (s2) *s2 = '\0', slot[2] = s2 + 1;
                    }
                    const long long lim[3] = {nv, nt, nn};
                    static const char *const what[3] = {"vertex", "texture coordinate", "normal"};
                    for (int k = 0; k < 3; ++k) {
                        if (!slot[k] || (k > 0 && !*slot[k])) continue;
                        if (!obj_index_ok(slot[k], lim[k])) {
                            snprintf(msg, sizeof msg, "line %lld: face names %s '%.40s' of %lld in the file", lineno,
                                     what[k], slot[k], lim[k]);
                            return refuse(err, errlen, path, msg);
                        }
                    }
                    ++refs;
                }
                if (refs < 3) {
                    snprintf(msg, sizeof msg, "line %lld: a face needs at least 3 vertices, has %d", lineno, refs);
                    return refuse(err, errlen, path, msg);
                }
                ++faces;
            }
            /* skip the rest of an overlong line */
            while (cut && fgets(line, sizeof line, f) && line[strlen(line) - 1] != '\n') {
            }
        }
    }
    if (ferror(f)) return refuse(err, errlen, path, "read error");
    if (!faces) return refuse(err, errlen, path, "OBJ file without faces");
    return SOAK_OK;
}

static uint32_t le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static soak_status check_glb(const char *path, const char *buf, size_t n, long long size, char *err, size_t errlen)
{
    const unsigned char *u = (const unsigned char *)buf;
    char msg[256];
    if (n < 20 || memcmp(buf, "glTF", 4) != 0) return refuse(err, errlen, path, "GLB without the 'glTF' magic and header");
    if (le32(u + 4) != 2 && le32(u + 4) != 1) {
        snprintf(msg, sizeof msg, "GLB version %u: Soak reads glTF binary versions 1 and 2", le32(u + 4));
        return refuse(err, errlen, path, msg);
    }
    if ((long long)le32(u + 8) != size) {
        snprintf(msg, sizeof msg, "GLB header declares %u bytes, the file has %lld (truncated?)", le32(u + 8), size);
        return refuse(err, errlen, path, msg);
    }
    if (le32(u + 4) == 1) { /* KHR_binary_glTF: content length, format 0 (JSON), then the body */
        if (le32(u + 16) != 0 || 20 + (long long)le32(u + 12) > size)
            return refuse(err, errlen, path, "glTF 1.0 binary header whose scene is not JSON or does not fit the file");
        return SOAK_OK;
    }
    long long at = 12;
    while (at < size) {
        if (at + 8 > size || (size_t)at + 8 > n) break; /* chunk headers past the first 64 KiB: left to Assimp */
        long long len = le32(u + at);
        if (at + 8 + len > size) {
            snprintf(msg, sizeof msg, "GLB chunk at byte %lld declares %lld bytes past the end of the file", at, len);
            return refuse(err, errlen, path, msg);
        }
        at += 8 + len;
    }
    return SOAK_OK;
}

static soak_status check_gltf(const char *path, FILE *f, long long size, char *err, size_t errlen)
{
    if (size > (64LL << 20)) return SOAK_OK; /* a huge JSON is parsed by Assimp alone */
    char *text = malloc((size_t)size + 1);
    if (!text) return SOAK_ERR_NOMEM;
    rewind(f);
    size_t got = fread(text, 1, (size_t)size, f);
    text[got] = '\0';
    cJSON *j = got == (size_t)size ? cJSON_ParseWithLength(text, got) : NULL;
    free(text);
    int ok = cJSON_IsObject(j) && cJSON_IsObject(cJSON_GetObjectItemCaseSensitive(j, "asset"));
    cJSON_Delete(j);
    return ok ? SOAK_OK : refuse(err, errlen, path, "glTF that is not a complete JSON object with an 'asset' (truncated?)");
}

/* A UTF-16 byte-order mark: the reader converts such an OBJ to UTF-8
 * (render/plugin/mesh_convert.c) and counts its faces itself. */
static int utf16_bom(const char *buf, size_t n)
{
    const unsigned char *u = (const unsigned char *)buf;
    return n >= 2 && ((u[0] == 0xFE && u[1] == 0xFF) || (u[0] == 0xFF && u[1] == 0xFE));
}

soak_status soak_mesh_check_file(const char *path, FILE *f, long long size, char *err, size_t errlen)
{
    char *buf = malloc(HEADER_MAX);
    if (!buf) return SOAK_ERR_NOMEM;
    rewind(f);
    size_t n = fread(buf, 1, HEADER_MAX, f);
    const char *ext = ext_of(path);
    soak_status st = SOAK_OK;
    if (n == 0) st = refuse(err, errlen, path, "empty file");
    else if (!strcasecmp(ext, "ply")) st = check_ply(path, buf, n, size, err, errlen);
    else if (!strcasecmp(ext, "off")) st = check_off(path, buf, n, size, err, errlen);
    else if (!strcasecmp(ext, "stl")) st = check_stl(path, f, buf, n, size, err, errlen);
    else if (!strcasecmp(ext, "obj") && !utf16_bom(buf, n)) st = check_obj(path, f, err, errlen);
    else if (!strcasecmp(ext, "glb")) st = check_glb(path, buf, n, size, err, errlen);
    else if (!strcasecmp(ext, "gltf")) st = check_gltf(path, f, size, err, errlen);
    free(buf);
    return st;
}
