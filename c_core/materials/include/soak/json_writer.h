/* The one JSON writer of the files soak writes for others to read (`soak
 * export --target json` and `--target blender`, `soak materials --json`):
 * a cJSON tree built through these calls and printed by cJSON, so that
 * escaping and layout are cJSON's everywhere and each file states its
 * numbers' precision once.
 *
 * Numbers are rounded to `digits` significant digits (printf's %.*g, read
 * back), so the same input gives the same bytes on every machine whatever
 * the last bits of the arithmetic; magnitudes below `zero_below` are written
 * as 0 (no "-0", no 1e-17 noise of a quantity that is zero). digits 0 does
 * no rounding of its own: cJSON prints 15 significant digits (17 where those
 * read back more than DBL_EPSILON relative away). A rounded number prints as
 * its short decimal, which reads back as that same double.
 *
 * Every call adds under key to the object parent, or appends to the array
 * parent when key is NULL, and returns the new item. A failed allocation (or
 * a NULL parent, left by an earlier failure) returns NULL and clears ok, so a
 * builder checks ok once at the end. */
#ifndef SOAK_JSON_WRITER_H
#define SOAK_JSON_WRITER_H

#include <cjson/cJSON.h>
#include <stdio.h>

#include "soak/status.h"
#include "soak/vec.h"

typedef struct soak_json {
    int ok;            /* 0 once an addition failed */
    int digits;        /* significant digits; 0: cJSON's 15 */
    double zero_below; /* |x| below this is written as 0 */
} soak_json;

static inline soak_json soak_json_writer(int digits, double zero_below)
{
    return (soak_json){1, digits, zero_below};
}

/* The number x as it will be written. */
double soak_json_round(const soak_json *j, double x);

cJSON *soak_json_num(soak_json *j, cJSON *parent, const char *key, double v);
cJSON *soak_json_int(soak_json *j, cJSON *parent, const char *key, int v); /* exact, never rounded */
cJSON *soak_json_str(soak_json *j, cJSON *parent, const char *key, const char *v); /* NULL: "" */
cJSON *soak_json_bool(soak_json *j, cJSON *parent, const char *key, int v);
cJSON *soak_json_rgb(soak_json *j, cJSON *parent, const char *key, soak_rgb c); /* [r, g, b] */
cJSON *soak_json_array(soak_json *j, cJSON *parent, const char *key);
cJSON *soak_json_object(soak_json *j, cJSON *parent, const char *key);

/* root as cJSON's formatted text in a malloc'd string (SOAK_ERR_NOMEM when
 * ok was cleared or printing fails). */
soak_status soak_json_print(const soak_json *j, const cJSON *root, char **text);

/* The same text and a newline, written to out (SOAK_ERR_IO when the write
 * fails). */
soak_status soak_json_write(const soak_json *j, const cJSON *root, FILE *out);

#endif
