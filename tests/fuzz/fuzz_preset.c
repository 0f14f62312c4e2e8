/* Preset database loader (soak_presets_load). */
#include <stdlib.h>

#include "fuzz_common.h"
#include "soak/preset.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 1 << 20) return 0;
    const char *path = fuzz_temp_file(data, size, "json");
    if (!path) return 0;
    soak_preset_db *db = NULL;
    char err[1024] = "";
    if (soak_presets_load(path, &db, err, sizeof err) == SOAK_OK) soak_presets_free(db);
    else fuzz_check_message(err, path, NULL);
    return 0;
}
