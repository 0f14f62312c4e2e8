/* Soak's data folder: the material presets (materials.json), the export
 * schema, the measured data, the demo scene (scenes/) and the POV-Ray
 * includes (povray/). Installed as PREFIX/share/soak; in the source tree
 * its files live in c_core/data, scenes/ and povray/.
 *
 * Search order (the first folder holding materials.json wins):
 *   1. $SOAK_DATA_DIR, when set and not empty (and only there);
 *   2. share/soak beside the executable's folder: PREFIX/bin/soak reads
 *      PREFIX/share/soak, wherever PREFIX was installed or moved to;
 *   3. the source tree the program was built from, only for a program that
 *      runs from inside its build tree (the build's soak, tests, benchmarks):
 *      an installed or moved copy never reads the source tree.
 * Nothing found is an error naming every folder tried. */
#ifndef SOAK_DATA_DIR_H
#define SOAK_DATA_DIR_H

#include <stddef.h>

#include "soak/status.h"

/* The file that marks a data folder. */
#define SOAK_DATA_MARKER "materials.json"

/* Writes "<data folder>/<relative>" to out (relative: "materials.json",
 * "scenes/default_wet_dry.json", "povray/soak.inc", ...; in the source tree
 * "scenes/..." and "povray/..." map to the repository's folders of those
 * names, everything else to c_core/data). SOAK_ERR_NOT_FOUND when no data
 * folder is found, SOAK_ERR_ARG when the path does not fit in n bytes;
 * err (if non-NULL) then says why, naming the folders tried. The file
 * itself is not opened: its reader reports a missing or bad file. */
soak_status soak_data_path(const char *relative, char *out, size_t n, char *err, size_t errlen);

#endif
