/* The one reader of values from a JSON file soak loads (the preset file
 * `materials.json` and scene files), beside the rule for a number
 * (soak/json_number.h): objects and their keys, numbers, colours and
 * strings, each failure worded once, as "<file>: <json path>: <reason>"
 * (soak_verror_at), so presets and scenes report the same mistake the same
 * way:
 *   "must be a JSON object"
 *   "unknown key (accepted: a, b, c)", "key not used by <why> (accepted: ...)"
 *   "duplicate key", "missing (required)"
 *   "must be an array of 3 numbers (R, G, B)" (colours) or "... (x, y, z)"
 *   "must be a non-empty string"
 *   and soak_json_number's reasons for a number. */
#ifndef SOAK_JSON_READ_H
#define SOAK_JSON_READ_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "soak/status.h"
#include "soak/vec.h"

/* Where messages go and the file they name. */
typedef struct soak_json_in {
    const char *file;
    char *err;
    size_t errlen;
} soak_json_in;

/* JSON paths are cut at this length (the schemas' are far shorter). */
#define SOAK_JSON_PATH_MAX 512

/* Writes "<file>: <path>: <reason>" and returns st. */
soak_status soak_json_fail(const soak_json_in *in, soak_status st, const char *path, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* Child paths "parent.key" ("key" at the top, parent "") and "parent[i]". */
void soak_json_path(char *buf, size_t n, const char *parent, const char *key);
void soak_json_index(char *buf, size_t n, const char *parent, int i);

/* obj is an object whose keys are all in the NULL-terminated `allowed`, none
 * twice. A key in `known` (may be NULL) but not allowed is "not used by
 * <why>"; with require_all every allowed key must be present. */
soak_status soak_json_keys(const soak_json_in *in, const cJSON *obj, const char *path, const char *const *allowed,
                           const char *const *known, const char *why, int require_all);
/* obj[key] (path of obj given) as a number in [lo, hi] ((lo, hi] with
 * lo_open); absent: def, or "missing (required)" when required. */
soak_status soak_json_get_number(const soak_json_in *in, const cJSON *obj, const char *key, const char *path, double lo,
                                 double hi, int lo_open, int required, double def, double *out);
/* obj[key] as [a, b, c] each in [lo, hi]; grey_ok: one number for all
 * three. what: "R, G, B" or "x, y, z" for the message. */
soak_status soak_json_get_triple(const soak_json_in *in, const cJSON *obj, const char *key, const char *path, double lo,
                                 double hi, int grey_ok, int required, const double def[3], const char *what,
                                 double out[3]);
/* soak_json_get_triple as a colour. */
soak_status soak_json_get_rgb(const soak_json_in *in, const cJSON *obj, const char *key, const char *path, double lo,
                              double hi, int grey_ok, int required, soak_rgb def, soak_rgb *out);
/* obj[key] as a non-empty string (pointing into obj); NULL when absent and
 * not required. */
soak_status soak_json_get_string(const soak_json_in *in, const cJSON *obj, const char *key, const char *path,
                                 int required, const char **out);

#endif
