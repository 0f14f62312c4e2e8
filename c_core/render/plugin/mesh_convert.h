/* Files Assimp 5.2 misreads, turned into a text it reads (mesh_convert.c):
 * an OBJ in UTF-16 with a byte-order mark (Assimp reads the bytes as
 * UTF-8: no faces) and a glTF 1.0 binary file (KHR_binary_glTF; Assimp 5.2
 * reads glTF 1.0 only as .gltf). Private to libsoak_mesh.so. */
#ifndef SOAK_MESH_CONVERT_H
#define SOAK_MESH_CONVERT_H

#include <stddef.h>

typedef struct soak_mesh_text {
    char *data; /* malloc'ed */
    size_t size;
    const char *hint; /* Assimp's format hint for aiImportFileFromMemory */
} soak_mesh_text;

/* 1: path needs converting and *out holds the converted file; 0: read path
 * as it is; -1: it needs converting and cannot be (why says so). */
int soak_mesh_convert(const char *path, soak_mesh_text *out, char *why, size_t whylen);

#endif
