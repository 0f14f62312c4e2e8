/* One escaping function per generated language (soak/export_escape.h). */
#include "soak/export_escape.h"

#include <stdio.h>
#include <string.h>

typedef struct sink {
    char *dst;
    size_t cap, len;
    int full;
} sink;

static void put(sink *k, const char *text, size_t n)
{
    if (k->full || n >= k->cap - k->len) {
        k->full = 1;
        return;
    }
    memcpy(k->dst + k->len, text, n);
    k->len += n;
    k->dst[k->len] = '\0';
}

static void put_fmt(sink *k, const char *fmt, unsigned value)
{
    char buf[16];
    int n = snprintf(buf, sizeof buf, fmt, value);
    put(k, buf, (size_t)n);
}

static int is_control(unsigned char c) { return c < 0x20 || c == 0x7f; }

/* Length of the well-formed UTF-8 sequence at p (RFC 3629: no overlong
 * forms, no surrogates, nothing above U+10FFFF), 0 when there is none. */
static size_t utf8_length(const unsigned char *p)
{
    unsigned char c = p[0];
    if (c < 0x80) return 1;
    size_t n = c >= 0xc2 && c <= 0xdf ? 2 : (c >= 0xe0 && c <= 0xef ? 3 : (c >= 0xf0 && c <= 0xf4 ? 4 : 0));
    for (size_t i = 1; i < n; ++i)
        if ((p[i] & 0xc0) != 0x80) return 0;
    if (n == 3 && c == 0xe0 && p[1] < 0xa0) return 0;  /* overlong */
    if (n == 3 && c == 0xed && p[1] >= 0xa0) return 0; /* surrogate */
    if (n == 4 && c == 0xf0 && p[1] < 0x90) return 0;  /* overlong */
    if (n == 4 && c == 0xf4 && p[1] >= 0x90) return 0; /* above U+10FFFF */
    return n;
}

static soak_status finish(sink *k, soak_status st)
{
    if (st == SOAK_OK && k->full) st = SOAK_ERR_NOMEM;
    if (st != SOAK_OK && k->cap) k->dst[0] = '\0';
    return st;
}

static soak_status start(sink *k, const char *s, char *dst, size_t cap)
{
    *k = (sink){dst, cap, 0, 0};
    if (!s || !dst) return SOAK_ERR_NULL;
    if (!cap) return SOAK_ERR_NOMEM;
    dst[0] = '\0';
    return SOAK_OK;
}

soak_status soak_escape_povray(const char *s, char *dst, size_t cap)
{
    sink k;
    soak_status st = start(&k, s, dst, cap);
    if (st != SOAK_OK) return st;
    for (const unsigned char *p = (const unsigned char *)s; *p; ++p) {
        if (*p == '"' || *p == '\\') put(&k, *p == '"' ? "\\\"" : "\\\\", 2);
        else if (is_control(*p)) put_fmt(&k, "\\u%04X", *p);
        else put(&k, (const char *)p, 1);
    }
    return finish(&k, SOAK_OK);
}

/* The C-family escapes OSL, Python and JavaScript share. */
static int put_c_escape(sink *k, unsigned char c)
{
    static const char from[] = "\"\\\n\t\r", *const to[] = {"\\\"", "\\\\", "\\n", "\\t", "\\r"};
    const char *hit = c ? strchr(from, c) : NULL;
    if (!hit) return 0;
    put(k, to[hit - from], 2);
    return 1;
}

soak_status soak_escape_osl(const char *s, char *dst, size_t cap)
{
    sink k;
    soak_status st = start(&k, s, dst, cap);
    if (st != SOAK_OK) return st;
    for (const unsigned char *p = (const unsigned char *)s; *p; ++p) {
        if (put_c_escape(&k, *p)) continue;
        if (is_control(*p)) put_fmt(&k, "\\%03o", *p);
        else put(&k, (const char *)p, 1);
    }
    return finish(&k, SOAK_OK);
}

/* Python and JavaScript: text must be UTF-8; controls as hex_fmt. */
static soak_status escape_script(const char *s, char *dst, size_t cap, const char *hex_fmt, int line_separators)
{
    sink k;
    soak_status st = start(&k, s, dst, cap);
    if (st != SOAK_OK) return st;
    for (const unsigned char *p = (const unsigned char *)s; *p;) {
        size_t n = utf8_length(p);
        if (!n) return finish(&k, SOAK_ERR_ARG);
        int done = n == 1 && (*p == '\'' ? (put(&k, "\\'", 2), 1) : put_c_escape(&k, *p));
        if (done) {
            p += n;
            continue;
        }
        if (n == 1 && is_control(*p)) put_fmt(&k, hex_fmt, *p);
        else if (line_separators && n == 3 && p[0] == 0xe2 && p[1] == 0x80 && (p[2] == 0xa8 || p[2] == 0xa9))
            put_fmt(&k, "\\u%04X", p[2] == 0xa8 ? 0x2028u : 0x2029u);
        else put(&k, (const char *)p, n);
        p += n;
    }
    return finish(&k, SOAK_OK);
}

soak_status soak_escape_python(const char *s, char *dst, size_t cap)
{
    return escape_script(s, dst, cap, "\\x%02x", 0);
}

soak_status soak_escape_javascript(const char *s, char *dst, size_t cap)
{
    return escape_script(s, dst, cap, "\\u%04X", 1);
}
