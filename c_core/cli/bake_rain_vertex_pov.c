/* soak bake rain MESH --per-vertex OUT.inc: the per-vertex wetness as a
 * POV-Ray 3.7 mesh2 (bake_vertex_pov.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "bake_vertex_pov.h"
#include "soak/export_escape.h"
#include "soak/staged.h"

int bake_vertex_pov_path(const char *path)
{
    const char *slash = path ? strrchr(path, '/') : NULL, *dot = path ? strrchr(path, '.') : NULL;
    return dot && (!slash || dot > slash) && !strcasecmp(dot, ".inc");
}

int bake_vertex_pov_name_ok(const char *name)
{
    size_t n = name ? strlen(name) : 0;
    if (n == 0 || n > BAKE_VERTEX_POV_NAME_MAX || !(name[0] >= 'A' && name[0] <= 'Z')) return 0;
    for (size_t i = 1; i < n; ++i) {
        char c = name[i];
        if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return 0;
    }
    return 1;
}

/* The texture level of a wetness: round(w / step). */
static long level_of(float w) { return lround((double)w * BAKE_VERTEX_POV_LEVELS); }

/* slot[k]: the texture_list index of level k, or -1; returns the count. */
static long assign_levels(const float *values, size_t n, long *slot)
{
    for (long k = 0; k <= BAKE_VERTEX_POV_LEVELS; ++k) slot[k] = -1;
    for (size_t i = 0; i < n; ++i) slot[level_of(values[i])] = 0;
    long used = 0;
    for (long k = 0; k <= BAKE_VERTEX_POV_LEVELS; ++k)
        if (slot[k] == 0) slot[k] = used++;
    return used;
}

/* 1 when every normal is finite and not zero (POV-Ray normalises them). */
static int normals_usable(const soak_mesh *m)
{
    if (!m->normals) return 0;
    for (size_t i = 0; i < 3 * m->n_vertices; i += 3) {
        const double *v = m->normals + i;
        double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (!(soak_is_finite(len) && len > 1e-12)) return 0;
    }
    return 1;
}

static void write_header(FILE *f, const char *escaped_mesh, const char *name, const soak_mesh *m)
{
    fprintf(
        f,
        "// Rain wetness per vertex: soak bake rain \"%s\" --per-vertex (docs/meshes.md).\n"
        "// %zu vertices, %zu faces, coordinates as in the mesh file; the wetness of each\n"
        "// vertex rounded to 1/%d. Each texture is Soak_Mesh_Texture(wetness) of\n"
        "// soak_mesh.inc (or your own macro of that name); POV-Ray shades the three\n"
        "// textures of a face and interpolates the results across it.\n"
        "//   #include \"soak.inc\"\n"
        "//   #declare Soak_Mesh_Preset = \"concrete\";  // optional; also Soak_Mesh_Liquid, Soak_Mesh_Pigment\n"
        "//   #include \"soak_mesh.inc\"\n"
        "//   #include \"this file\"\n"
        "//   object { %s Soak_Wet_Interior(Soak_Mesh_Liquid) }\n"
        "#ifndef (Soak_Mesh_Inc_Temp)\n"
        "  #error \"per-vertex wetness: #include \\\"soak_mesh.inc\\\" (Soak's povray folder) before this file\\n\"\n"
        "#end\n",
        escaped_mesh, m->n_vertices, m->n_triangles, BAKE_VERTEX_POV_LEVELS, name);
}

static void write_mesh2(FILE *f, const soak_mesh *m, const float *values, const long *slot, long used, const char *name)
{
    fprintf(f, "#declare %s = mesh2 {\n  vertex_vectors { %zu,\n", name, m->n_vertices);
    for (size_t i = 0; i < m->n_vertices && !ferror(f); ++i)
        fprintf(f, "%s    <%.9g, %.9g, %.9g>", i ? ",\n" : "", m->positions[3 * i], m->positions[3 * i + 1],
                m->positions[3 * i + 2]);
    fprintf(f, "\n  }\n");
    if (normals_usable(m)) {
        fprintf(f, "  normal_vectors { %zu,\n", m->n_vertices);
        for (size_t i = 0; i < m->n_vertices && !ferror(f); ++i)
            fprintf(f, "%s    <%.9g, %.9g, %.9g>", i ? ",\n" : "", m->normals[3 * i], m->normals[3 * i + 1],
                    m->normals[3 * i + 2]);
        fprintf(f, "\n  }\n");
    }
    fprintf(f, "  texture_list { %ld,\n", used);
    for (long k = 0; k <= BAKE_VERTEX_POV_LEVELS && !ferror(f); ++k)
        if (slot[k] >= 0) fprintf(f, "    Soak_Mesh_Texture(%.*f)\n", 3, (double)k / BAKE_VERTEX_POV_LEVELS);
    fprintf(f, "  }\n  face_indices { %zu,\n", m->n_triangles);
    for (size_t t = 0; t < m->n_triangles && !ferror(f); ++t) {
        const unsigned *v = m->indices + 3 * t;
        fprintf(f, "%s    <%u, %u, %u>, %ld, %ld, %ld", t ? ",\n" : "", v[0], v[1], v[2], slot[level_of(values[v[0]])],
                slot[level_of(values[v[1]])], slot[level_of(values[v[2]])]);
    }
    fprintf(f, "\n  }\n}\n");
}

static soak_status fail(char *err, size_t errlen, soak_status st, const char *fmt, const char *arg)
{
    if (err && errlen) snprintf(err, errlen, fmt, arg);
    return st;
}

soak_status bake_vertex_pov_write(const char *path, const soak_mesh *m, const float *values, const char *mesh_path,
                                  const char *name, char *err, size_t errlen)
{
    if (!path || !m || !values || !mesh_path || !name) return SOAK_ERR_NULL;
    if (!bake_vertex_pov_name_ok(name))
        return fail(err, errlen, SOAK_ERR_ARG, "'%s' is not a POV-Ray identifier", name);
    for (size_t i = 0; i < m->n_vertices; ++i)
        if (!(values[i] >= 0.0f && values[i] <= 1.0f))
            return fail(err, errlen, SOAK_ERR_NUMERIC, "%s", "wetness out of [0, 1]");
    size_t cap = SOAK_ESCAPE_SIZE(strlen(mesh_path));
    char *escaped = malloc(cap);
    long *slot = malloc((BAKE_VERTEX_POV_LEVELS + 1) * sizeof *slot);
    soak_status st = escaped && slot ? soak_escape_povray(mesh_path, escaped, cap) : SOAK_ERR_NOMEM;
    soak_staged stage;
    soak_staged_init(&stage);
    FILE *f = NULL;
    if (st == SOAK_OK) st = soak_staged_open(&stage, path, &f, err, errlen);
    if (st == SOAK_OK) {
        write_header(f, escaped, name, m);
        write_mesh2(f, m, values, slot, assign_levels(values, m->n_vertices, slot), name);
        int bad = ferror(f);
        st = soak_staged_close(f, path, err, errlen);
        if (st == SOAK_OK && bad) st = fail(err, errlen, SOAK_ERR_IO, "%s: write failed", path);
    } else if (st == SOAK_ERR_NOMEM) {
        fail(err, errlen, st, "%s: out of memory", path);
    }
    free(escaped);
    free(slot);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return st;
    }
    return soak_staged_commit(&stage, err, errlen);
}
