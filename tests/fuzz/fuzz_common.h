/* Shared pieces of the fuzz targets: each target defines
 * LLVMFuzzerTestOneInput; replay_main.c runs it over stored inputs in every
 * build, libFuzzer drives it in `make fuzz`. */
#ifndef SOAK_FUZZ_COMMON_H
#define SOAK_FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Writes data to "<private temp folder>/in.<ext>" and returns that path
 * (static storage, overwritten by the next call); NULL on failure. */
const char *fuzz_temp_file(const uint8_t *data, size_t size, const char *ext);
/* The same for "<private temp folder>/<name>" (at most 8 names in use; each
 * name's path stays valid until the process ends). */
const char *fuzz_temp_named(const char *name, const uint8_t *data, size_t size);
/* The private temp folder itself. */
const char *fuzz_temp_dir(void);

/* Every failure path sets its message (issue 21 item 5): aborts unless err
 * is non-empty, printable (no control bytes but newline and tab -- OIIO's
 * messages span lines; UTF-8 above 0x7f allowed) and
 * names the file: path or, when not NULL, other. */
void fuzz_check_message(const char *err, const char *path, const char *other);
/* The same for text inputs without a file name: err must name a field or
 * the position (contain a quote, a dot path, "line" or "offset"). */
void fuzz_check_message_text(const char *err);

#endif
