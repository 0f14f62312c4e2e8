/* String literals for generated source (issue 51 item 2): every string from
 * outside (a file name, a preset or liquid name) that a writer puts into a
 * POV-Ray, OSL, Python or JavaScript file goes through the function of that
 * language, so that no byte of it can end the literal, start a directive or
 * a line, or splice one.
 *
 * Each function writes the literal's body (without the surrounding double
 * quotes) to dst, NUL-terminated, and fails with SOAK_ERR_NOMEM when dst is
 * too small (SOAK_ESCAPE_SIZE(n) bytes always suffice for an n-byte input)
 * or SOAK_ERR_ARG when the language cannot hold the text (Python and
 * JavaScript: bytes that are not UTF-8). The body also holds no newline, so
 * it may stand in a line comment of its language. */
#ifndef SOAK_EXPORT_ESCAPE_H
#define SOAK_EXPORT_ESCAPE_H

#include <stddef.h>

#include "soak/status.h"

/* Worst case: six output bytes per input byte (\u00XX), plus the NUL. */
#define SOAK_ESCAPE_SIZE(n) (6 * (size_t)(n) + 1)

/* POV-Ray 3.7: \" and \\; every control byte and DEL as \u00XX (POV-Ray's
 * string escapes, verified with povray 3.7.0.10); other bytes as they are. */
soak_status soak_escape_povray(const char *s, char *dst, size_t cap);

/* OSL (C-like): \" \\ \n \t, every other control byte and DEL as a
 * three-digit octal escape; other bytes as they are. */
soak_status soak_escape_osl(const char *s, char *dst, size_t cap);

/* Python 3 str literal (double-quoted): \" \' \\ \n \r \t, other control
 * bytes and DEL as \xHH; UTF-8 sequences as they are, anything else refused. */
soak_status soak_escape_python(const char *s, char *dst, size_t cap);

/* JavaScript string literal (double-quoted): \" \' \\ \n \r \t, other
 * control bytes, DEL, U+2028 and U+2029 as \uXXXX; UTF-8 sequences as they
 * are, anything else refused. */
soak_status soak_escape_javascript(const char *s, char *dst, size_t cap);

#endif
