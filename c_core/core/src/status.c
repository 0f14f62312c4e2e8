#include "soak/status.h"

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
