/* The files a mesh names, checked before the reader opens them: a glTF's
 * or GLB's buffers (the "uri" of each buffer that is not a data: URI) and an OBJ's
 * material libraries ("mtllib" lines). Each must pass the input policy
 * (soak/input_file.h: a regular file; a FIFO would block Assimp's open
 * forever) and counts, with the mesh, against SOAK_MAX_MESH_MB; their
 * stored bytes size the reader's time and memory limits (mesh_contain.c).
 * A 419-byte glTF naming a 1.5 GB buffer drove the reader to 5.1 GB. */
#define _GNU_SOURCE
#include <ctype.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include <cjson/cJSON.h>

#include "mesh_import.h"
#include "soak/input_file.h"

#define GLTF_TEXT_MAX (64LL << 20) /* larger glTF JSON: mesh_check.c leaves it to Assimp as well */

/* Bytes of path that hold data (a sparse file's holes do not). */
static long long stored_bytes(const char *path)
{
    struct stat sb;
    if (stat(path, &sb) != 0) return 0;
    return soak_input_stored_bytes((long long)sb.st_size, (long long)sb.st_blocks);
}

/* One named file: resolved against the mesh's folder, checked, counted. */
static soak_status add_file(const char *mesh, const char *name, const char *what, int optional, soak_mesh_inputs *in,
                            char *err, size_t errlen)
{
    char full[4096], role[4200];
    const char *slash = strrchr(mesh, '/');
    if (name[0] == '/' || !slash) snprintf(full, sizeof full, "%s", name);
    else snprintf(full, sizeof full, "%.*s/%s", (int)(slash - mesh), mesh, name);
    struct stat sb;
    if (optional && stat(full, &sb) != 0 && errno == ENOENT) return SOAK_OK; /* Assimp only warns */
    snprintf(role, sizeof role, "%s named by %s", what, mesh);
    soak_status st = soak_input_check_part(full, SOAK_INPUT_MESH, role, &in->total_bytes, err, errlen);
    if (st == SOAK_OK) in->stored_bytes += stored_bytes(full);
    return st;
}

/* Every buffer "uri" of a glTF JSON text that is not a data: URI. */
static soak_status json_buffers(const char *path, const char *text, size_t n, soak_mesh_inputs *in, char *err,
                                size_t errlen)
{
    cJSON *j = cJSON_ParseWithLength(text, n);
    const cJSON *buffers = cJSON_GetObjectItemCaseSensitive(j, "buffers"), *b;
    soak_status st = SOAK_OK;
    cJSON_ArrayForEach(b, buffers)
    {
        const cJSON *uri = cJSON_GetObjectItemCaseSensitive(b, "uri");
        if (!cJSON_IsString(uri) || !strncmp(uri->valuestring, "data:", 5)) continue;
        st = add_file(path, uri->valuestring, "buffer", 0, in, err, errlen);
        if (st != SOAK_OK) break;
    }
    cJSON_Delete(j);
    return st;
}

static soak_status gltf_buffers(const char *path, soak_mesh_inputs *in, char *err, size_t errlen)
{
    char *text = NULL;
    size_t n = 0;
    if (in->total_bytes > GLTF_TEXT_MAX) return SOAK_OK;
    soak_status st = soak_input_read(path, SOAK_INPUT_MESH, &text, &n, err, errlen);
    if (st != SOAK_OK) return st;
    st = json_buffers(path, text, n, in, err, errlen);
    free(text);
    return st;
}

static uint32_t le32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

/* Binary glTF (GLB, glTF 2.0 sec. 4.4): a 12-byte header, then the JSON
 * chunk (length, type "JSON", text), whose buffers may name files as a
 * .gltf's do. A file that is not a GLB is left to the reader's own error. */
static soak_status glb_buffers(const char *path, soak_mesh_inputs *in, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) return SOAK_OK; /* the mesh itself was checked: reported by the reader */
    unsigned char head[20];
    soak_status st = SOAK_OK;
    if (fread(head, 1, sizeof head, f) == sizeof head && !memcmp(head, "glTF", 4) && !memcmp(head + 16, "JSON", 4)) {
        uint32_t n = le32(head + 12);
        char *text = n > 0 && (long long)n <= GLTF_TEXT_MAX && (long long)n + 20 <= in->total_bytes ? malloc(n) : NULL;
        if (text && fread(text, 1, n, f) == n) st = json_buffers(path, text, n, in, err, errlen);
        free(text);
    }
    fclose(f);
    return st;
}

static soak_status obj_materials(const char *path, soak_mesh_inputs *in, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) return SOAK_OK; /* the mesh itself was checked: reported by the reader */
    char line[4096];
    soak_status st = SOAK_OK;
    while (st == SOAK_OK && fgets(line, sizeof line, f)) {
        if (strncmp(line, "mtllib", 6) || !isspace((unsigned char)line[6])) continue;
        for (char *tok = strtok(line + 6, " \t\r\n"); tok && st == SOAK_OK; tok = strtok(NULL, " \t\r\n"))
            st = add_file(path, tok, "material library", 1, in, err, errlen);
    }
    fclose(f);
    return st;
}

soak_status soak_mesh_external_files(const char *path, soak_mesh_inputs *in, char *err, size_t errlen)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    const char *ext = dot && (!slash || dot > slash) ? dot + 1 : "";
    in->total_bytes = 0;
    in->stored_bytes = stored_bytes(path);
    soak_status st = soak_input_check_part(path, SOAK_INPUT_MESH, NULL, &in->total_bytes, err, errlen);
    if (st != SOAK_OK) return st;
    if (!strcasecmp(ext, "gltf")) return gltf_buffers(path, in, err, errlen);
    if (!strcasecmp(ext, "glb")) return glb_buffers(path, in, err, errlen);
    if (!strcasecmp(ext, "obj")) return obj_materials(path, in, err, errlen);
    return SOAK_OK;
}
