/* The two halves of soak_mesh_load: the Assimp import itself (run in a
 * child process by mesh_contain.c, and called directly by the fuzzer) and
 * the checks on what comes back. */
#ifndef SOAK_MESH_IMPORT_H
#define SOAK_MESH_IMPORT_H

#include <stdio.h>

#include "soak/geometry.h"
#include "mesh_plugin.h"

/* Assimp import in this process, validated. No containment: a malformed
 * file may crash or hang it. Opens libsoak_mesh.so on first use. */
soak_status soak_mesh_import(const char *path, int require_uvs, soak_mesh *mesh, char *err, size_t errlen);
/* The same with a choice of UV set (mesh_plugin.h). */
soak_status soak_mesh_import_rq(const char *path, const soak_mesh_request *rq, soak_mesh *mesh, char *err,
                                size_t errlen);
/* Opens libsoak_mesh.so (Assimp) if it is not open yet: an error naming
 * path and the module when it cannot be loaded. */
soak_status soak_mesh_reader_open(const char *path, char *err, size_t errlen);
/* Rejects (and frees) a mesh with a non-finite coordinate or an index past
 * its vertices, naming path and the first offender. */
soak_status soak_mesh_validate(soak_mesh *m, const char *path, char *err, size_t errlen);
/* Structural checks of the header (and for OBJ the face indices) of an
 * open mesh file of size bytes, by path's extension (mesh_check.c): refuses
 * a file whose header is incomplete or claims more than the file holds. */
soak_status soak_mesh_check_file(const char *path, FILE *f, long long size, char *err, size_t errlen);
/* A mesh file and the files it names (glTF buffers, OBJ material
 * libraries, mesh_external.c). */
typedef struct soak_mesh_inputs {
    long long total_bytes;  /* their sizes, counted against SOAK_MAX_MESH_MB */
    long long stored_bytes; /* their bytes that hold data (not a sparse file's holes): sizes the reader's limits */
} soak_mesh_inputs;
/* Checks every file the mesh at path names against the input policy
 * (soak/input_file.h) and adds up their sizes. */
soak_status soak_mesh_external_files(const char *path, soak_mesh_inputs *in, char *err, size_t errlen);
/* 1 when path's extension is a mesh format Soak accepts; 0 with the
 * reason in why (mesh_formats.c). */
int soak_mesh_format_ok(const char *path, char *why, size_t whylen);

#endif
