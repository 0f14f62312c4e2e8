/* Loadable modules for the heavy I/O libraries. OpenImageIO (which brings
 * GDAL, ffmpeg, DICOM, ...: 260 shared libraries), OpenVDB and Assimp live in
 * shared modules next to the `soak` executable (libsoak_image.so,
 * libsoak_vdb.so, libsoak_mesh.so), opened on a command's first image,
 * volume or mesh; a command that touches none of them maps none of them.
 *
 * A module is looked for, in order:
 *   1. in $SOAK_PLUGIN_DIR, when set (and only there);
 *   2. in the folder of the file holding libsoak's code: the executable,
 *      found through /proc/self/maps, which names it also when the program
 *      was started through an explicit loader (`ld-linux.so --library-path
 *      ... soak`, as the Blender 4.3 tests do; /proc/self/exe then names the
 *      loader), then the folder of /proc/self/exe;
 *   3. in lib/soak beside the executable's folder (an installed copy:
 *      PREFIX/bin/soak, PREFIX/lib/soak/libsoak_image.so);
 *   4. in the build tree's bin/ folder (tests and benchmarks live elsewhere).
 * A module that is found but does not load (a library it needs is missing)
 * is an error naming the module and the loader's reason; so is a module
 * found nowhere, naming every folder searched. */
#ifndef SOAK_PLUGIN_H
#define SOAK_PLUGIN_H

#include <pthread.h>
#include <stddef.h>

#include "soak/status.h"

/* One module and its table: filled once per process (pthread_once), then
 * read-only. The dlopen'ed module is process-wide state by nature (the
 * loader keeps it until exit whatever we store), so one slot per module
 * avoids a context argument on every image, volume and mesh function of
 * the public API (whose callers are in every layer above). */
typedef struct soak_plugin_slot {
    pthread_once_t once;
    const char *file;   /* "libsoak_image.so" */
    const char *symbol; /* the table the module exports */
    const char *what;   /* "image I/O (OpenImageIO)" for messages */
    const void *table;  /* set by soak_plugin_slot_fill when the module loaded */
    soak_status status;
    char message[1536];
} soak_plugin_slot;

#define SOAK_PLUGIN_SLOT(file, symbol, what) {PTHREAD_ONCE_INIT, file, symbol, what, NULL, SOAK_OK, ""}

/* Opens the slot's module and looks up its table; call only through
 * pthread_once(&slot->once, ...). */
void soak_plugin_slot_fill(soak_plugin_slot *slot);
/* The slot's table, or NULL with the load error copied to err. */
const void *soak_plugin_slot_table(const soak_plugin_slot *slot, char *err, size_t errlen);

#endif
