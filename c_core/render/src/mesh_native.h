/* The native mesh reader (issue 47 item 6): plain OBJ, PLY (ASCII and
 * binary) and STL (binary, plain ASCII), the formats large meshes come
 * in, read without Assimp inside the same contained reader child
 * (mesh_contain.c). It gives the triangles,
 * positions and UVs Assimp 5.2 gives for the files it takes (same numbers
 * parsed the same way, quads split as Assimp's triangulator splits them,
 * smooth normals made as its GenSmoothNormals makes them, up to vertices
 * that lie within its epsilon but not exactly together) and declines
 * everything else, which then goes to Assimp as before: the native reader
 * never fails a file, so every message about a malformed file stays
 * Assimp's and the containment's. docs/meshes.md lists what it takes. */
#ifndef SOAK_MESH_NATIVE_H
#define SOAK_MESH_NATIVE_H

#include <stddef.h>
#include <stdint.h>

#include "mesh_plugin.h"
#include "soak/geometry.h"

/* 1: *mesh holds path's triangles (validated); 0: declined, why says why
 * ("not OBJ, PLY or STL", "n-gon of 5 corners at line 12", ...). */
int soak_mesh_native_read(const char *path, const soak_mesh_request *rq, soak_mesh *mesh, char *why, size_t whylen);

/* 0 when SOAK_MESH_READER is "assimp" (every file to Assimp), else 1. */
int soak_mesh_native_enabled(void);

/* --- shared by mesh_native*.c --- */

/* A file as read, before vertices are made: float like Assimp's arrays.
 * Corners are (position, uv, normal) index triples, UINT32_MAX for none. */
typedef struct native_mesh {
    float *pos, *uv, *nrm; /* 3, 2, 3 floats per entry */
    size_t n_pos, n_uv, n_nrm, cap_pos, cap_uv, cap_nrm;
    uint32_t *corner;    /* 9 per triangle */
    unsigned char *kind; /* per triangle: 0 a triangle face, 1 and 2 the halves of a quad */
    size_t n_tri, cap_tri;
    int any_quad; /* Assimp triangulates (and re-encodes, see native_encode_ngons) only then */
    int indexed;  /* PLY: corners share vertices (Assimp keeps PLY's vertex list) */
} native_mesh;

/* The bytes of a file, read-only. */
typedef struct native_text {
    const char *p, *end;
} native_text;

void native_mesh_free(native_mesh *m);
/* Room for n more floats of k per entry; 0 when out of memory. */
int native_grow_floats(float **a, size_t *cap, size_t used, size_t k);
/* Adds a triangle or a quad (corners c: count 3 or 4 triples) split as
 * Assimp's TriangulateProcess splits it; 0 when the split is too close to
 * call (a quad with a corner within 1e-4 rad of flat) or out of memory. */
int native_add_face(native_mesh *m, const uint32_t *c, int count);
/* The corner rotations of Assimp's n-gon encoding, applied once all faces
 * are in (mesh_native.c). */
void native_encode_ngons(native_mesh *m);
/* Assimp's fast_atoreal_move (fast_atof.h, Assimp 5.2) on a plain decimal:
 * the same float for the same text; 0 (and *t unchanged) on anything else
 * (nan, inf, a comma, no digits, over 18 integer digits). as_double: its
 * double variant, rounded to float afterwards (PLY's double properties). */
int native_parse_real(native_text *t, int as_double, float *out);
/* A decimal unsigned integer below 2^32; 0 otherwise. */
int native_parse_uint(native_text *t, uint32_t *out);
void native_skip_blanks(native_text *t);

/* The soak_mesh of a file read (mesh_native_finish.c); 0 with why when
 * it is one to leave to Assimp (UVs or normals on some faces only, a
 * non-finite number, no triangles, no UVs when they are required). */
int native_finish(native_mesh *m, const soak_mesh_request *rq, soak_mesh *mesh, char *why, size_t whylen);
int native_read_obj(native_text t, native_mesh *m, char *why, size_t whylen);
int native_read_ply(native_text t, native_mesh *m, char *why, size_t whylen);
int native_read_stl(native_text t, native_mesh *m, char *why, size_t whylen);

#endif
