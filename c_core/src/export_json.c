/* soak export --target json: the generic interface (written below). */
#include <stdio.h>

#include "soak/export.h"

soak_status soak_export_write_json(const soak_preset_db *db, FILE *out, char *err, size_t errlen)
{
    (void)db;
    (void)out;
    snprintf(err, errlen, "target 'json' is being written");
    return SOAK_ERR_UNSUPPORTED;
}
