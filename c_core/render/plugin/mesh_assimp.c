/* libsoak_mesh.so: mesh files through Assimp's C API, every mesh of the file
 * merged into one soak_mesh with its node transforms applied (the table of
 * render/src/mesh_plugin.h; see soak/geometry.h). Loaded by mesh_io.c on a
 * command's first mesh; the import runs in a child process
 * (mesh_contain.c). Calls nothing of libsoak. */
#define _POSIX_C_SOURCE 200809L
#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_convert.h"
#include "mesh_plugin.h"

static void set_err(char *err, size_t errlen, const char *fmt, const char *a, const char *b)
{
    if (err && errlen) snprintf(err, errlen, fmt, a, b);
}

static void mesh_free(soak_mesh *m)
{
    if (!m) return;
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->indices);
    free(m->tri_uv);
    memset(m, 0, sizeof *m);
}

/* The UV channel of aiMesh m that the request names, or -1. */
static int uv_channel(const struct aiMesh *m, const soak_mesh_uv_choice *uv)
{
    if (!uv) return m->mTextureCoords[0] ? 0 : -1;
    if (!uv->uv_name[0])
        return uv->uv_index >= 0 && uv->uv_index < AI_MAX_NUMBER_OF_TEXTURECOORDS && m->mTextureCoords[uv->uv_index]
                   ? uv->uv_index
                   : -1;
    for (int k = 0; k < AI_MAX_NUMBER_OF_TEXTURECOORDS; ++k)
        if (m->mTextureCoords[k] && m->mTextureCoordsNames && m->mTextureCoordsNames[k] &&
            !strcmp(m->mTextureCoordsNames[k]->data, uv->uv_name))
            return k;
    return -1;
}

typedef struct walk_state {
    const struct aiScene *scene;
    soak_mesh *out;
    size_t nv, nt;     /* filled so far */
    size_t nt_uv;      /* counted triangles with the UV set */
    int counting;      /* first pass only counts */
    int any_uv, all_uv;
    const soak_mesh_uv_choice *uv;
    unsigned sets;     /* bit k: some part has UV channel k */
    char names[160];   /* the names of the sets, for an error */
} walk_state;

static void note_sets(walk_state *w, const struct aiMesh *m)
{
    for (int k = 0; k < AI_MAX_NUMBER_OF_TEXTURECOORDS; ++k) {
        if (!m->mTextureCoords[k]) continue;
        w->sets |= 1u << k;
        const char *name = m->mTextureCoordsNames && m->mTextureCoordsNames[k] ? m->mTextureCoordsNames[k]->data : "";
        size_t len = strlen(w->names);
        if (!name[0] || strstr(w->names, name) || len + strlen(name) + 5 >= sizeof w->names) continue;
        if (len) strcat(w->names, ", ");
        strcat(w->names, "'");
        strcat(w->names, name);
        strcat(w->names, "'");
    }
}

/* 4x4 row-major product r = a * b (Assimp matrices are row-major, column vectors). */
static void mat_mul(const double *a, const double *b, double *r)
{
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a[4 * i + k] * b[4 * k + j];
            r[4 * i + j] = s;
        }
}

static void walk(walk_state *w, const struct aiNode *node, const double *parent)
{
    const struct aiMatrix4x4 *T = &node->mTransformation;
    double local[16] = {T->a1, T->a2, T->a3, T->a4, T->b1, T->b2, T->b3, T->b4,
                        T->c1, T->c2, T->c3, T->c4, T->d1, T->d2, T->d3, T->d4};
    double M[16];
    mat_mul(parent, local, M);
    /* Normals: cofactor of the 3x3 part (inverse transpose up to scale). */
    double a = M[0], b = M[1], c = M[2], d = M[4], e = M[5], f = M[6], h = M[8], k = M[9], l = M[10];
    double C[9] = {e * l - f * k, f * h - d * l, d * k - e * h, c * k - b * l, a * l - c * h,
                   b * h - a * k, b * f - c * e, c * d - a * f, a * e - b * d};
    double det = a * C[0] + b * C[1] + c * C[2];
    for (unsigned mi = 0; mi < node->mNumMeshes; ++mi) {
        const struct aiMesh *m = w->scene->mMeshes[node->mMeshes[mi]];
        unsigned ntri = 0;
        for (unsigned fi = 0; fi < m->mNumFaces; ++fi) ntri += m->mFaces[fi].mNumIndices == 3;
        int ch = uv_channel(m, w->uv), has_uv = ch >= 0;
        if (w->counting) {
            note_sets(w, m);
            w->any_uv |= has_uv;
            w->all_uv &= has_uv;
            w->nv += m->mNumVertices;
            w->nt += ntri;
            w->nt_uv += has_uv ? ntri : 0;
            continue;
        }
        soak_mesh *o = w->out;
        size_t base = w->nv;
        for (unsigned vi = 0; vi < m->mNumVertices; ++vi) {
            const struct aiVector3D *p = &m->mVertices[vi];
            double *dst = o->positions + 3 * (base + vi);
            for (int r = 0; r < 3; ++r) dst[r] = M[4 * r] * p->x + M[4 * r + 1] * p->y + M[4 * r + 2] * p->z + M[4 * r + 3];
            if (o->normals) {
                double n[3] = {0, 0, 1};
                if (m->mNormals) {
                    const struct aiVector3D *q = &m->mNormals[vi];
                    double s = det < 0 ? -1 : 1;
                    for (int r = 0; r < 3; ++r) n[r] = s * (C[3 * r] * q->x + C[3 * r + 1] * q->y + C[3 * r + 2] * q->z);
                    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                    if (len > 1e-300 && isfinite(len)) {
                        n[0] /= len, n[1] /= len, n[2] /= len;
                    } else {
                        n[0] = 0, n[1] = 0, n[2] = 1;
                    }
                }
                memcpy(o->normals + 3 * (base + vi), n, sizeof n);
            }
            if (o->uvs) {
                o->uvs[2 * (base + vi)] = has_uv ? m->mTextureCoords[ch][vi].x : 0.0;
                o->uvs[2 * (base + vi) + 1] = has_uv ? m->mTextureCoords[ch][vi].y : 0.0;
            }
        }
        for (unsigned fi = 0; fi < m->mNumFaces; ++fi) {
            const struct aiFace *fc = &m->mFaces[fi];
            if (fc->mNumIndices != 3) continue; /* points and lines left by the triangulator */
            unsigned *t = o->indices + 3 * w->nt;
            t[0] = (unsigned)base + fc->mIndices[0];
            t[1] = (unsigned)base + fc->mIndices[det < 0 ? 2 : 1];
            t[2] = (unsigned)base + fc->mIndices[det < 0 ? 1 : 2];
            if (o->tri_uv) o->tri_uv[w->nt] = (unsigned char)has_uv;
            w->nt++;
        }
        w->nv += m->mNumVertices;
    }
    for (unsigned ci = 0; ci < node->mNumChildren; ++ci) walk(w, node->mChildren[ci], M);
}

static int raw_vertices_finite(const struct aiScene *sc, const char *path, char *err, size_t errlen)
{
    for (unsigned mi = 0; mi < sc->mNumMeshes; ++mi) {
        const struct aiMesh *m = sc->mMeshes[mi];
        for (unsigned vi = 0; vi < m->mNumVertices; ++vi) {
            const struct aiVector3D *p = &m->mVertices[vi];
            if (isfinite(p->x) && isfinite(p->y) && isfinite(p->z)) continue;
            if (err && errlen)
                snprintf(err, errlen, "%s: vertex %u of mesh %u has a non-finite coordinate (%g, %g, %g)", path, vi + 1,
                         mi + 1, p->x, p->y, p->z);
            return 0;
        }
    }
    return 1;
}

/* aiImportFile, or for a file Assimp misreads (mesh_convert.h) its
 * converted text from memory; NULL with err set when that cannot be made. */
static const struct aiScene *read_scene(const char *path, unsigned flags, char *err, size_t errlen)
{
    soak_mesh_text text;
    char why[256] = "";
    int conv = soak_mesh_convert(path, &text, why, sizeof why);
    if (conv < 0) {
        set_err(err, errlen, "%s: %s", path, why);
        return NULL;
    }
    if (conv == 0) return aiImportFile(path, flags);
    const struct aiScene *sc = text.size <= 0xFFFFFFFFu
                                   ? aiImportFileFromMemory(text.data, (unsigned)text.size, flags, text.hint)
                                   : NULL;
    free(text.data);
    return sc;
}

/* "mesh has no UVs", or when the file has UV sets but not the one asked
 * for, which sets it has. */
static void no_uvs(const walk_state *w, const char *path, char *err, size_t errlen)
{
    char sets[64] = "", want[96];
    for (int k = 0, len = 0; k < AI_MAX_NUMBER_OF_TEXTURECOORDS; ++k)
        if (w->sets >> k & 1u) len += snprintf(sets + len, sizeof sets - (size_t)len, "%s%d", len ? ", " : "", k);
    if (w->uv->uv_name[0]) snprintf(want, sizeof want, "named '%s'", w->uv->uv_name);
    else snprintf(want, sizeof want, "%d", w->uv->uv_index);
    if (!w->sets) set_err(err, errlen, "%s: %s", path, "mesh has no UVs");
    else if (err && errlen)
        snprintf(err, errlen, "%s: mesh has no UV set %s (it has set%s %s%s%s)", path, want,
                 strchr(sets, ',') ? "s" : "", sets, w->names[0] ? ": " : "", w->names);
}

static soak_status import(const char *path, const soak_mesh_request *rq, soak_mesh *mesh, char *err, size_t errlen)
{
    if (!path || !mesh || !rq) return SOAK_ERR_NULL;
    if (err && errlen) err[0] = '\0'; /* read_scene's refusal is told by a message */
    /* Coordinates are checked on a first import without post-processing:
     * joining identical vertices merges a NaN vertex into another one (NaN
     * compares equal in its spatial sort), leaving a silently degenerate
     * triangle. The file is then read again with post-processing in one call
     * (aiApplyPostProcessing on the first import crashes Assimp 5.2 when a
     * step fails: found by tests/fuzz, reproducers/mesh/stl_fuzz_segv). */
    const struct aiScene *sc = read_scene(path, 0, err, errlen);
    if (!sc && err && errlen && err[0]) return SOAK_ERR_PARSE;
    int finite = !sc || !sc->mRootNode || raw_vertices_finite(sc, path, err, errlen);
    if (sc) aiReleaseImport(sc);
    if (!finite) return SOAK_ERR_PARSE;
    sc = read_scene(path, aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
                              aiProcess_SortByPType, err, errlen);
    if (!sc || !sc->mRootNode) {
        const char *dot = strrchr(path, '.');
        if (dot && !strcmp(dot, ".blend") && strstr(aiGetErrorString(), "BlendDNA"))
            set_err(err, errlen, "%s: cannot read mesh (%s): Assimp 5.2 reads .blend files of Blender 2.5 to 3.0; "
                    "export FBX or glTF from newer Blender versions", path, aiGetErrorString());
        else
            set_err(err, errlen, "%s: cannot read mesh (%s)", path, aiGetErrorString());
        if (sc) aiReleaseImport(sc);
        return SOAK_ERR_PARSE;
    }
    static const double I[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    static const soak_mesh_uv_choice first = {0, ""};
    const soak_mesh_uv_choice *uv = rq->uv ? rq->uv : &first;
    walk_state w = {.scene = sc, .counting = 1, .all_uv = 1, .uv = uv};
    walk(&w, sc->mRootNode, I);
    soak_status st = SOAK_OK;
    if (w.nt == 0) {
        set_err(err, errlen, "%s: %s", path, "file contains no triangles");
        st = SOAK_ERR_PARSE;
    } else if (rq->require_uvs && !w.any_uv) {
        no_uvs(&w, path, err, errlen);
        st = SOAK_ERR_PARSE;
    } else if (rq->require_uvs == SOAK_MESH_UVS_ALL && !w.all_uv) {
        if (err && errlen)
            snprintf(err, errlen, "%s: partial UVs: %zu of %zu triangles have no texture coordinates (a wetness map "
                     "needs them on every face)", path, w.nt - w.nt_uv, w.nt);
        st = SOAK_ERR_PARSE;
    } else if (w.nv > 0xFFFFFFFEu) {
        set_err(err, errlen, "%s: %s", path, "too many vertices");
        st = SOAK_ERR_ARG;
    }
    if (st != SOAK_OK) {
        aiReleaseImport(sc);
        return st;
    }
    soak_mesh m = {0};
    m.n_vertices = w.nv;
    m.n_triangles = w.nt;
    m.positions = malloc(3 * w.nv * sizeof(double));
    m.normals = malloc(3 * w.nv * sizeof(double));
    m.uvs = w.any_uv ? malloc(2 * w.nv * sizeof(double)) : NULL;
    m.indices = malloc(3 * w.nt * sizeof(unsigned));
    m.tri_uv = w.any_uv && !w.all_uv ? malloc(w.nt) : NULL;
    if (!m.positions || !m.normals || !m.indices || (w.any_uv && !m.uvs) || (w.any_uv && !w.all_uv && !m.tri_uv)) {
        mesh_free(&m);
        aiReleaseImport(sc);
        return SOAK_ERR_NOMEM;
    }
    walk_state fill = {.scene = sc, .out = &m, .uv = uv};
    walk(&fill, sc->mRootNode, I);
    aiReleaseImport(sc);
    *mesh = m;
    return SOAK_OK;
}

__attribute__((visibility("default"))) const soak_mesh_plugin soak_mesh_plugin_v2 = {import};
