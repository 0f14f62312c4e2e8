/* Error codes shared by every public function of libsoak.
 * Public functions never abort and never return NaN/Inf: they validate their
 * inputs and report a soak_status; outputs are written only on SOAK_OK. */
#ifndef SOAK_STATUS_H
#define SOAK_STATUS_H

#include <stdarg.h>
#include <stddef.h>

typedef enum soak_status {
    SOAK_OK = 0,
    SOAK_ERR_ARG,         /* argument out of its documented range, NaN or Inf */
    SOAK_ERR_NULL,        /* required pointer was NULL */
    SOAK_ERR_IO,          /* file could not be read or written */
    SOAK_ERR_PARSE,       /* file content malformed */
    SOAK_ERR_NOT_FOUND,   /* named item (material, model, key) does not exist */
    SOAK_ERR_NOMEM,       /* allocation failed */
    SOAK_ERR_UNSUPPORTED, /* valid request the build cannot serve */
    SOAK_ERR_NUMERIC      /* internal computation failed to produce a finite value */
} soak_status;

const char *soak_status_str(soak_status s);

/* Makes an error message printable in place: control bytes other than
 * newline and tab (echoed from a malformed input: a key or a value) become
 * '?', so a message never carries terminal escapes or garbage. */
void soak_message_printable(char *msg);

/* The one form of an input error: "<file>: <where>: <message>" (": <where>"
 * left out when where is NULL or empty) into err (when err and errlen are
 * given), made printable; returns st so a parser can `return soak_error_at(...)`. */
__attribute__((format(printf, 6, 7))) soak_status soak_error_at(char *err, size_t errlen, soak_status st,
                                                                const char *file, const char *where, const char *fmt,
                                                                ...);
soak_status soak_verror_at(char *err, size_t errlen, soak_status st, const char *file, const char *where,
                           const char *fmt, va_list ap);

/* The range test used everywhere: false for NaN and +-Inf as well. */
static inline int soak_in_range(double x, double lo, double hi)
{
    return x >= lo && x <= hi;
}

static inline int soak_is_finite(double x)
{
    return x >= -1.7976931348623157e308 && x <= 1.7976931348623157e308;
}

#endif
