/* JSON scene reader (format: scenes/README.md): render settings, camera,
 * environment, lights and objects. Materials and wetness: scene_material.c. */
#define _POSIX_C_SOURCE 200809L
#include "soak/scene.h"
#include "soak/input_file.h"
#include "soak/preset.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "scene_json.h"
#include "scene_levels.h"
#include "scene_material.h"

/* Counts are whole numbers: 31.7 is an error, not 31. */
static soak_status whole(scene_ctx *c, const char *path, double v)
{
    if (v == floor(v)) return SOAK_OK;
    return sj_fail(c, SOAK_ERR_ARG, path, "must be a whole number, got %g", v);
}

/* render.robust: Embree's robust traversal for the scene (a boolean, on by
 * default: see soak_geometry_set_robust). */
static soak_status parse_robust(scene_ctx *c, const cJSON *j, int *robust)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(j, "robust");
    if (!v) return SOAK_OK;
    if (!cJSON_IsBool(v)) return sj_fail(c, SOAK_ERR_ARG, "render.robust", "must be true or false");
    *robust = cJSON_IsTrue(v);
    return SOAK_OK;
}

static soak_status parse_render(scene_ctx *c, const cJSON *j)
{
    static const char *const keys[] = {"width",          "height", "spp",        "max_depth", "caustic_photons",
                                       "caustic_radius", "robust", "walk_guide", NULL};
    soak_scene *s = c->scene;
    double w = 256, h = 192, spp = 16, md = 256, np = 0, rad = 0, guide = SOAK_RENDER_WALK_GUIDE;
    int robust = 1;
    if (j) {
        soak_status st = sj_keys(c, j, "render", keys);
        if (st == SOAK_OK) st = parse_robust(c, j, &robust);
        if (st == SOAK_OK) st = sj_num(c, j, "caustic_photons", "render", 0, 1e9, 0, 0, &np);
        if (st == SOAK_OK) st = sj_num(c, j, "caustic_radius", "render", 0, 1e12, 0, 0, &rad);
        if (st == SOAK_OK) st = sj_num(c, j, "walk_guide", "render", 0, 0.99, 0, SOAK_RENDER_WALK_GUIDE, &guide);
        if (st == SOAK_OK && np > 0 && !(rad > 0))
            return sj_fail(c, SOAK_ERR_ARG, "render.caustic_radius", "must be > 0 when render.caustic_photons is set");
        if (st == SOAK_OK) st = sj_num(c, j, "width", "render", 1, SOAK_RENDER_MAX_SIZE, 0, 256, &w);
        if (st == SOAK_OK) st = sj_num(c, j, "height", "render", 1, SOAK_RENDER_MAX_SIZE, 0, 192, &h);
        if (st == SOAK_OK) st = sj_num(c, j, "spp", "render", 1, SOAK_RENDER_MAX_SPP, 0, 16, &spp);
        if (st == SOAK_OK) st = sj_num(c, j, "max_depth", "render", 1, SOAK_RENDER_MAX_DEPTH, 0, 256, &md);
        if (st == SOAK_OK) st = whole(c, "render.width", w);
        if (st == SOAK_OK) st = whole(c, "render.height", h);
        if (st == SOAK_OK) st = whole(c, "render.spp", spp);
        if (st == SOAK_OK) st = whole(c, "render.max_depth", md);
        if (st == SOAK_OK) st = whole(c, "render.caustic_photons", np);
        if (st != SOAK_OK) return st;
    }
    s->width = (int)w;
    s->height = (int)h;
    s->spp = (int)spp;
    s->max_depth = (int)md;
    s->caustic_photons = (long long)np;
    s->caustic_radius = rad;
    s->walk_guide = guide;
    return soak_geometry_set_robust(s->geometry, robust);
}

static soak_status parse_camera(scene_ctx *c, const cJSON *j)
{
    static const char *const keys[] = {"position", "look_at",        "up",       "fov",
                                       "aperture", "focus_distance", "exposure", NULL};
    if (!j) return sj_fail(c, SOAK_ERR_PARSE, "camera", "missing (required)");
    soak_camera *cam = &c->scene->camera;
    soak_status st = sj_keys(c, j, "camera", keys);
    if (st == SOAK_OK) st = sj_vec3(c, j, "position", "camera", 1, soak_v3(0, 0, 0), &cam->position);
    if (st == SOAK_OK) st = sj_vec3(c, j, "look_at", "camera", 1, soak_v3(0, 0, 0), &cam->look_at);
    if (st == SOAK_OK) st = sj_vec3(c, j, "up", "camera", 0, soak_v3(0, 0, 1), &cam->up);
    if (st == SOAK_OK) st = sj_num_gt(c, j, "fov", "camera", 0, 179, 0, 40, &cam->fov_deg);
    if (st == SOAK_OK) st = sj_num(c, j, "aperture", "camera", 0, 1e6, 0, 0, &cam->aperture);
    double dist = soak_v3_len(soak_v3_sub(cam->look_at, cam->position));
    if (st == SOAK_OK && !(dist > 0))
        return sj_fail(c, SOAK_ERR_ARG, "camera.look_at", "must differ from camera.position");
    if (st == SOAK_OK) st = sj_num_gt(c, j, "focus_distance", "camera", 0, 1e12, 0, dist, &cam->focus_distance);
    if (st == SOAK_OK) st = sj_num(c, j, "exposure", "camera", -50, 50, 0, 0, &cam->exposure);
    if (st != SOAK_OK) return st;
    soak_vec3 fwd = soak_v3_norm(soak_v3_sub(cam->look_at, cam->position));
    if (!(soak_v3_len(soak_v3_cross(fwd, soak_v3_norm(cam->up))) > 1e-6))
        return sj_fail(c, SOAK_ERR_ARG, "camera.up", "must not be parallel to the viewing direction");
    return SOAK_OK;
}

/* Blender's CC0 world HDRIs (Poly Haven), where Debian's blender-data
 * package puts them; SOAK_HDRI_DIR points elsewhere. */
#define SOAK_HDRI_DIR_DEFAULT "/usr/share/blender/datafiles/studiolights/world"

/* "hdri": NAME -> DIR/NAME.exr, checked here so a missing package is named. */
static soak_status hdri_file(scene_ctx *c, const char *name, char *out, size_t n)
{
    if (!name[0] || strspn(name, "abcdefghijklmnopqrstuvwxyz0123456789_-") != strlen(name))
        return sj_fail(c, SOAK_ERR_ARG, "environment.hdri",
                       "'%s' is not a name (letters, digits, '_', '-'; e.g. courtyard)", name);
    const char *dir = getenv("SOAK_HDRI_DIR");
    int from_env = dir && dir[0];
    char path[2048];
    int w = snprintf(path, sizeof path, "%s/%s.exr", from_env ? dir : SOAK_HDRI_DIR_DEFAULT, name);
    if (w < 0 || (size_t)w >= sizeof path) return sj_fail(c, SOAK_ERR_ARG, "environment.hdri", "file name too long");
    FILE *f = fopen(path, "rb");
    if (f) {
        fclose(f);
        return sj_file(c, path, "environment.hdri", out, n);
    }
    return sj_fail(c, SOAK_ERR_IO, "environment.hdri", "%s: %s (%s)", path, strerror(errno),
                   from_env ? "set by SOAK_HDRI_DIR"
                            : "Blender's HDRIs come with Debian's blender-data package, installed by the README's "
                              "set-up; or set SOAK_HDRI_DIR to a folder of NAME.exr files");
}

static soak_status parse_environment(scene_ctx *c, const cJSON *j)
{
    soak_environment *e = &c->scene->env;
    e->type = SOAK_ENV_NONE;
    if (!j) return SOAK_OK;
    const char *type;
    soak_status st = sj_str(c, j, "type", "environment", 1, &type);
    if (st != SOAK_OK) return st;
    if (strcmp(type, "constant") == 0) {
        static const char *const keys[] = {"type", "radiance", NULL};
        st = sj_keys(c, j, "environment", keys);
        if (st == SOAK_OK) st = sj_rgb(c, j, "radiance", "environment", 0, 1e9, 1, soak_rgb3(0, 0, 0), &e->radiance);
        if (st == SOAK_OK) e->type = SOAK_ENV_CONSTANT;
        return st;
    }
    if (strcmp(type, "map") == 0) {
        static const char *const keys[] = {"type", "file", "hdri", "scale", "rotation", NULL};
        const char *file = NULL, *hdri = NULL;
        st = sj_keys(c, j, "environment", keys);
        if (st == SOAK_OK) st = sj_str(c, j, "file", "environment", 0, &file);
        if (st == SOAK_OK) st = sj_str(c, j, "hdri", "environment", 0, &hdri);
        if (st == SOAK_OK && !file == !hdri)
            st = sj_fail(c, SOAK_ERR_ARG, "environment", "a map needs exactly one of \"file\" and \"hdri\"");
        if (st == SOAK_OK) st = sj_num(c, j, "scale", "environment", 0, 1e9, 0, 1, &e->scale);
        if (st == SOAK_OK) st = sj_num(c, j, "rotation", "environment", -360, 360, 0, 0, &e->rotation_deg);
        if (st != SOAK_OK) return st;
        char full[2048], msg[1024];
        st = file ? sj_file(c, file, "environment.file", full, sizeof full) : hdri_file(c, hdri, full, sizeof full);
        if (st != SOAK_OK) return st;
        st = soak_image_read(full, &e->map, msg, sizeof msg);
        if (st != SOAK_OK) return sj_fail(c, st, "environment.file", "%s", msg);
        e->type = SOAK_ENV_MAP;
        /* Lossy EXR compression leaves slightly negative pixels (down to -0.003
         * in Blender's HDRIs): radiance cannot be negative, so they read as 0. */
        for (size_t i = 0; i < (size_t)e->map.width * e->map.height * e->map.channels; ++i) {
            if (!(e->map.pixels[i] > -3e38f && e->map.pixels[i] < 3e38f))
                return sj_fail(c, SOAK_ERR_ARG, "environment.file", "%s: non-finite pixel", full);
            if (e->map.pixels[i] < 0) e->map.pixels[i] = 0;
        }
        return SOAK_OK;
    }
    return sj_fail(c, SOAK_ERR_PARSE, "environment.type", "unknown type '%s' (accepted: constant, map)", type);
}

static soak_status add_material_emitter(soak_scene *s, soak_rgb radiance, int *index)
{
    soak_material *m = realloc(s->materials, (size_t)(s->n_materials + 1) * sizeof *m);
    if (!m) return SOAK_ERR_NOMEM;
    s->materials = m;
    memset(&m[s->n_materials], 0, sizeof *m);
    m[s->n_materials].type = SOAK_MAT_EMITTER;
    m[s->n_materials].radiance = radiance;
    snprintf(m[s->n_materials].name, sizeof m->name, "(light)");
    *index = s->n_materials++;
    return SOAK_OK;
}

static soak_status push_object(soak_scene *s, soak_shape_kind shape, unsigned id, int material)
{
    if ((int)id != s->n_objects) return SOAK_ERR_ARG;
    soak_object *o = realloc(s->objects, (size_t)(s->n_objects + 1) * sizeof *o);
    if (!o) return SOAK_ERR_NOMEM;
    s->objects = o;
    memset(&o[s->n_objects], 0, sizeof *o);
    o[s->n_objects].shape = shape;
    o[s->n_objects].object_id = id;
    o[s->n_objects].material = material;
    o[s->n_objects].wetness.type = SOAK_WETNESS_CONSTANT;
    o[s->n_objects].wetness.value = 1.0;
    s->n_objects++;
    return SOAK_OK;
}

static soak_status parse_lights(scene_ctx *c, const cJSON *j)
{
    soak_scene *s = c->scene;
    if (!j) return SOAK_OK;
    if (!cJSON_IsArray(j)) return sj_fail(c, SOAK_ERR_PARSE, "lights", "must be an array");
    int n = cJSON_GetArraySize(j);
    s->lights = calloc((size_t)(n > 0 ? n : 1), sizeof *s->lights);
    if (!s->lights) return SOAK_ERR_NOMEM;
    const cJSON *l = j->child;
    for (int i = 0; i < n; ++i, l = l->next) {
        char p[64];
        sj_index(p, sizeof p, "lights", i);
        const char *type;
        soak_light *L = &s->lights[i];
        soak_status st = sj_str(c, l, "type", p, 1, &type);
        if (st != SOAK_OK) return st;
        if (strcmp(type, "sun") == 0 || strcmp(type, "directional") == 0) {
            static const char *const keys[] = {"type", "direction", "irradiance", NULL};
            L->type = SOAK_LIGHT_DIRECTIONAL;
            st = sj_keys(c, l, p, keys);
            if (st == SOAK_OK) st = sj_vec3(c, l, "direction", p, 1, soak_v3(0, 0, 1), &L->direction);
            if (st == SOAK_OK) st = sj_rgb(c, l, "irradiance", p, 0, 1e9, 1, soak_rgb3(0, 0, 0), &L->value);
            if (st != SOAK_OK) return st;
            if (!(soak_v3_len(L->direction) > 0)) {
                char q[96];
                sj_path(q, sizeof q, p, "direction");
                return sj_fail(c, SOAK_ERR_ARG, q, "must not be the zero vector");
            }
            L->direction = soak_v3_norm(L->direction);
        } else if (strcmp(type, "point") == 0) {
            static const char *const keys[] = {"type", "position", "intensity", NULL};
            L->type = SOAK_LIGHT_POINT;
            st = sj_keys(c, l, p, keys);
            if (st == SOAK_OK) st = sj_vec3(c, l, "position", p, 1, soak_v3(0, 0, 0), &L->position);
            if (st == SOAK_OK) st = sj_rgb(c, l, "intensity", p, 0, 1e12, 1, soak_rgb3(0, 0, 0), &L->value);
            if (st != SOAK_OK) return st;
        } else if (strcmp(type, "sphere") == 0) {
            static const char *const keys[] = {"type", "center", "radius", "radiance", NULL};
            L->type = SOAK_LIGHT_SPHERE;
            st = sj_keys(c, l, p, keys);
            if (st == SOAK_OK) st = sj_vec3(c, l, "center", p, 1, soak_v3(0, 0, 0), &L->position);
            if (st == SOAK_OK) st = sj_num_gt(c, l, "radius", p, 0, 1e9, 1, 0, &L->radius);
            if (st == SOAK_OK) st = sj_rgb(c, l, "radiance", p, 0, 1e12, 1, soak_rgb3(0, 0, 0), &L->value);
            if (st != SOAK_OK) return st;
            int mat;
            st = add_material_emitter(s, L->value, &mat);
            if (st == SOAK_OK) st = soak_geometry_add_sphere(s->geometry, L->position, L->radius, &L->object_id);
            if (st == SOAK_OK) st = push_object(s, SOAK_SHAPE_SPHERE, L->object_id, mat);
            if (st != SOAK_OK) return sj_fail(c, st, p, "cannot add the light's sphere (%s)", soak_status_str(st));
        } else {
            char q[96];
            sj_path(q, sizeof q, p, "type");
            return sj_fail(c, SOAK_ERR_PARSE, q, "unknown light type '%s' (accepted: sun, directional, point, sphere)",
                           type);
        }
        s->n_lights = i + 1;
    }
    return SOAK_OK;
}

static soak_status parse_materials(scene_ctx *c, const cJSON *j)
{
    soak_scene *s = c->scene;
    if (!j) return sj_fail(c, SOAK_ERR_PARSE, "materials", "missing (required)");
    if (!cJSON_IsObject(j)) return sj_fail(c, SOAK_ERR_PARSE, "materials", "must be an object of named materials");
    for (const cJSON *it = j->child; it; it = it->next) {
        char p[256];
        sj_path(p, sizeof p, "materials", it->string);
        if (strlen(it->string) >= sizeof s->materials->name || !it->string[0])
            return sj_fail(c, SOAK_ERR_ARG, p, "name must have 1 to 63 characters");
        soak_material *m = realloc(s->materials, (size_t)(s->n_materials + 1) * sizeof *m);
        if (!m) return SOAK_ERR_NOMEM;
        s->materials = m;
        m = &s->materials[s->n_materials];
        memset(m, 0, sizeof *m);
        s->n_materials++;
        snprintf(m->name, sizeof m->name, "%s", it->string);
        soak_status st = scene_parse_material(c, it, p, m);
        if (st != SOAK_OK) return st;
    }
    return SOAK_OK;
}

static int find_material(const soak_scene *s, const char *name)
{
    for (int i = 0; i < s->n_materials; ++i)
        if (s->materials[i].type != SOAK_MAT_EMITTER && strcmp(s->materials[i].name, name) == 0) return i;
    return -1;
}

/* The shape parsers: each reads its keys (errors at their JSON paths) and
 * adds the shape to the geometry, returning the new object's id. */
typedef soak_status (*shape_parser)(scene_ctx *c, const cJSON *o, const char *p, unsigned *id);

/* A failure of the geometry to take a shape the parser accepted. */
static soak_status shape_added(scene_ctx *c, const char *p, soak_status st)
{
    if (st != SOAK_OK) return sj_fail(c, st, p, "cannot add the shape (%s)", soak_status_str(st));
    return SOAK_OK;
}

static soak_status add_sphere(scene_ctx *c, const cJSON *o, const char *p, unsigned *id)
{
    static const char *const keys[] = {"type", "material", "wetness", "center", "radius", NULL};
    soak_vec3 center;
    double r;
    soak_status st = sj_keys(c, o, p, keys);
    if (st == SOAK_OK) st = sj_vec3(c, o, "center", p, 1, soak_v3(0, 0, 0), &center);
    if (st == SOAK_OK) st = sj_num_gt(c, o, "radius", p, 0, 1e9, 1, 1, &r);
    if (st != SOAK_OK) return st;
    return shape_added(c, p, soak_geometry_add_sphere(c->scene->geometry, center, r, id));
}

static soak_status add_quad(scene_ctx *c, const cJSON *o, const char *p, unsigned *id)
{
    static const char *const keys[] = {"type", "material", "wetness", "origin", "edge_u", "edge_v", NULL};
    soak_vec3 org, eu, ev;
    soak_status st = sj_keys(c, o, p, keys);
    if (st == SOAK_OK) st = sj_vec3(c, o, "origin", p, 1, soak_v3(0, 0, 0), &org);
    if (st == SOAK_OK) st = sj_vec3(c, o, "edge_u", p, 1, soak_v3(0, 0, 0), &eu);
    if (st == SOAK_OK) st = sj_vec3(c, o, "edge_v", p, 1, soak_v3(0, 0, 0), &ev);
    if (st != SOAK_OK) return st;
    if (!(soak_v3_len(soak_v3_cross(eu, ev)) > 0)) {
        char q[320];
        sj_path(q, sizeof q, p, "edge_v");
        return sj_fail(c, SOAK_ERR_ARG, q, "edges must be non-zero and not parallel");
    }
    return shape_added(c, p, soak_geometry_add_quad(c->scene->geometry, org, eu, ev, id));
}

/* A plane's "size": [width, depth], both > 0 and finite (required). */
static soak_status plane_size(scene_ctx *c, const cJSON *o, const char *p, soak_vec3 *size)
{
    char q[320];
    const cJSON *sz = cJSON_GetObjectItemCaseSensitive(o, "size");
    sj_path(q, sizeof q, p, "size");
    if (!sz) return sj_fail(c, SOAK_ERR_PARSE, q, "missing (required)");
    if (!cJSON_IsArray(sz) || cJSON_GetArraySize(sz) != 2 || !cJSON_IsNumber(cJSON_GetArrayItem(sz, 0)) ||
        !cJSON_IsNumber(cJSON_GetArrayItem(sz, 1)))
        return sj_fail(c, SOAK_ERR_PARSE, q, "must be [width, depth]");
    *size = soak_v3(cJSON_GetArrayItem(sz, 0)->valuedouble, cJSON_GetArrayItem(sz, 1)->valuedouble, 0);
    if (!(size->x > 0 && size->y > 0 && size->x < 1e12 && size->y < 1e12))
        return sj_fail(c, SOAK_ERR_ARG, q, "sizes must be > 0 and finite, got [%g, %g]", size->x, size->y);
    return SOAK_OK;
}

/* A plane is a quad centred at "center", its edges along the tangents of "normal". */
static soak_status add_plane(scene_ctx *c, const cJSON *o, const char *p, unsigned *id)
{
    static const char *const keys[] = {"type", "material", "wetness", "center", "normal", "size", NULL};
    soak_vec3 center, n, size = soak_v3(0, 0, 0);
    soak_status st = sj_keys(c, o, p, keys);
    if (st == SOAK_OK) st = sj_vec3(c, o, "center", p, 0, soak_v3(0, 0, 0), &center);
    if (st == SOAK_OK) st = sj_vec3(c, o, "normal", p, 0, soak_v3(0, 0, 1), &n);
    if (st == SOAK_OK) st = plane_size(c, o, p, &size);
    if (st != SOAK_OK) return st;
    if (!(soak_v3_len(n) > 0)) {
        char q[320];
        sj_path(q, sizeof q, p, "normal");
        return sj_fail(c, SOAK_ERR_ARG, q, "must not be the zero vector");
    }
    soak_vec3 t, b;
    n = soak_v3_norm(n);
    soak_v3_basis(n, &t, &b);
    soak_vec3 eu = soak_v3_scale(t, size.x), ev = soak_v3_scale(b, size.y);
    soak_vec3 org = soak_v3_sub(center, soak_v3_scale(soak_v3_add(eu, ev), 0.5));
    return shape_added(c, p, soak_geometry_add_quad(c->scene->geometry, org, eu, ev, id));
}

static soak_status add_box(scene_ctx *c, const cJSON *o, const char *p, unsigned *id)
{
    static const char *const keys[] = {"type", "material", "wetness", "min", "max", NULL};
    soak_vec3 lo, hi;
    soak_status st = sj_keys(c, o, p, keys);
    if (st == SOAK_OK) st = sj_vec3(c, o, "min", p, 1, soak_v3(0, 0, 0), &lo);
    if (st == SOAK_OK) st = sj_vec3(c, o, "max", p, 1, soak_v3(0, 0, 0), &hi);
    if (st != SOAK_OK) return st;
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) {
        char q[320];
        sj_path(q, sizeof q, p, "max");
        return sj_fail(c, SOAK_ERR_ARG, q, "must exceed min on every axis (negative or zero size)");
    }
    return shape_added(c, p, soak_geometry_add_box(c->scene->geometry, lo, hi, id));
}

/* A mesh's "translate" and "scale" (one number or one per axis, > 0). */
static soak_status mesh_placement(scene_ctx *c, const cJSON *o, const char *p, soak_vec3 *tr, soak_vec3 *sc)
{
    soak_status st = sj_vec3(c, o, "translate", p, 0, soak_v3(0, 0, 0), tr);
    if (st == SOAK_OK && cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(o, "scale"))) {
        double k;
        st = sj_num_gt(c, o, "scale", p, 0, 1e12, 1, 1, &k);
        *sc = soak_v3(k, k, k);
    } else if (st == SOAK_OK) {
        st = sj_vec3(c, o, "scale", p, 0, soak_v3(1, 1, 1), sc);
    }
    if (st != SOAK_OK) return st;
    char q[320];
    sj_path(q, sizeof q, p, "scale");
    if (!(sc->x > 0 && sc->y > 0 && sc->z > 0)) return sj_fail(c, SOAK_ERR_ARG, q, "must be > 0 on every axis");
    return SOAK_OK;
}

/* Does the object's wetness read a map (then the mesh must have texture coordinates)? */
static int wetness_is_map(const cJSON *o)
{
    const cJSON *wet = cJSON_GetObjectItemCaseSensitive(o, "wetness");
    const cJSON *wtype = cJSON_IsObject(wet) ? cJSON_GetObjectItemCaseSensitive(wet, "type") : NULL;
    return cJSON_IsString(wtype) && strcmp(wtype->valuestring, "map") == 0;
}

static soak_status add_mesh(scene_ctx *c, const cJSON *o, const char *p, unsigned *id)
{
    static const char *const keys[] = {"type", "material", "wetness", "file", "translate", "scale", NULL};
    const char *file;
    soak_vec3 tr, sc = soak_v3(1, 1, 1);
    soak_status st = sj_keys(c, o, p, keys);
    if (st == SOAK_OK) st = sj_str(c, o, "file", p, 1, &file);
    if (st == SOAK_OK) st = mesh_placement(c, o, p, &tr, &sc);
    if (st != SOAK_OK) return st;
    char q[320], full[2048], msg[2200];
    sj_path(q, sizeof q, p, "file");
    st = sj_file(c, file, q, full, sizeof full);
    if (st != SOAK_OK) return st;
    soak_mesh mesh;
    st = soak_mesh_load(full, wetness_is_map(o), &mesh, msg, sizeof msg);
    if (st != SOAK_OK) return sj_fail(c, st, q, "%s", msg);
    double xf[12] = {sc.x, 0, 0, tr.x, 0, sc.y, 0, tr.y, 0, 0, sc.z, tr.z};
    st = soak_geometry_add_mesh(c->scene->geometry, &mesh, xf, id);
    soak_mesh_free(&mesh);
    return shape_added(c, p, st);
}

typedef struct shape_type {
    const char *name;
    soak_shape_kind kind;
    shape_parser add;
} shape_type;

static const shape_type *find_shape(const char *name)
{
    static const shape_type shapes[] = {
        {"sphere", SOAK_SHAPE_SPHERE, add_sphere}, {"quad", SOAK_SHAPE_QUAD, add_quad},
        {"plane", SOAK_SHAPE_QUAD, add_plane},     {"box", SOAK_SHAPE_BOX, add_box},
        {"mesh", SOAK_SHAPE_MESH, add_mesh},
    };
    for (size_t i = 0; i < sizeof shapes / sizeof shapes[0]; ++i)
        if (strcmp(name, shapes[i].name) == 0) return &shapes[i];
    return NULL;
}

/* The wetness of the object just added (material mat), when it has one. */
static soak_status parse_object_wetness(scene_ctx *c, const cJSON *o, const char *p, int mat)
{
    soak_scene *s = c->scene;
    const cJSON *w = cJSON_GetObjectItemCaseSensitive(o, "wetness");
    if (!w) return SOAK_OK;
    char q[320];
    sj_path(q, sizeof q, p, "wetness");
    if (s->materials[mat].type != SOAK_MAT_WET && s->materials[mat].type != SOAK_MAT_MODEL)
        return sj_fail(c, SOAK_ERR_ARG, q, "only objects with a \"wet\" or model material take a wetness");
    return scene_parse_wetness(c, w, q, &s->objects[s->n_objects - 1].wetness);
}

static soak_status parse_object(scene_ctx *c, const cJSON *o, const char *p)
{
    soak_scene *s = c->scene;
    const char *type, *mname;
    soak_status st = sj_str(c, o, "type", p, 1, &type);
    if (st == SOAK_OK) st = sj_str(c, o, "material", p, 1, &mname);
    if (st != SOAK_OK) return st;
    char q[320];
    int mat = find_material(s, mname);
    if (mat < 0) {
        sj_path(q, sizeof q, p, "material");
        return sj_fail(c, SOAK_ERR_NOT_FOUND, q, "no material named '%s' in \"materials\"", mname);
    }
    const shape_type *shape = find_shape(type);
    if (!shape) {
        sj_path(q, sizeof q, p, "type");
        return sj_fail(c, SOAK_ERR_PARSE, q, "unknown object type '%s' (accepted: sphere, quad, plane, box, mesh)",
                       type);
    }
    unsigned id = 0;
    st = shape->add(c, o, p, &id);
    if (st == SOAK_OK) st = push_object(s, shape->kind, id, mat);
    if (st == SOAK_OK) st = parse_object_wetness(c, o, p, mat);
    return st;
}

static soak_status parse_objects(scene_ctx *c, const cJSON *j)
{
    if (!j) return sj_fail(c, SOAK_ERR_PARSE, "objects", "missing (required)");
    if (!cJSON_IsArray(j)) return sj_fail(c, SOAK_ERR_PARSE, "objects", "must be an array");
    int i = 0;
    const cJSON *item;
    cJSON_ArrayForEach(item, j) /* cJSON_GetArrayItem(j, i) walks the list: quadratic */
    {
        char p[64];
        sj_index(p, sizeof p, "objects", i++);
        soak_status st = parse_object(c, item, p);
        if (st != SOAK_OK) return st;
    }
    return SOAK_OK;
}

soak_status soak_scene_parse(const char *text, const char *name, const char *base_dir, soak_scene *scene, char *err,
                             size_t errlen)
{
    if (!text || !scene) return SOAK_ERR_NULL;
    memset(scene, 0, sizeof *scene);
    scene_ctx c = {name ? name : "(scene)", base_dir ? base_dir : "", err, errlen, scene, NULL};
    snprintf(scene->path, sizeof scene->path, "%s", c.name);
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithOpts(text, &end, 1);
    if (!root) {
        sj_syntax_error(text, end ? end : text, c.name, err, errlen);
        return SOAK_ERR_PARSE;
    }
    const char *dup = sj_duplicate_key(root);
    if (dup) {
        if (err && errlen) {
            snprintf(err, errlen, "%s: duplicate key \"%s\"", c.name, dup);
            soak_message_printable(err); /* the key comes from the file */
        }
        cJSON_Delete(root);
        return SOAK_ERR_PARSE;
    }
    static const char *const keys[] = {"render", "camera", "environment", "lights", "materials", "objects", NULL};
    soak_status st = sj_keys(&c, root, "(top level)", keys);
    if (st == SOAK_OK) {
        char msg[512];
        st = soak_geometry_create(&scene->geometry, msg, sizeof msg);
        if (st != SOAK_OK) sj_fail(&c, st, "(geometry)", "%s", msg);
    }
    if (st == SOAK_OK) st = parse_render(&c, cJSON_GetObjectItemCaseSensitive(root, "render"));
    if (st == SOAK_OK) st = parse_camera(&c, cJSON_GetObjectItemCaseSensitive(root, "camera"));
    if (st == SOAK_OK) st = parse_environment(&c, cJSON_GetObjectItemCaseSensitive(root, "environment"));
    if (st == SOAK_OK) st = parse_materials(&c, cJSON_GetObjectItemCaseSensitive(root, "materials"));
    if (st == SOAK_OK) st = parse_lights(&c, cJSON_GetObjectItemCaseSensitive(root, "lights"));
    if (st == SOAK_OK) st = parse_objects(&c, cJSON_GetObjectItemCaseSensitive(root, "objects"));
    cJSON_Delete(root);
    if (st == SOAK_OK) st = scene_levels_build(&c, scene);
    soak_presets_free(c.db);
    if (st == SOAK_OK && scene->n_objects == 0) st = sj_fail(&c, SOAK_ERR_ARG, "objects", "the scene has no objects");
    if (st == SOAK_OK && scene->n_lights == 0 && scene->env.type == SOAK_ENV_NONE)
        st = sj_fail(&c, SOAK_ERR_ARG, "lights", "the scene has neither lights nor an environment");
    if (st == SOAK_OK) {
        st = soak_geometry_commit(scene->geometry);
        if (st != SOAK_OK) sj_fail(&c, st, "objects", "geometry could not be built");
    }
    if (st != SOAK_OK) soak_scene_free(scene);
    return st;
}

soak_status soak_scene_load(const char *path, soak_scene *scene, char *err, size_t errlen)
{
    if (!path || !scene) return SOAK_ERR_NULL;
    memset(scene, 0, sizeof *scene);
    if (err && errlen) err[0] = '\0';
    /* soak/input_file.h: a regular file within SOAK_MAX_SCENE_MB, read
     * without growing; every failure names the file. */
    char *text = NULL;
    size_t n = 0;
    soak_status rst = soak_input_read(path, SOAK_INPUT_SCENE, &text, &n, err, errlen);
    if (rst != SOAK_OK) return rst;
    if (strlen(text) != n) { /* the parser would stop there and ignore the rest */
        if (err && errlen) snprintf(err, errlen, "%s: contains a NUL byte at offset %zu", path, strlen(text));
        free(text);
        return SOAK_ERR_PARSE;
    }
    char dir[1024];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash) *slash = '\0';
    else snprintf(dir, sizeof dir, ".");
    soak_status st = soak_scene_parse(text, path, dir, scene, err, errlen);
    free(text);
    if (st != SOAK_OK && err && errlen && !err[0]) /* every failure explains itself, even out of memory */
        snprintf(err, errlen, "%s: %s", path, soak_status_str(st));
    return st;
}

void soak_scene_free(soak_scene *s)
{
    if (!s) return;
    for (int i = 0; i < s->n_materials; ++i) scene_material_free(&s->materials[i]);
    for (int i = 0; i < s->n_objects; ++i)
        if (s->objects[i].wetness.type == SOAK_WETNESS_MAP) soak_image_free(&s->objects[i].wetness.map);
    for (int i = 0; i < s->n_inputs; ++i) free(s->inputs[i]);
    free(s->inputs);
    free(s->materials);
    free(s->objects);
    free(s->lights);
    if (s->env.type == SOAK_ENV_MAP) soak_image_free(&s->env.map);
    soak_geometry_destroy(s->geometry);
    memset(s, 0, sizeof *s);
}
