/* Private helpers of the scene parser (scene_json.c): JSON access with
 * error messages of the form "<file>: <json path>: <reason>", and the
 * messages for text that is not JSON. */
#ifndef SOAK_SCENE_JSON_H
#define SOAK_SCENE_JSON_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "soak/scene.h"

typedef struct scene_ctx {
    const char *name;     /* file name for messages */
    const char *base_dir; /* folder for relative paths */
    char *err;
    size_t errlen;
    soak_scene *scene;
    /* The presets (materials.json), loaded by the first preset material and
     * shared by every later one and by the levels (scene_presets_db); the
     * parser frees it. NULL until then. */
    struct soak_preset_db *db;
} scene_ctx;

/* Formats the message and returns status. */
soak_status sj_fail(scene_ctx *c, soak_status status, const char *path, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* Every key of obj must be in the NULL-terminated list. obj must be an object. */
soak_status sj_keys(scene_ctx *c, const cJSON *obj, const char *path, const char *const *allowed);
/* Number in [lo, hi]; missing -> def (or an error when required). */
soak_status sj_num(scene_ctx *c, const cJSON *obj, const char *key, const char *path, double lo, double hi,
                   int required, double def, double *out);
/* Like sj_num but ] lo, hi ] (strictly above lo). */
soak_status sj_num_gt(scene_ctx *c, const cJSON *obj, const char *key, const char *path, double lo, double hi,
                      int required, double def, double *out);
/* [x, y, z], finite. */
soak_status sj_vec3(scene_ctx *c, const cJSON *obj, const char *key, const char *path, int required, soak_vec3 def,
                    soak_vec3 *out);
/* Colour: [r, g, b] or one number for grey, each in [lo, hi]. */
soak_status sj_rgb(scene_ctx *c, const cJSON *obj, const char *key, const char *path, double lo, double hi,
                   int required, soak_rgb def, soak_rgb *out);
/* String; *out NULL when absent and not required. */
soak_status sj_str(scene_ctx *c, const cJSON *obj, const char *key, const char *path, int required, const char **out);
/* Child path "parent.key" / "parent[i]". */
void sj_path(char *buf, size_t n, const char *parent, const char *key);
void sj_index(char *buf, size_t n, const char *parent, int i);
/* Resolves a relative file name against base_dir and records it as an input. */
soak_status sj_file(scene_ctx *c, const char *file, const char *path, char *out, size_t n);

/* The message for text cJSON could not parse, stopped at `at`:
 * "<name>: line L, column C: JSON syntax error" (naming NaN/Infinity when
 * the text there reads like them, or the nesting limit when it is passed). */
void sj_syntax_error(const char *text, const char *at, const char *name, char *err, size_t errlen);
/* The first key that appears twice in one object anywhere in the tree;
 * NULL when there is none. */
const char *sj_duplicate_key(const cJSON *root);

#endif
