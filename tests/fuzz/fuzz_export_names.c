/* `soak export`'s string inputs (issue 51 item 2): the input is a string
 * (up to its first NUL byte).
 *  1. Each escape of soak/export_escape.h: what it writes decodes, by the
 *     language's rules written out here (not the escaper's code), back to the
 *     input, holds no raw control byte and no quote that would end the
 *     literal; Python and JavaScript refuse only text that is not UTF-8.
 *  2. When the string is a valid file name: the preset file
 *     tests/fuzz/data/export_names_presets.json under that name exported to
 *     POV-Ray and OSL has, outside its string literals and comments, exactly
 *     the code of the same export under a plain name ("m.json"): no byte of
 *     the name became code. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "soak/export.h"
#include "soak/export_escape.h"
#include "soak/preset.h"

#define NAME_MAX_BYTES 255

static void fail(const char *what, const char *s)
{
    fprintf(stderr, "fuzz_export_names: %s (input of %zu bytes)\n", what, strlen(s));
    abort();
}

static int hex_value(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

static int read_hex(const char *p, int digits)
{
    int v = 0;
    for (int i = 0; i < digits; ++i) {
        int h = hex_value(p[i]);
        if (h < 0) return -1;
        v = v * 16 + h;
    }
    return v;
}

/* Appends code point cp as UTF-8 (an escape of a byte below 0x80 is that byte). */
static size_t put_utf8(char *out, long cp)
{
    if (cp < 0x80) return out[0] = (char)cp, 1;
    if (cp < 0x800) return out[0] = (char)(0xc0 | (cp >> 6)), out[1] = (char)(0x80 | (cp & 0x3f)), 2;
    out[0] = (char)(0xe0 | (cp >> 12));
    out[1] = (char)(0x80 | ((cp >> 6) & 0x3f));
    out[2] = (char)(0x80 | (cp & 0x3f));
    return 3;
}

/* Decodes a literal body: the escapes each language defines that the
 * bodies may use (POV-Ray 3.7: \" \\ \uXXXX; OSL/C: \" \\ \n \t \r \ooo;
 * Python: \' \xHH too; JavaScript: \uXXXX). Returns 0 on a malformed body:
 * a raw quote, a raw control byte, an unknown escape. */
static int decode(const char *lit, char lang, char *out)
{
    size_t n = 0;
    for (const char *p = lit; *p; ++p) {
        unsigned char c = (unsigned char)*p;
        if (c == '"' || c < 0x20 || c == 0x7f) return 0;
        if (c != '\\') {
            out[n++] = (char)c;
            continue;
        }
        char e = *++p;
        int v;
        if (e == '"' || e == '\\' || (e == '\'' && (lang == 'p' || lang == 'j'))) out[n++] = e;
        else if (lang != 'v' && (e == 'n' || e == 't' || e == 'r')) out[n++] = e == 'n' ? '\n' : (e == 't' ? '\t' : '\r');
        else if (e == 'u' && (lang == 'v' || lang == 'j') && (v = read_hex(p + 1, 4)) >= 0) {
            n += put_utf8(out + n, v);
            p += 4;
        } else if (e == 'x' && lang == 'p' && (v = read_hex(p + 1, 2)) >= 0) {
            out[n++] = (char)v;
            p += 2;
        } else if (lang == 'o' && e >= '0' && e <= '3' && p[1] >= '0' && p[1] <= '7' && p[2] >= '0' && p[2] <= '7') {
            out[n++] = (char)((e - '0') * 64 + (p[1] - '0') * 8 + (p[2] - '0'));
            p += 2;
        } else
            return 0;
    }
    out[n] = '\0';
    return 1;
}

static void check_escapes(const char *s)
{
    static const struct {
        char lang;
        soak_status (*fn)(const char *, char *, size_t);
    } langs[] = {{'v', soak_escape_povray}, {'o', soak_escape_osl}, {'p', soak_escape_python},
                 {'j', soak_escape_javascript}};
    size_t cap = SOAK_ESCAPE_SIZE(strlen(s));
    char *lit = malloc(cap), *back = malloc(cap);
    if (!lit || !back) abort();
    int high = 0;
    for (const unsigned char *p = (const unsigned char *)s; *p; ++p) high |= *p >= 0x80;
    for (size_t i = 0; i < sizeof langs / sizeof langs[0]; ++i) {
        soak_status st = langs[i].fn(s, lit, cap);
        if (st == SOAK_ERR_ARG && (langs[i].lang == 'p' || langs[i].lang == 'j') && high) continue;
        if (st != SOAK_OK) fail("an escape failed with room to spare", s);
        if (!decode(lit, langs[i].lang, back)) fail("a literal body is malformed for its language", s);
        if (strcmp(back, s) != 0) fail("a literal body does not decode to its input", s);
    }
    free(lit);
    free(back);
}

/* The text outside "..." literals and comments (C, OSL and POV-Ray share
 * these lexical rules), literal bodies replaced by nothing. */
static char *code_only(const char *t)
{
    char *out = malloc(strlen(t) + 1), *o = out;
    if (!out) abort();
    while (*t) {
        if (t[0] == '/' && t[1] == '/') {
            while (*t && *t != '\n') ++t;
        } else if (t[0] == '/' && t[1] == '*') {
            const char *end = strstr(t + 2, "*/");
            t = end ? end + 2 : t + strlen(t);
        } else if (*t == '"') {
            *o++ = '"';
            for (++t; *t && *t != '"'; ++t)
                if (*t == '\\' && t[1]) ++t;
            if (*t) ++t;
            *o++ = '"';
        } else
            *o++ = *t++;
    }
    *o = '\0';
    return out;
}

static char *read_all(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t cap = 1 << 20, n = 0, got;
    char *buf = malloc(cap);
    while (buf && (got = fread(buf + n, 1, cap - 1 - n, f)) > 0) n += got;
    fclose(f);
    if (buf) buf[n] = '\0';
    return buf;
}

/* The export of the test presets stored as dir/name, outside literals and
 * comments; NULL when the export fails. */
static char *export_code(const char *name, const soak_export_target *t, const char *presets)
{
    char in[4096], outp[512], err[1024] = "";
    snprintf(in, sizeof in, "%s/%s", fuzz_temp_dir(), name);
    snprintf(outp, sizeof outp, "%s/names.out", fuzz_temp_dir());
    FILE *f = fopen(in, "wb");
    if (!f) return NULL;
    fputs(presets, f);
    fclose(f);
    soak_preset_db *db = NULL;
    char *code = NULL;
    if (soak_presets_load(in, &db, err, sizeof err) == SOAK_OK &&
        soak_export_run(t, db, outp, err, sizeof err) == SOAK_OK) {
        char *text = read_all(outp);
        if (text) code = code_only(text);
        free(text);
    }
    soak_presets_free(db);
    remove(in);
    remove(outp);
    return code;
}

static int valid_file_name(const char *s)
{
    size_t n = strlen(s);
    return n >= 1 && n <= NAME_MAX_BYTES && !strchr(s, '/') && strcmp(s, ".") && strcmp(s, "..") &&
           strcmp(s, "names.out");
}

static void check_writers(const char *s)
{
    char *presets = read_all(SOAK_FUZZ_DATA_DIR "/export_names_presets.json");
    if (!presets) abort();
    const char *targets[] = {"povray", "osl-wetmap", "osl"};
    for (size_t i = 0; i < sizeof targets / sizeof targets[0]; ++i) {
        const soak_export_target *t = soak_export_find_target(targets[i]);
        char *want = export_code("m.json", t, presets), *got = export_code(s, t, presets);
        if (!want || !got) fail("the export failed", s);
        if (strcmp(want, got) != 0) {
            fprintf(stderr, "--target %s: the file name changed the code outside literals and comments\n", targets[i]);
            fail("a file name became code", s);
        }
        free(want);
        free(got);
    }
    free(presets);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 1024) return 0;
    char s[1025];
    memcpy(s, data, size);
    s[size] = '\0';
    check_escapes(s);
    if (valid_file_name(s)) check_writers(s);
    return 0;
}
