/* Ray-tracing geometry shared by the reference tracer, the virtual
 * gonio-reflectometer and the bakers: triangle meshes, spheres, quads and
 * boxes in an Embree 3 scene owned by one soak_geometry (no global state).
 *
 * Usage: soak_geometry_create, add shapes, soak_geometry_commit, then query
 * from any number of threads (queries only read the committed scene; each
 * call uses its own Embree intersect context). Adding after commit needs
 * another commit before querying again, and is not thread-safe.
 *
 * Conventions: object ids are dense, in the order the shapes were added,
 * starting at 0. The geometric normal ng points to the front side: for
 * triangles the side from which the vertices appear counter-clockwise
 * (ng = normalize((p1-p0) x (p2-p0))); for spheres and boxes outward; for a
 * quad normalize(edge_u x edge_v). The shading normal ns is the interpolated
 * vertex normal when the mesh has normals (flipped onto ng's side), otherwise
 * ng. Hit positions and distances are recomputed in double precision from
 * the shape data (Embree traverses in float). */
#ifndef SOAK_GEOMETRY_H
#define SOAK_GEOMETRY_H

#include <stddef.h>
#include <stdio.h>

#include "soak/status.h"
#include "soak/vec.h"

typedef struct soak_geometry soak_geometry;

/* A triangle mesh in memory. normals and uvs may be NULL. */
typedef struct soak_mesh {
    size_t n_vertices;
    size_t n_triangles;
    double *positions;  /* 3 * n_vertices */
    double *normals;    /* 3 * n_vertices, unit, or NULL */
    double *uvs;        /* 2 * n_vertices, or NULL */
    unsigned *indices;  /* 3 * n_triangles, each < n_vertices */
    unsigned char *tri_uv; /* n_triangles: 0 where the face has no UVs (a part of the file without
                              the UV set); NULL when every face has them or there are none */
} soak_mesh;

typedef enum soak_shape_kind {
    SOAK_SHAPE_MESH = 0,
    SOAK_SHAPE_SPHERE,
    SOAK_SHAPE_QUAD,
    SOAK_SHAPE_BOX
} soak_shape_kind;

typedef struct soak_ray {
    soak_vec3 org;
    soak_vec3 dir;  /* need not be unit; t is in units of |dir| */
    double tnear;   /* >= 0 */
    double tfar;    /* > tnear; may be INFINITY */
} soak_ray;

typedef struct soak_hit {
    double t;
    soak_vec3 p;        /* org + t dir, refined on the shape */
    soak_vec3 ng;       /* unit geometric normal (front side, see above) */
    soak_vec3 ns;       /* unit shading normal, same side as ng */
    double u, v;        /* texture coordinates (0 when the mesh has none) */
    unsigned prim_id;   /* triangle index within the object (0 for spheres) */
    unsigned object_id; /* as returned by soak_geometry_add_* */
} soak_hit;

/* Mesh loading through Assimp (the formats of soak_mesh_formats_print:
 * OBJ, PLY, glTF/GLB, FBX, Collada, 3DS, .blend, X, LWO, MS3D, ...):
 * triangulated, smooth normals generated where missing, identical
 * vertices joined, all meshes of the file merged with their node transforms
 * applied. With require_uvs, a file without texture coordinates fails with
 * SOAK_ERR_PARSE and "<file>: mesh has no UVs", and a file where only some
 * parts have them with "partial UVs" and the counts (soak_mesh_load_uv
 * loads it with tri_uv marking the faces that have them). Missing/unreadable files
 * give SOAK_ERR_IO with the file and the reason. Formats outside the table
 * are SOAK_ERR_UNSUPPORTED with the reason. Assimp runs in a child process
 * with a time limit (SOAK_MESH_TIMEOUT seconds, default 120): a crash or a
 * hang there is SOAK_ERR_PARSE naming the file; non-finite coordinates and
 * out-of-range indices are rejected. Plain OBJ, PLY and STL are read in that
 * child by soak's own reader, which gives Assimp's triangles
 * (render/src/mesh_native.h; SOAK_MESH_READER=assimp turns it off). */
soak_status soak_mesh_load(const char *path, int require_uvs, soak_mesh *mesh, char *err, size_t errlen);

/* Which UV set soak_mesh_load_uv reads: uv_index (0 = the first; Assimp's
 * channel number) or, when uv_name is not empty, the set of that name
 * (formats that name their sets, e.g. FBX, Collada). */
#define SOAK_MESH_UV_NAME_MAX 64
#define SOAK_MESH_UV_SETS 8
typedef struct soak_mesh_uv_choice {
    int uv_index;
    char uv_name[SOAK_MESH_UV_NAME_MAX];
} soak_mesh_uv_choice;
/* soak_mesh_load with require_uvs and a choice of UV set (NULL: the first);
 * parts of the file without the set load with tri_uv marking their faces.
 * A set that no part of the file has fails naming the sets it has. */
soak_status soak_mesh_load_uv(const char *path, const soak_mesh_uv_choice *uv, soak_mesh *mesh, char *err,
                              size_t errlen);
void soak_mesh_free(soak_mesh *mesh);

/* The mesh formats for --help: one line per extension with what reads it
 * or why it is left out. */
void soak_mesh_formats_print(FILE *out);

soak_status soak_geometry_create(soak_geometry **out, char *err, size_t errlen);
void soak_geometry_destroy(soak_geometry *g);

/* xform: row-major 3x4 affine matrix (rotation/scale | translation) applied to
 * positions; normals use its inverse transpose. NULL = identity. The mesh is
 * copied. */
soak_status soak_geometry_add_mesh(soak_geometry *g, const soak_mesh *mesh, const double *xform, unsigned *object_id);
/* radius in (0, 1e9]. UV: u = azimuth / 2pi around +z, v = polar angle / pi. */
soak_status soak_geometry_add_sphere(soak_geometry *g, soak_vec3 center, double radius, unsigned *object_id);
/* Parallelogram origin + s edge_u + t edge_v, s,t in [0,1]; uv = (s, t). */
soak_status soak_geometry_add_quad(soak_geometry *g, soak_vec3 origin, soak_vec3 edge_u, soak_vec3 edge_v,
                                   unsigned *object_id);
/* Axis-aligned box lo < hi per axis (12 triangles, outward faces, each face
 * with uv over [0,1]^2). */
soak_status soak_geometry_add_box(soak_geometry *g, soak_vec3 lo, soak_vec3 hi, unsigned *object_id);
soak_status soak_geometry_commit(soak_geometry *g);
/* Embree's robust traversal (RTC_SCENE_FLAG_ROBUST): on (1) by default;
 * takes effect at the next commit. Off saves about 6 % of the instructions
 * of a mesh-heavy render (c_core/bench/results/2026-11-27-render-vs-cycles.md),
 * but a ray aimed at an edge or corner between triangles may pass between
 * them: from inside a box, 61 of 1280 rays aimed exactly at its edges and
 * corners did (tests/c/render/test_geometry.c). */
soak_status soak_geometry_set_robust(soak_geometry *g, int robust);

unsigned soak_geometry_object_count(const soak_geometry *g);
soak_shape_kind soak_geometry_object_kind(const soak_geometry *g, unsigned object_id);
/* Triangle count of an object (0 for spheres). */
size_t soak_geometry_triangle_count(const soak_geometry *g, unsigned object_id);
/* Axis-aligned bounds of one object (spheres: centre +- radius). */
soak_status soak_geometry_object_bounds(const soak_geometry *g, unsigned object_id, soak_vec3 *lo, soak_vec3 *hi);
/* Axis-aligned bounds of the whole committed scene. */
soak_status soak_geometry_bounds(const soak_geometry *g, soak_vec3 *lo, soak_vec3 *hi);

/* Closest hit in (tnear, tfar). *found = 1 and *hit filled on a hit,
 * *found = 0 (hit untouched) on a miss. */
soak_status soak_geometry_intersect(const soak_geometry *g, const soak_ray *ray, soak_hit *hit, int *found);
/* *occluded = 1 when anything lies in (tnear, tfar). */
soak_status soak_geometry_occluded(const soak_geometry *g, const soak_ray *ray, int *occluded);
/* Batches: n rays, found[i]/occluded[i] per ray. */
soak_status soak_geometry_intersect_n(const soak_geometry *g, const soak_ray *rays, size_t n, soak_hit *hits,
                                      int *found);
soak_status soak_geometry_occluded_n(const soak_geometry *g, const soak_ray *rays, size_t n, int *occluded);
/* The same for n rays from one origin along dirs[i] with tnear 0 and tfar
 * infinite (the answers soak_geometry_occluded_n gives for those rays), the
 * origin converted once. */
soak_status soak_geometry_occluded_fan(const soak_geometry *g, soak_vec3 org, const soak_vec3 *dirs, size_t n,
                                       int *occluded);

/* Queries for a walk inside object object_id (a medium): they equal the
 * whole-scene queries for rays starting inside it whenever no other surface
 * enters its interior, and then only its own surface is tested. An isolated
 * sphere (every other surface at least its radius from its centre, decided
 * at commit) is answered in closed form in double precision, without the
 * BVH; so is a closed convex mesh that no other object's bounds reach into
 * (found at commit), by a walk across its faces from a direction map's guess
 * to the face whose cone from the ray's origin holds the direction
 * (geometry_convex.c; a walk of more than a few dozen faces asks the BVH);
 * every other case falls back to the scene query, except that an
 * occlusion query whose segment lies in the object's clear ball (about the
 * centre of its bounds, free of every surface, found at commit) or, for a
 * box that no other object's bounds meet, in its interior answers 0
 * without traversal. Cycles' subsurface
 * walk likewise intersects only its own object (scene_intersect_local).
 * With want_uv = 0 a hit leaves u = v = 0 and ns = ng (a walk needs texture
 * coordinates only for a wet map, and no shading normal). */
soak_status soak_geometry_intersect_local(const soak_geometry *g, unsigned object_id, const soak_ray *ray, int want_uv,
                                          soak_hit *hit, int *found);
soak_status soak_geometry_occluded_local(const soak_geometry *g, unsigned object_id, const soak_ray *ray, int *occluded);
/* 1 when the local queries of object_id skip the BVH: an isolated sphere or
 * an isolated closed convex mesh. */
int soak_geometry_object_isolated(const soak_geometry *g, unsigned object_id);
/* 1 when a ray leaving convex object object_id (a sphere, a box or a closed
 * convex mesh) from its surface, outward, certainly meets no surface: it
 * cannot come back to the object, and it misses every other object's bounds
 * (grown by Embree's float error). 0 when that is not certain (then ask
 * soak_geometry_occluded) or with more than a few objects. No traversal. */
int soak_geometry_ray_escapes(const soak_geometry *g, unsigned object_id, const soak_ray *ray);
/* A lower bound on the distance from p, inside object object_id, to any
 * surface: from an isolated sphere's own radius, or from the object's clear
 * ball or clear box (the larger); 0 when p is outside them or there is
 * none. No traversal. */
double soak_geometry_clear_distance(const soak_geometry *g, unsigned object_id, soak_vec3 p);

/* Origin for a ray leaving the surface at p toward direction dir: p moved off
 * the surface along ng to dir's side by an amount scaled to |p|, so the new
 * ray does not re-hit the surface it starts on (Embree works in float). */
soak_vec3 soak_geometry_offset(soak_vec3 p, soak_vec3 ng, soak_vec3 dir);

#endif
