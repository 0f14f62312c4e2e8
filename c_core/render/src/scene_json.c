/* JSON access for the scene parser (scene_json.h) through the reader every
 * JSON file of soak shares (soak/json_read.h: "<file>: <json path>:
 * <reason>", each reason worded once), and the messages for text that is
 * not JSON. */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "scene_json.h"
#include "soak/json_read.h"

/* The scene's file and message buffer as the shared JSON reader sees them. */
static soak_json_in in_of(const scene_ctx *c) { return (soak_json_in){c->name, c->err, c->errlen}; }

soak_status sj_fail(scene_ctx *c, soak_status status, const char *path, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    soak_verror_at(c->err, c->errlen, status, c->name, path, fmt, ap);
    va_end(ap);
    return status;
}

void sj_path(char *buf, size_t n, const char *parent, const char *key) { soak_json_path(buf, n, parent, key); }

void sj_index(char *buf, size_t n, const char *parent, int i) { soak_json_index(buf, n, parent, i); }

soak_status sj_keys(scene_ctx *c, const cJSON *obj, const char *path, const char *const *allowed)
{
    soak_json_in in = in_of(c);
    return soak_json_keys(&in, obj, path, allowed, NULL, NULL, 0);
}

soak_status sj_num(scene_ctx *c, const cJSON *obj, const char *key, const char *path, double lo, double hi,
                   int required, double def, double *out)
{
    soak_json_in in = in_of(c);
    return soak_json_get_number(&in, obj, key, path, lo, hi, 0, required, def, out);
}

soak_status sj_num_gt(scene_ctx *c, const cJSON *obj, const char *key, const char *path, double lo, double hi,
                      int required, double def, double *out)
{
    soak_json_in in = in_of(c);
    return soak_json_get_number(&in, obj, key, path, lo, hi, 1, required, def, out);
}

soak_status sj_vec3(scene_ctx *c, const cJSON *obj, const char *key, const char *path, int required, soak_vec3 def,
                    soak_vec3 *out)
{
    soak_json_in in = in_of(c);
    double d[3] = {def.x, def.y, def.z}, t[3];
    soak_status st = soak_json_get_triple(&in, obj, key, path, -1e12, 1e12, 0, required, d, "x, y, z", t);
    if (st == SOAK_OK) *out = soak_v3(t[0], t[1], t[2]);
    return st;
}

soak_status sj_rgb(scene_ctx *c, const cJSON *obj, const char *key, const char *path, double lo, double hi,
                   int required, soak_rgb def, soak_rgb *out)
{
    soak_json_in in = in_of(c);
    return soak_json_get_rgb(&in, obj, key, path, lo, hi, 1, required, def, out);
}

soak_status sj_str(scene_ctx *c, const cJSON *obj, const char *key, const char *path, int required, const char **out)
{
    soak_json_in in = in_of(c);
    return soak_json_get_string(&in, obj, key, path, required, out);
}

soak_status sj_file(scene_ctx *c, const char *file, const char *path, char *out, size_t n)
{
    int w =
        file[0] == '/' || !c->base_dir[0] ? snprintf(out, n, "%s", file) : snprintf(out, n, "%s/%s", c->base_dir, file);
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
        snprintf(err, errlen, "%s: line %d, column %d: arrays and objects nested deeper than %d levels", name, line,
                 col, CJSON_NESTING_LIMIT);
    else
        snprintf(err, errlen, "%s: line %d, column %d: JSON syntax error%s", name, line, col,
                 non_number_at(at) ? " (NaN/Infinity are not JSON numbers)" : "");
}
