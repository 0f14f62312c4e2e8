/* soak/json_writer.h: deterministic JSON through cJSON. */
#include "soak/json_writer.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

double soak_json_round(const soak_json *j, double x)
{
    if (fabs(x) < j->zero_below) return 0.0;
    if (j->digits <= 0 || !isfinite(x)) return x;
    char buf[48];
    snprintf(buf, sizeof buf, "%.*g", j->digits, x);
    return strtod(buf, NULL);
}

static cJSON *attach(soak_json *j, cJSON *parent, const char *key, cJSON *item)
{
    if (item && parent && (key ? cJSON_AddItemToObject(parent, key, item) : cJSON_AddItemToArray(parent, item)))
        return item;
    cJSON_Delete(item);
    j->ok = 0;
    return NULL;
}

cJSON *soak_json_num(soak_json *j, cJSON *parent, const char *key, double v)
{
    return attach(j, parent, key, cJSON_CreateNumber(soak_json_round(j, v)));
}

cJSON *soak_json_int(soak_json *j, cJSON *parent, const char *key, int v)
{
    return attach(j, parent, key, cJSON_CreateNumber((double)v));
}

cJSON *soak_json_str(soak_json *j, cJSON *parent, const char *key, const char *v)
{
    return attach(j, parent, key, cJSON_CreateString(v ? v : ""));
}

cJSON *soak_json_bool(soak_json *j, cJSON *parent, const char *key, int v)
{
    return attach(j, parent, key, cJSON_CreateBool(v ? 1 : 0));
}

cJSON *soak_json_rgb(soak_json *j, cJSON *parent, const char *key, soak_rgb c)
{
    cJSON *a = soak_json_array(j, parent, key);
    for (int i = 0; a && i < 3; ++i) soak_json_num(j, a, NULL, soak_rgb_at(c, i));
    return a;
}

cJSON *soak_json_array(soak_json *j, cJSON *parent, const char *key)
{
    return attach(j, parent, key, cJSON_CreateArray());
}

cJSON *soak_json_object(soak_json *j, cJSON *parent, const char *key)
{
    return attach(j, parent, key, cJSON_CreateObject());
}

soak_status soak_json_print(const soak_json *j, const cJSON *root, char **text)
{
    if (!j || !root || !text) return SOAK_ERR_NULL;
    *text = NULL;
    if (!j->ok) return SOAK_ERR_NOMEM;
    *text = cJSON_Print(root);
    return *text ? SOAK_OK : SOAK_ERR_NOMEM;
}

soak_status soak_json_write(const soak_json *j, const cJSON *root, FILE *out)
{
    if (!out) return SOAK_ERR_NULL;
    char *text = NULL;
    soak_status st = soak_json_print(j, root, &text);
    if (st != SOAK_OK) return st;
    int bad = fputs(text, out) < 0 || fputc('\n', out) == EOF;
    free(text);
    return bad ? SOAK_ERR_IO : SOAK_OK;
}
