/* soak export: the table of target writers and the atomic file output every
 * target shares (the writers' common header: export_header.c). */
#define _POSIX_C_SOURCE 200809L
#include "soak/export.h"

#include <stdlib.h>
#include <string.h>

#include "soak/staged_files.h"

static const soak_export_target targets[] = {
    {"json", "generic JSON interface (schema: c_core/data/export.schema.json)", "soak_export.json",
     soak_export_write_json},
    {"povray", "POV-Ray include with per-preset, per-liquid tables (povray/soak_materials.inc)", "soak_materials.inc",
     soak_export_write_povray},
    {"blender", "data shipped inside the Blender add-on (blender_addon/soak/)", "soak_data.json",
     soak_export_write_blender},
    {"osl", "OSL wet-surface shader for Cycles, Blender 3.4-4.x (osl/soak_wet_surface.osl)", "soak_wet_surface.osl",
     soak_export_write_osl},
    {"osl-legacy", "OSL wet-surface shader for Cycles, Blender 2.80-3.4 (osl/soak_wet_surface_legacy.osl)",
     "soak_wet_surface_legacy.osl", soak_export_write_osl_legacy},
    {"osl-sheet", "OSL wet thin-sheet shader for Cycles, Blender 2.80-4.x (osl/soak_wet_sheet.osl)",
     "soak_wet_sheet.osl", soak_export_write_osl_sheet},
    {"osl-wetmap", "OSL wet-map / drying shader (osl/soak_wetmap.osl)", "soak_wetmap.osl",
     soak_export_write_osl_wetmap},
    {"osl-math", "the OSL shaders' arithmetic as a header for your own shaders (osl/soak_wet_math.h)",
     "soak_wet_math.h", soak_export_write_osl_math},
};

const soak_export_target *soak_export_targets(int *count)
{
    if (count) *count = (int)(sizeof targets / sizeof targets[0]);
    return targets;
}

const soak_export_target *soak_export_find_target(const char *name)
{
    if (!name) return NULL;
    for (size_t i = 0; i < sizeof targets / sizeof targets[0]; ++i)
        if (strcmp(targets[i].name, name) == 0) return &targets[i];
    return NULL;
}

static soak_status write_all(const char *text, size_t len, FILE *f)
{
    if (len && fwrite(text, 1, len, f) != len) return SOAK_ERR_IO;
    return fflush(f) == 0 ? SOAK_OK : SOAK_ERR_IO;
}

soak_status soak_export_run(const soak_export_target *target, const soak_preset_db *db, const char *path, char *err,
                            size_t errlen)
{
    if (!target || !db || !err || !errlen) return SOAK_ERR_NULL;
    err[0] = '\0';
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    if (!mem) return SOAK_ERR_NOMEM;
    soak_status st = target->write(db, mem, err, errlen);
    if (fclose(mem) != 0 && st == SOAK_OK) st = SOAK_ERR_NOMEM;
    if (st != SOAK_OK) {
        free(text);
        return st;
    }
    if (!path || strcmp(path, "-") == 0) {
        st = write_all(text, len, stdout);
        if (st != SOAK_OK) snprintf(err, errlen, "writing to stdout failed");
        free(text);
        return st;
    }
    soak_staged staged;
    soak_staged_init(&staged);
    FILE *f = NULL;
    st = soak_staged_open(&staged, path, &f, err, errlen);
    if (st == SOAK_OK) {
        st = write_all(text, len, f);
        if (st != SOAK_OK) snprintf(err, errlen, "%s: write failed", path);
        soak_status cs = soak_staged_close(f, path, err, errlen);
        if (st == SOAK_OK) st = cs;
    }
    free(text);
    if (st == SOAK_OK) return soak_staged_commit(&staged, err, errlen);
    soak_staged_abort(&staged);
    return st;
}
