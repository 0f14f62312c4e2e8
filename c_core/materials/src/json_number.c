#include "soak/json_number.h"

#include <stdio.h>

#include "soak/status.h"

static const char *json_type_name(const cJSON *v)
{
    if (!v) return "nothing";
    if (cJSON_IsString(v)) return "a string";
    if (cJSON_IsBool(v)) return "a boolean";
    if (cJSON_IsNull(v)) return "null";
    if (cJSON_IsArray(v)) return "an array";
    if (cJSON_IsObject(v)) return "an object";
    return "another JSON type";
}

static int in_bounds(double x, double lo, double hi, int lo_open)
{
    return soak_in_range(x, lo, hi) && (!lo_open || x > lo);
}

soak_status soak_json_number(const cJSON *v, double lo, double hi, int lo_open, double *out, char *why,
                             size_t why_len)
{
    if (!cJSON_IsNumber(v)) {
        snprintf(why, why_len, "must be a number, got %s", json_type_name(v));
        return SOAK_ERR_PARSE;
    }
    double x = v->valuedouble;
    if (!soak_is_finite(x)) {
        snprintf(why, why_len, "must be a finite number");
        return SOAK_ERR_ARG;
    }
    if (!in_bounds(x, lo, hi, lo_open)) {
        snprintf(why, why_len, lo_open ? "must be > %g and <= %g, got %.10g" : "must be in [%g, %g], got %.10g", lo,
                 hi, x);
        return SOAK_ERR_ARG;
    }
    *out = x;
    return SOAK_OK;
}
