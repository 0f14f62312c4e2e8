/* The denoiser's guide (soak/denoise.h): what the scene's camera sees first
 * in each pixel, through the same pinhole or thin lens as render.c's camera
 * rays, at fixed points spread over the pixel (the R2 sequence, Roberts
 * 2018) and over the lens (Vogel's golden-angle spiral), so the features
 * blur where the lens blurs the picture. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "soak/denoise.h"
#include "soak/geometry.h"

typedef struct feat_cam {
    soak_vec3 pos, fwd, right, up;
    double tan_half, aspect, aperture, focus;
    int W, H;
} feat_cam;

static feat_cam feat_camera(const soak_camera *cam, int W, int H)
{
    feat_cam c;
    c.pos = cam->position;
    c.fwd = soak_v3_norm(soak_v3_sub(cam->look_at, cam->position));
    c.right = soak_v3_norm(soak_v3_cross(c.fwd, cam->up));
    c.up = soak_v3_cross(c.right, c.fwd);
    c.tan_half = tan(cam->fov_deg * SOAK_PI / 360.0);
    c.aspect = (double)W / H;
    c.aperture = cam->aperture;
    c.focus = cam->focus_distance;
    c.W = W;
    c.H = H;
    return c;
}

/* Ray k of n through pixel (px, py): sub-pixel point k of the R2 sequence,
 * lens point k of the spiral (k = 0: the pixel's and the lens's centres). */
static soak_ray feat_ray(const feat_cam *c, int px, int py, int k, int n)
{
    double jx = k ? fmod(0.5 + k * 0.7548776662466927, 1.0) : 0.5;
    double jy = k ? fmod(0.5 + k * 0.5698402909980532, 1.0) : 0.5;
    double sx = (2 * (px + jx) / c->W - 1) * c->tan_half * c->aspect;
    double sy = (1 - 2 * (py + jy) / c->H) * c->tan_half;
    soak_vec3 d = soak_v3_norm(soak_v3_add(c->fwd, soak_v3_add(soak_v3_scale(c->right, sx), soak_v3_scale(c->up, sy))));
    soak_ray ray = {c->pos, d, 0.0, INFINITY};
    if (c->aperture > 0 && k > 0) {
        soak_vec3 focus = soak_v3_add(c->pos, soak_v3_scale(d, c->focus / soak_v3_dot(d, c->fwd)));
        double r = c->aperture * sqrt((k + 0.5) / n), phi = k * 2.399963229728653; /* golden angle */
        ray.org =
            soak_v3_add(c->pos, soak_v3_add(soak_v3_scale(c->right, r * cos(phi)), soak_v3_scale(c->up, r * sin(phi))));
        ray.dir = soak_v3_norm(soak_v3_sub(focus, ray.org));
    }
    return ray;
}

/* Pixel i's features from n rays; SOAK_OK or the geometry's error. */
static soak_status feat_pixel(const soak_scene *s, const feat_cam *c, int px, int py, int n, soak_denoise_features *f)
{
    size_t i = (size_t)py * c->W + px;
    double nsum[3] = {0, 0, 0}, psum[3] = {0, 0, 0}, zsum = 0, wsum = 0;
    int hits = 0;
    f->object[i] = -1;
    for (int k = 0; k < n; ++k) {
        soak_ray ray = feat_ray(c, px, py, k, n);
        soak_hit hit;
        int found = 0;
        soak_status st = soak_geometry_intersect(s->geometry, &ray, &hit, &found);
        if (st != SOAK_OK) return st;
        if (!found) continue;
        /* The shading normal, or the geometric one where they part (a
         * mesh's generated normals can be far off its faces: a thin box's
         * corners average its sides in); the geometric normal alone would
         * show a smooth mesh's facets through the filter. */
        soak_vec3 nf = soak_v3_dot(hit.ns, hit.ng) > 0.9 ? hit.ns : hit.ng;
        soak_vec3 ns = soak_v3_dot(nf, ray.dir) > 0 ? soak_v3_scale(nf, -1) : nf;
        nsum[0] += ns.x;
        nsum[1] += ns.y;
        nsum[2] += ns.z;
        zsum += hit.t;
        psum[0] += hit.p.x;
        psum[1] += hit.p.y;
        psum[2] += hit.p.z;
        if (hit.object_id < (unsigned)s->n_objects)
            wsum += soak_scene_wetness(&s->objects[hit.object_id], hit.p, hit.u, hit.v);
        if (k == 0) f->object[i] = (int)hit.object_id;
        hits++;
    }
    for (int a = 0; a < 3; ++a) {
        f->normal[3 * i + a] = (float)(nsum[a] / n);
        f->position[3 * i + a] = hits ? (float)(psum[a] / hits) : 0.0f;
    }
    f->depth[i] = hits ? (float)(zsum / hits) : 0.0f;
    f->wetness[i] = hits ? (float)(wsum / hits) : 0.0f;
    return SOAK_OK;
}

void soak_denoise_features_free(soak_denoise_features *f)
{
    if (!f) return;
    free(f->normal);
    free(f->position);
    free(f->depth);
    free(f->object);
    free(f->wetness);
    memset(f, 0, sizeof *f);
}

soak_status soak_render_features(const soak_scene *scene, int width, int height, int lens_samples,
                                 soak_denoise_features *out, char *err, size_t errlen)
{
    if (!scene || !out) return SOAK_ERR_NULL;
    memset(out, 0, sizeof *out);
    if (!(width >= 1 && width <= SOAK_RENDER_MAX_SIZE && height >= 1 && height <= SOAK_RENDER_MAX_SIZE &&
          lens_samples >= 1 && lens_samples <= 256)) {
        if (err && errlen) snprintf(err, errlen, "features: size or lens samples out of range");
        return SOAK_ERR_ARG;
    }
    size_t n = (size_t)width * height;
    out->width = width;
    out->height = height;
    out->normal = malloc(3 * n * sizeof(float));
    out->position = malloc(3 * n * sizeof(float));
    out->depth = malloc(n * sizeof(float));
    out->object = malloc(n * sizeof(int));
    out->wetness = malloc(n * sizeof(float));
    soak_status st =
        out->normal && out->position && out->depth && out->object && out->wetness ? SOAK_OK : SOAK_ERR_NOMEM;
    feat_cam c = feat_camera(&scene->camera, width, height);
    for (int y = 0; y < height && st == SOAK_OK; ++y)
        for (int x = 0; x < width && st == SOAK_OK; ++x) st = feat_pixel(scene, &c, x, y, lens_samples, out);
    if (st != SOAK_OK) {
        if (err && errlen) snprintf(err, errlen, "features: %s", soak_status_str(st));
        soak_denoise_features_free(out);
    }
    return st;
}
