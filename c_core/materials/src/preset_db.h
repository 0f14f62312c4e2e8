/* The preset database's layout, private to the materials layer: the loader
 * (preset.c, the schema in preset_parse.c) fills it, preset_variant.c adds presets to it. */
#ifndef SOAK_PRESET_DB_H
#define SOAK_PRESET_DB_H

#include <cjson/cJSON.h>

#include "soak/json_read.h"
#include "soak/preset.h"

struct soak_preset_db {
    char *path;
    soak_preset *materials;
    int n_materials;
    soak_liquid *liquids;
    int n_liquids;
    char **strings; /* every string the presets point to */
    int n_strings, cap_strings;
};

/* Reads the parsed preset file `root` into the empty db (preset_parse.c);
 * messages through in. */
soak_status soak_preset_parse_root(const soak_json_in *in, const cJSON *root, soak_preset_db *db);

/* A copy of s owned by db (freed with it), in *out. SOAK_ERR_NOMEM. */
soak_status soak_preset_db_keep(soak_preset_db *db, const char *s, const char **out);

#endif
