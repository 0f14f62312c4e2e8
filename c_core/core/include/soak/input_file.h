/* One policy for every file soak reads (scenes, presets, grid headers,
 * images, meshes and the files they name, volumes):
 *  - it must be a regular file (after following symbolic links): a folder,
 *    FIFO, socket or device (/dev/stdin, /dev/zero) is refused by what it
 *    is, before anything could block on it or read it without end;
 *  - it is opened without blocking, and checked again on the open file;
 *  - it may hold at most the cap of its kind (README "Outputs and inputs";
 *    each kind's environment variable raises it, in MiB);
 *  - a read into memory stops at the file's size: a file that grows or
 *    shrinks while it is read is an error, never a larger buffer;
 *  - every failure sets a message that names the file and the kind.
 * The readers that hand a path to a library (images, meshes, volumes) call
 * soak_input_check first; the ones that parse text read it through
 * soak_input_read. */
#ifndef SOAK_INPUT_FILE_H
#define SOAK_INPUT_FILE_H

#include <stddef.h>

#include "soak/status.h"

typedef enum soak_input_kind {
    SOAK_INPUT_SCENE,   /* scene JSON, and JSON files a scene names (grid headers): 16 MiB, SOAK_MAX_SCENE_MB */
    SOAK_INPUT_PRESETS, /* materials.json (--materials, SOAK_MATERIALS): 16 MiB, SOAK_MAX_PRESETS_MB */
    SOAK_INPUT_IMAGE,   /* maps, masks, environment images: 2048 MiB, SOAK_MAX_IMAGE_MB */
    SOAK_INPUT_MESH,    /* a mesh with every file it names (glTF buffers, OBJ materials): 2048 MiB, SOAK_MAX_MESH_MB */
    SOAK_INPUT_VOLUME,  /* df3, grid payloads, OpenVDB: 8192 MiB (a grid at the voxel limit), SOAK_MAX_VOLUME_MB */
    SOAK_INPUT_KINDS
} soak_input_kind;

/* The kind's name in messages ("scene file", ...). */
const char *soak_input_kind_name(soak_input_kind kind);
/* The kind's environment variable ("SOAK_MAX_SCENE_MB", ...). */
const char *soak_input_kind_env(soak_input_kind kind);
/* The kind's cap in bytes: its environment variable when set to a number of
 * MiB in [1, 1e7], else the default above. */
long long soak_input_cap(soak_input_kind kind);

/* Checks path against the policy without reading it: SOAK_ERR_IO when it
 * does not exist, is not a regular file or cannot be opened; SOAK_ERR_ARG
 * when it is larger than the cap. *size (may be NULL) gets its size. */
soak_status soak_input_check(const char *path, soak_input_kind kind, long long *size, char *err, size_t errlen);
/* The same, for a file counted together with others against one cap (a
 * mesh and the buffers it names): *total is increased by the file's size
 * and compared with the cap; role names it in messages ("buffer of
 * 'x.gltf'"). */
soak_status soak_input_check_part(const char *path, soak_input_kind kind, const char *role, long long *total,
                                  char *err, size_t errlen);

/* Bytes of a file of size bytes and blocks 512-byte blocks that hold data:
 * a sparse file's holes do not (its zeros are no compressed pixels and no
 * mesh). Files up to 64 KiB count whole (some file systems store small
 * files inline, without blocks). */
long long soak_input_stored_bytes(long long size, long long blocks);

/* Reads the whole of path into a malloc'ed buffer with a terminating zero
 * byte (*text, *n bytes before it), after soak_input_check. SOAK_ERR_NOMEM
 * with a message when the buffer cannot be allocated, SOAK_ERR_IO on a read
 * error or when the file changes size while it is read. */
soak_status soak_input_read(const char *path, soak_input_kind kind, char **text, size_t *n, char *err,
                            size_t errlen);

#endif
