/* JSON values with the messages of soak/json_read.h. */
#define _POSIX_C_SOURCE 200809L
#include "soak/json_read.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "soak/json_number.h"

soak_status soak_json_fail(const soak_json_in *in, soak_status st, const char *path, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    soak_verror_at(in->err, in->errlen, st, in->file, path, fmt, ap);
    va_end(ap);
    return st;
}

void soak_json_path(char *buf, size_t n, const char *parent, const char *key)
{
    snprintf(buf, n, "%s%s%s", parent, parent[0] ? "." : "", key);
}

void soak_json_index(char *buf, size_t n, const char *parent, int i) { snprintf(buf, n, "%s[%d]", parent, i); }

static int in_list(const char *key, const char *const *list)
{
    for (int i = 0; list && list[i]; ++i)
        if (strcmp(key, list[i]) == 0) return 1;
    return 0;
}

/* "a, b, c" of a NULL-terminated list, cut to the buffer. */
static void list_text(char *out, size_t n, const char *const *list)
{
    out[0] = '\0';
    for (int i = 0; list[i]; ++i) {
        strncat(out, list[i], n - strlen(out) - 1);
        if (list[i + 1]) strncat(out, ", ", n - strlen(out) - 1);
    }
}

static soak_status key_error(const soak_json_in *in, const char *sub, const char *const *allowed,
                             const char *const *known, const char *key, const char *why)
{
    char list[512];
    list_text(list, sizeof list, allowed);
    if (in_list(key, known))
        return soak_json_fail(in, SOAK_ERR_PARSE, sub, "key not used by %s (accepted: %s)", why, list);
    return soak_json_fail(in, SOAK_ERR_PARSE, sub, "unknown key (accepted: %s)", list);
}

soak_status soak_json_keys(const soak_json_in *in, const cJSON *obj, const char *path, const char *const *allowed,
                           const char *const *known, const char *why, int require_all)
{
    if (!cJSON_IsObject(obj)) return soak_json_fail(in, SOAK_ERR_PARSE, path, "must be a JSON object");
    char sub[SOAK_JSON_PATH_MAX];
    for (const cJSON *it = obj->child; it; it = it->next) {
        soak_json_path(sub, sizeof sub, path, it->string ? it->string : "?");
        for (const cJSON *prev = obj->child; prev != it; prev = prev->next)
            if (strcmp(prev->string, it->string) == 0) return soak_json_fail(in, SOAK_ERR_PARSE, sub, "duplicate key");
        if (!in_list(it->string, allowed)) return key_error(in, sub, allowed, known, it->string, why);
    }
    for (int i = 0; require_all && allowed[i]; ++i)
        if (!cJSON_GetObjectItemCaseSensitive(obj, allowed[i])) {
            soak_json_path(sub, sizeof sub, path, allowed[i]);
            return soak_json_fail(in, SOAK_ERR_PARSE, sub, "missing (required)");
        }
    return SOAK_OK;
}

/* obj[key] with its path written to sub; NULL when absent, with *st the
 * error when the key is required, else SOAK_OK (the caller's default). */
static const cJSON *member(const soak_json_in *in, const cJSON *obj, const char *key, const char *path, int required,
                           char sub[SOAK_JSON_PATH_MAX], soak_status *st)
{
    soak_json_path(sub, SOAK_JSON_PATH_MAX, path, key);
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    *st = !v && required ? soak_json_fail(in, SOAK_ERR_PARSE, sub, "missing (required)") : SOAK_OK;
    return v;
}

static soak_status number_at(const soak_json_in *in, const cJSON *v, const char *path, double lo, double hi,
                             int lo_open, double *out)
{
    char why[128];
    soak_status st = soak_json_number(v, lo, hi, lo_open, out, why, sizeof why);
    return st == SOAK_OK ? SOAK_OK : soak_json_fail(in, st, path, "%s", why);
}

soak_status soak_json_get_number(const soak_json_in *in, const cJSON *obj, const char *key, const char *path, double lo,
                                 double hi, int lo_open, int required, double def, double *out)
{
    char sub[SOAK_JSON_PATH_MAX];
    soak_status st;
    const cJSON *v = member(in, obj, key, path, required, sub, &st);
    if (!v) {
        if (st == SOAK_OK) *out = def;
        return st;
    }
    return number_at(in, v, sub, lo, hi, lo_open, out);
}

soak_status soak_json_get_triple(const soak_json_in *in, const cJSON *obj, const char *key, const char *path, double lo,
                                 double hi, int grey_ok, int required, const double def[3], const char *what,
                                 double out[3])
{
    char sub[SOAK_JSON_PATH_MAX];
    soak_status st;
    const cJSON *v = member(in, obj, key, path, required, sub, &st);
    if (!v) {
        if (st == SOAK_OK) memcpy(out, def, 3 * sizeof *out);
        return st;
    }
    double t[3];
    if (grey_ok && cJSON_IsNumber(v)) {
        st = number_at(in, v, sub, lo, hi, 0, &t[0]);
        if (st == SOAK_OK) out[0] = out[1] = out[2] = t[0];
        return st;
    }
    if (!cJSON_IsArray(v) || cJSON_GetArraySize(v) != 3)
        return soak_json_fail(in, SOAK_ERR_PARSE, sub, "must be an array of 3 numbers (%s)%s", what,
                              grey_ok ? " or one number" : "");
    for (int i = 0; i < 3; ++i) {
        char si[SOAK_JSON_PATH_MAX + 16];
        soak_json_index(si, sizeof si, sub, i);
        st = number_at(in, cJSON_GetArrayItem(v, i), si, lo, hi, 0, &t[i]);
        if (st != SOAK_OK) return st;
    }
    memcpy(out, t, sizeof t);
    return SOAK_OK;
}

soak_status soak_json_get_rgb(const soak_json_in *in, const cJSON *obj, const char *key, const char *path, double lo,
                              double hi, int grey_ok, int required, soak_rgb def, soak_rgb *out)
{
    double d[3] = {def.r, def.g, def.b}, t[3];
    soak_status st = soak_json_get_triple(in, obj, key, path, lo, hi, grey_ok, required, d, "R, G, B", t);
    if (st == SOAK_OK) *out = soak_rgb3(t[0], t[1], t[2]);
    return st;
}

soak_status soak_json_get_string(const soak_json_in *in, const cJSON *obj, const char *key, const char *path,
                                 int required, const char **out)
{
    char sub[SOAK_JSON_PATH_MAX];
    soak_status st;
    const cJSON *v = member(in, obj, key, path, required, sub, &st);
    *out = NULL;
    if (!v) return st;
    if (!cJSON_IsString(v) || !v->valuestring || !v->valuestring[0])
        return soak_json_fail(in, SOAK_ERR_PARSE, sub, "must be a non-empty string");
    *out = v->valuestring;
    return SOAK_OK;
}
