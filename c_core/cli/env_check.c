/* Every environment variable soak reads, parsed like an option before any
 * command runs (issue 51 item 6): a malformed or out-of-range value is an
 * error naming the variable, never silently replaced by the default. The
 * library's readers (input_file.c, memory_budget.c, child_process.c,
 * mesh_contain.c, image_contain.c, args.c) accept the same ranges. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

typedef enum { ENV_NUMBER, ENV_FLAG, ENV_PATH, ENV_WORD } env_kind;

typedef struct env_var {
    const char *name;
    env_kind kind;
    double lo, hi; /* ENV_NUMBER: lo < value <= hi when lo_open, else lo <= value <= hi */
    int lo_open;
    const char *help;
} env_var;

static const env_var vars[] = {
    {"SOAK_DATA_DIR", ENV_PATH, 0, 0, 0, "the data folder (above)"},
    {"SOAK_MATERIALS", ENV_PATH, 0, 0, 0, "the presets file (default: materials.json of the data folder)"},
    {"SOAK_PLUGIN_DIR", ENV_PATH, 0, 0, 0, "the folder of the I/O modules (default: beside soak, or PREFIX/lib/soak)"},
    {"SOAK_HDRI_DIR", ENV_PATH, 0, 0, 0,
     "the folder of a scene's named environments (\"hdri\": \"NAME\" reads NAME.exr;\ndefault: Blender's "
     "/usr/share/blender/datafiles/studiolights/world)"},
    {"SOAK_PROGRESS", ENV_FLAG, 0, 1, 0, "1: progress bars even when stderr is not a terminal"},
    {"SOAK_IMAGE_IN_PROCESS", ENV_FLAG, 0, 1, 0,
     "1: decode images inside soak, without the contained reader process\n"
     "(faster; a decoder crash or hang then takes soak with it)"},
    {"SOAK_MAX_SCENE_MB", ENV_NUMBER, 1, 1e7, 0, "cap on a scene file, MiB (default 16)"},
    {"SOAK_MAX_PRESETS_MB", ENV_NUMBER, 1, 1e7, 0, "cap on a presets file, MiB (default 16)"},
    {"SOAK_MAX_IMAGE_MB", ENV_NUMBER, 1, 1e7, 0, "cap on an image file, MiB (default 2048)"},
    {"SOAK_MAX_MESH_MB", ENV_NUMBER, 1, 1e7, 0, "cap on a mesh and its files, MiB (default 2048)"},
    {"SOAK_MAX_VOLUME_MB", ENV_NUMBER, 1, 1e7, 0, "cap on a volume file, MiB (default 8192)"},
    {"SOAK_MAX_MEMORY_MB", ENV_NUMBER, 64, 1e7, 0, "working memory of a bake, MiB (default: see above)"},
    {"SOAK_MESH_MEMORY_MB", ENV_NUMBER, 64, 1e7, 0, "memory of the mesh reader process, MiB"},
    {"SOAK_MAX_BAKE_S", ENV_NUMBER, 0, 1e9, 1,
     "estimated work of a drops, ripples or rain bake, s on one\ncore (default 10 + 2e-6 per output texel)"},
    {"SOAK_MESH_TIMEOUT", ENV_NUMBER, 0, 1e6, 1, "time of the mesh reader process, s"},
    {"SOAK_MESH_READER", ENV_WORD, 0, 0, 0,
     "auto (default): plain OBJ, PLY and STL read by soak's own reader, the rest\nby "
     "Assimp; assimp: every mesh by Assimp (both in the contained reader)"},
    {"SOAK_IMAGE_TIMEOUT", ENV_NUMBER, 0, 1e6, 1, "time of the image reader process, s"},
};

/* The values an ENV_WORD variable takes, "a|b". */
static const char *words_of(const env_var *v) { return !strcmp(v->name, "SOAK_MESH_READER") ? "auto|assimp" : ""; }

static int valid(const env_var *v, const char *value)
{
    if (v->kind == ENV_PATH) return 1;
    if (v->kind == ENV_WORD) {
        size_t n = strlen(value);
        for (const char *w = words_of(v); w && !strchr(value, '|'); w = strchr(w, '|') ? strchr(w, '|') + 1 : NULL)
            if (!strncmp(w, value, n) && (w[n] == '|' || w[n] == '\0')) return 1;
        return 0;
    }
    if (v->kind == ENV_FLAG) return !strcmp(value, "0") || !strcmp(value, "1");
    char *end = NULL;
    double x = strtod(value, &end);
    if (end == value || *end != '\0' || !isfinite(x)) return 0;
    return (v->lo_open ? x > v->lo : x >= v->lo) && x <= v->hi;
}

int cli_check_environment(void)
{
    for (size_t i = 0; i < sizeof vars / sizeof vars[0]; ++i) {
        const env_var *v = &vars[i];
        const char *value = getenv(v->name);
        if (!value || !*value || valid(v, value)) continue;
        char shown[64];
        snprintf(shown, sizeof shown, "%s", value);
        for (char *c = shown; *c; ++c)
            if ((unsigned char)*c < 0x20 || *c == 0x7f) *c = '?';
        if (v->kind == ENV_FLAG)
            fprintf(stderr, "soak: %s='%s': expected 0 or 1 (unset it for the default)\n", v->name, shown);
        else if (v->kind == ENV_WORD)
            fprintf(stderr, "soak: %s='%s': expected one of %s (unset it for the default)\n", v->name, shown,
                    words_of(v));
        else
            fprintf(stderr, "soak: %s='%s': expected a plain number in %s%g, %g] (no unit; unset it for the default)\n",
                    v->name, shown, v->lo_open ? "(" : "[", v->lo, v->hi);
        return SOAK_EXIT_USAGE;
    }
    return 0;
}

void cli_environment_help(FILE *out)
{
    fprintf(out, "\nenvironment (a malformed or out-of-range value is an error; empty = unset):\n");
    for (size_t i = 0; i < sizeof vars / sizeof vars[0]; ++i) {
        const env_var *v = &vars[i];
        char range[64] = "";
        if (v->kind == ENV_NUMBER) snprintf(range, sizeof range, " %s%g, %g]", v->lo_open ? "(" : "[", v->lo, v->hi);
        if (v->kind == ENV_WORD) snprintf(range, sizeof range, " %s", words_of(v));
        fprintf(out, "  %s%s\n", v->name, range);
        for (const char *line = v->help; *line;) {
            const char *nl = strchr(line, '\n');
            int n = nl ? (int)(nl - line) : (int)strlen(line);
            fprintf(out, "      %.*s\n", n, line);
            line += n + (nl ? 1 : 0);
        }
    }
}
