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
/* The private temp folder itself. */
const char *fuzz_temp_dir(void);

#endif
