/* The preset database (soak/preset.h): where materials.json is, loading it
 * (the file read, its JSON syntax; the schema read by preset_parse.c),
 * freeing and looking up. Every error names the file. */
#define _POSIX_C_SOURCE 200809L
#include "soak/preset.h"

#include <cjson/cJSON.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "soak/data_dir.h"
#include "soak/input_file.h"
#include "soak/json_read.h"

#include "preset_db.h"

soak_status soak_presets_default_path(char *out, size_t n, char *err, size_t errlen)
{
    if (!out || n == 0) return SOAK_ERR_NULL;
    const char *env = getenv("SOAK_MATERIALS");
    if (!env || env[0] == '\0') return soak_data_path("materials.json", out, n, err, errlen);
    if (strlen(env) < n) {
        memcpy(out, env, strlen(env) + 1);
        return SOAK_OK;
    }
    if (err && errlen) snprintf(err, errlen, "SOAK_MATERIALS: the path is longer than %zu bytes", n - 1);
    return SOAK_ERR_ARG;
}

void soak_presets_free(soak_preset_db *db)
{
    if (!db) return;
    for (int i = 0; i < db->n_strings; ++i) free(db->strings[i]);
    free(db->strings);
    free(db->materials);
    free(db->liquids);
    free(db->path);
    free(db);
}

soak_status soak_presets_load(const char *path, soak_preset_db **out, char *err, size_t errlen)
{
    if (err && errlen) err[0] = '\0';
    if (!out) return SOAK_ERR_NULL;
    char default_path[SOAK_PRESETS_PATH_MAX];
    if (!path) {
        soak_status found = soak_presets_default_path(default_path, sizeof default_path, err, errlen);
        if (found != SOAK_OK) return found;
        path = default_path;
    }
    soak_json_in c = {path, err, errlen};
    char *text = NULL;
    size_t len = 0;
    /* soak/input_file.h: a regular file within SOAK_MAX_PRESETS_MB, read
     * without growing; the message names the file. */
    soak_status st = soak_input_read(path, SOAK_INPUT_PRESETS, &text, &len, err, errlen);
    if (st != SOAK_OK) return st;
    if (strlen(text) != len) {
        free(text);
        return soak_json_fail(&c, SOAK_ERR_PARSE, "", "contains a NUL byte");
    }
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithOpts(text, &end, 1);
    if (!root) {
        int line = 1, col = 1;
        for (const char *p = text; end && p < end && *p; ++p) {
            if (*p == '\n') {
                ++line;
                col = 1;
            } else {
                ++col;
            }
        }
        free(text);
        return soak_json_fail(&c, SOAK_ERR_PARSE, "", "JSON syntax error at line %d, column %d", line, col);
    }
    free(text);
    soak_preset_db *db = calloc(1, sizeof *db);
    if (!db) {
        cJSON_Delete(root);
        return soak_json_fail(&c, SOAK_ERR_NOMEM, "", "out of memory");
    }
    db->path = strdup(path);
    st = db->path ? soak_preset_parse_root(&c, root, db) : soak_json_fail(&c, SOAK_ERR_NOMEM, "", "out of memory");
    cJSON_Delete(root);
    if (st != SOAK_OK) {
        soak_presets_free(db);
        return st;
    }
    *out = db;
    return SOAK_OK;
}

const char *soak_presets_path(const soak_preset_db *db) { return db ? db->path : NULL; }
int soak_presets_count(const soak_preset_db *db) { return db ? db->n_materials : 0; }
int soak_presets_liquid_count(const soak_preset_db *db) { return db ? db->n_liquids : 0; }

const soak_preset *soak_presets_at(const soak_preset_db *db, int index)
{
    return db && index >= 0 && index < db->n_materials ? &db->materials[index] : NULL;
}

const soak_liquid *soak_presets_liquid_at(const soak_preset_db *db, int index)
{
    return db && index >= 0 && index < db->n_liquids ? &db->liquids[index] : NULL;
}

const soak_preset *soak_presets_find(const soak_preset_db *db, const char *name)
{
    if (!db || !name) return NULL;
    for (int i = 0; i < db->n_materials; ++i)
        if (strcmp(db->materials[i].name, name) == 0) return &db->materials[i];
    return NULL;
}

const soak_liquid *soak_presets_find_liquid(const soak_preset_db *db, const char *name)
{
    if (!db || !name) return NULL;
    for (int i = 0; i < db->n_liquids; ++i)
        if (strcmp(db->liquids[i].name, name) == 0) return &db->liquids[i];
    return NULL;
}
