/* No command writes over one of its own inputs.
 *
 * A command lists every file it will read (scene, presets file including the
 * SOAK_MATERIALS default, maps, meshes, volumes, start maps) and every file
 * it will write (each file of a multi-file output) before it starts work;
 * soak_io_guard_check then compares them by device and inode, so a symbolic
 * link or a hard link to an input is caught as well as the same name. An
 * output that does not exist yet cannot be an input. The message names the
 * output and the input with their roles (option names). */
#ifndef SOAK_IO_GUARD_H
#define SOAK_IO_GUARD_H

#include <stddef.h>

#include "soak/status.h"

typedef struct soak_io_file {
    char *path;
    char *role; /* "--materials", "-o", "scene file", ... */
    int output;
} soak_io_file;

typedef struct soak_io_guard {
    int count, capacity;
    soak_io_file *files;
} soak_io_guard;

void soak_io_guard_init(soak_io_guard *g);
/* Records an input or output (NULL or empty path: ignored). SOAK_ERR_NOMEM
 * on allocation failure. */
soak_status soak_io_guard_input(soak_io_guard *g, const char *role, const char *path);
soak_status soak_io_guard_output(soak_io_guard *g, const char *role, const char *path);
/* SOAK_ERR_ARG with "<role> '<out>' is the same file as the input <role>
 * '<in>'; refusing to overwrite it" when an existing output is an input (or
 * two outputs are the same file), else SOAK_OK. */
soak_status soak_io_guard_check(const soak_io_guard *g, char *err, size_t errlen);
void soak_io_guard_free(soak_io_guard *g);

/* One-call form for a single output against a list of inputs. */
soak_status soak_io_check_output(const char *role, const char *output, const char *const *inputs, int n_inputs,
                                 char *err, size_t errlen);

#endif
