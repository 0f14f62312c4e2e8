/* JSON access for the scene parser with messages "<file>: <json path>:
 * <reason>" (scene_json.h), and the messages for text that is not JSON. */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "scene_json.h"
#include "soak/json_number.h"

soak_status sj_fail(scene_ctx *c, soak_status status, const char *path, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    soak_verror_at(c->err, c->errlen, status, c->name, path, fmt, ap);
    va_end(ap);
    return status;
}

void sj_path(char *buf, size_t n, const char *parent, const char *key)
{
    snprintf(buf, n, "%s%s%s", parent, parent[0] ? "." : "", key);
}

void sj_index(char *buf, size_t n, const char *parent, int i) { snprintf(buf, n, "%s[%d]", parent, i); }

soak_status sj_keys(scene_ctx *c, const cJSON *obj, const char *path, const char *const *allowed)
{
    if (!cJSON_IsObject(obj)) return sj_fail(c, SOAK_ERR_PARSE, path, "must be a JSON object");
    for (const cJSON *it = obj->child; it; it = it->next) {
        int ok = 0;
        for (const char *const *a = allowed; *a && !ok; ++a) ok = strcmp(*a, it->string) == 0;
        if (!ok) {
            char p[512];
            sj_path(p, sizeof p, path, it->string);
            char list[512] = "";
            for (const char *const *a = allowed; *a; ++a) {
                strncat(list, *a, sizeof list - strlen(list) - 1);
                if (a[1]) strncat(list, ", ", sizeof list - strlen(list) - 1);
            }
            return sj_fail(c, SOAK_ERR_PARSE, p, "unknown key (accepted: %s)", list);
        }
    }
    return SOAK_OK;
}

static soak_status num_value(scene_ctx *c, const cJSON *v, const char *path, double lo, double hi, int strict_lo,
                             double *out)
{
    char why[128];
    soak_status st = soak_json_number(v, lo, hi, strict_lo, out, why, sizeof why);
    return st == SOAK_OK ? SOAK_OK : sj_fail(c, st, path, "%s", why);
}

/* obj[key] with its dotted path written to p; NULL when absent, with *st
 * the error if the key is required, else SOAK_OK (the caller's default). */
static const cJSON *member(scene_ctx *c, const cJSON *obj, const char *key, const char *path, int required,
                           char p[512], soak_status *st)
{
    sj_path(p, 512, path, key);
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    *st = !v && required ? sj_fail(c, SOAK_ERR_PARSE, p, "missing (required)") : SOAK_OK;
    return v;
}

static soak_status num_impl(scene_ctx *c, const cJSON *obj, const char *key, const char *path, double lo, double hi,
                            int required, double def, int strict, double *out)
{
    char p[512];
    soak_status st;
    const cJSON *v = member(c, obj, key, path, required, p, &st);
    if (!v) {
        if (st == SOAK_OK) *out = def;
        return st;
    }
    return num_value(c, v, p, lo, hi, strict, out);
}

soak_status sj_num(scene_ctx *c, const cJSON *obj, const char *key, const char *path, double lo, double hi,
                   int required, double def, double *out)
{
    return num_impl(c, obj, key, path, lo, hi, required, def, 0, out);
}

soak_status sj_num_gt(scene_ctx *c, const cJSON *obj, const char *key, const char *path, double lo, double hi,
                      int required, double def, double *out)
{
    return num_impl(c, obj, key, path, lo, hi, required, def, 1, out);
}

static soak_status triple(scene_ctx *c, const cJSON *v, const char *p, double lo, double hi, double out[3])
{
    if (!cJSON_IsArray(v) || cJSON_GetArraySize(v) != 3)
        return sj_fail(c, SOAK_ERR_PARSE, p, "must be an array of 3 numbers");
    for (int i = 0; i < 3; ++i) {
        char pi[520];
        sj_index(pi, sizeof pi, p, i);
        soak_status st = num_value(c, cJSON_GetArrayItem(v, i), pi, lo, hi, 0, &out[i]);
        if (st != SOAK_OK) return st;
    }
    return SOAK_OK;
}

soak_status sj_vec3(scene_ctx *c, const cJSON *obj, const char *key, const char *path, int required, soak_vec3 def,
                    soak_vec3 *out)
{
    char p[512];
    soak_status st;
    const cJSON *v = member(c, obj, key, path, required, p, &st);
    if (!v) {
        if (st == SOAK_OK) *out = def;
        return st;
    }
    double t[3];
    st = triple(c, v, p, -1e12, 1e12, t);
    if (st == SOAK_OK) *out = soak_v3(t[0], t[1], t[2]);
    return st;
}

soak_status sj_rgb(scene_ctx *c, const cJSON *obj, const char *key, const char *path, double lo, double hi,
                   int required, soak_rgb def, soak_rgb *out)
{
    char p[512];
    soak_status st;
    const cJSON *v = member(c, obj, key, path, required, p, &st);
    if (!v) {
        if (st == SOAK_OK) *out = def;
        return st;
    }
    if (cJSON_IsNumber(v)) {
        double x = 0;
        st = num_value(c, v, p, lo, hi, 0, &x);
        if (st == SOAK_OK) *out = soak_rgb3(x, x, x);
        return st;
    }
    double t[3];
    st = triple(c, v, p, lo, hi, t);
    if (st == SOAK_OK) *out = soak_rgb3(t[0], t[1], t[2]);
    return st;
}

soak_status sj_str(scene_ctx *c, const cJSON *obj, const char *key, const char *path, int required, const char **out)
{
    char p[512];
    soak_status st;
    const cJSON *v = member(c, obj, key, path, required, p, &st);
    *out = NULL;
    if (!v) return st;
    if (!cJSON_IsString(v) || !v->valuestring[0]) return sj_fail(c, SOAK_ERR_PARSE, p, "must be a non-empty string");
    *out = v->valuestring;
    return SOAK_OK;
}

soak_status sj_file(scene_ctx *c, const char *file, const char *path, char *out, size_t n)
{
    int w = file[0] == '/' || !c->base_dir[0] ? snprintf(out, n, "%s", file) : snprintf(out, n, "%s/%s", c->base_dir, file);
    if (w < 0 || (size_t)w >= n) return sj_fail(c, SOAK_ERR_ARG, path, "file name too long");
    soak_scene *s = c->scene;
    char **in = realloc(s->inputs, (size_t)(s->n_inputs + 1) * sizeof *in);
    if (!in) return SOAK_ERR_NOMEM;
    s->inputs = in;
    in[s->n_inputs] = strdup(out);
    if (!in[s->n_inputs]) return SOAK_ERR_NOMEM;
    s->n_inputs++;
    return SOAK_OK;
}

static void syntax_position(const char *text, const char *at, int *line, int *col)
{
    *line = 1;
    *col = 1;
    for (const char *p = text; p < at && *p; ++p) {
        if (*p == '\n') {
            ++*line;
            *col = 1;
        } else {
            ++*col;
        }
    }
}

/* Depth of open arrays/objects at position at (strings skipped). */
static int nesting_at(const char *text, const char *at)
{
    int depth = 0, max = 0, in_string = 0;
    for (const char *p = text; p < at && *p; ++p) {
        if (in_string) {
            if (*p == '\\' && p[1]) ++p;
            else if (*p == '"') in_string = 0;
        } else if (*p == '"') {
            in_string = 1;
        } else if (*p == '[' || *p == '{') {
            if (++depth > max) max = depth;
        } else if (*p == ']' || *p == '}') {
            --depth;
        }
    }
    return max;
}

/* 1 when the text at the error reads like NaN or Infinity. */
static int non_number_at(const char *at)
{
    while (*at == ' ' || *at == '\t' || *at == ':' || *at == '-' || *at == '+') ++at;
    return strncasecmp(at, "nan", 3) == 0 || strncasecmp(at, "inf", 3) == 0;
}

/* The first key that appears twice in one object, anywhere in the tree;
 * NULL when there is none. Pairwise within an object: objects here have a
 * handful of keys (arrays, which can be long, are only walked). */
static const char *duplicate_key_at(const cJSON *node, int depth)
{
    if (depth > CJSON_NESTING_LIMIT) return NULL;
    for (const cJSON *a = node ? node->child : NULL; a; a = a->next) {
        if (cJSON_IsObject(node) && a->string)
            for (const cJSON *b = a->next; b; b = b->next)
                if (b->string && strcmp(a->string, b->string) == 0) return a->string;
        const char *d = duplicate_key_at(a, depth + 1);
        if (d) return d;
    }
    return NULL;
}

const char *sj_duplicate_key(const cJSON *root) { return duplicate_key_at(root, 0); }

void sj_syntax_error(const char *text, const char *at, const char *name, char *err, size_t errlen)
{
    int line, col;
    syntax_position(text, at, &line, &col);
    if (!err || !errlen) return;
    if (nesting_at(text, at) >= CJSON_NESTING_LIMIT)
        snprintf(err, errlen, "%s: line %d, column %d: arrays and objects nested deeper than %d levels", name, line, col,
                 CJSON_NESTING_LIMIT);
    else
        snprintf(err, errlen, "%s: line %d, column %d: JSON syntax error%s", name, line, col,
                 non_number_at(at) ? " (NaN/Infinity are not JSON numbers)" : "");
}
