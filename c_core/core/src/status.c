#include "soak/status.h"

#include <stdio.h>

const char *soak_status_str(soak_status s)
{
    switch (s) {
    case SOAK_OK: return "ok";
    case SOAK_ERR_ARG: return "argument out of range (or NaN/Inf)";
    case SOAK_ERR_NULL: return "missing (NULL) argument";
    case SOAK_ERR_IO: return "input/output error";
    case SOAK_ERR_PARSE: return "malformed file";
    case SOAK_ERR_NOT_FOUND: return "not found";
    case SOAK_ERR_NOMEM: return "out of memory";
    case SOAK_ERR_UNSUPPORTED: return "not supported by this build";
    case SOAK_ERR_NUMERIC: return "numerical failure";
    }
    return "unknown status";
}

void soak_message_printable(char *msg)
{
    if (!msg) return;
    for (unsigned char *c = (unsigned char *)msg; *c; ++c)
        if ((*c < 0x20 && *c != '\n' && *c != '\t') || *c == 0x7f) *c = '?';
}

soak_status soak_verror_at(char *err, size_t errlen, soak_status st, const char *file, const char *where,
                           const char *fmt, va_list ap)
{
    if (!err || !errlen) return st;
    int has_where = where && where[0];
    int n = snprintf(err, errlen, "%s: %s%s", file ? file : "", has_where ? where : "", has_where ? ": " : "");
    if (n >= 0 && (size_t)n < errlen) vsnprintf(err + n, errlen - (size_t)n, fmt, ap);
    soak_message_printable(err);
    return st;
}

soak_status soak_error_at(char *err, size_t errlen, soak_status st, const char *file, const char *where,
                          const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    soak_verror_at(err, errlen, st, file, where, fmt, ap);
    va_end(ap);
    return st;
}
