/* soak export --target povray: not written yet (front-end issue). */
#include <stdio.h>

#include "soak/export.h"

soak_status soak_export_write_povray(const soak_preset_db *db, FILE *out, char *err, size_t errlen)
{
    (void)db;
    (void)out;
    snprintf(err, errlen, "target 'povray' is not implemented yet");
    return SOAK_ERR_UNSUPPORTED;
}
