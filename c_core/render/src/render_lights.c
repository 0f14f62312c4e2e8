/* Light sampling for the path tracer: sun (delta direction), point, spherical
 * area light (uniform cone sampling) and environment maps (luminance-weighted
 * pixel sampling).
 *
 * A constant environment is NOT light-sampled: sampling it uniformly over the
 * sphere knows nothing the BSDF sampler does not (half the samples go below
 * the horizon, the rest ignore the cosine), and under MIS it only adds
 * variance. Paths reach it by BSDF sampling, with MIS weight 1 (its light pdf
 * is 0). Measured on scenes/bench_wet_sphere.json: the per-pixel variance of
 * the sunlit wet ground fell 12x. Cycles makes the same choice (background
 * MIS is disabled unless the world shader varies over directions:
 * LightManager::test_enabled_lights, intern/cycles/scene/light.cpp). */
#include <stdlib.h>
#include <string.h>

#include "render_lights.h"

soak_status rt_env_build(rt_env *env, const soak_environment *e)
{
    memset(env, 0, sizeof *env);
    if (e->type != SOAK_ENV_MAP) return SOAK_OK;
    const soak_image *im = &e->map;
    int W = im->width, H = im->height, C = im->channels;
    env->row_cdf = calloc((size_t)H + 1, sizeof(double));
    env->col_cdf = calloc((size_t)H * (W + 1), sizeof(double));
    if (!env->row_cdf || !env->col_cdf) {
        rt_env_free(env);
        return SOAK_ERR_NOMEM;
    }
    for (int i = 0; i < H; ++i) {
        /* Weight = luminance * solid angle of the pixel (its cos(theta) band). */
        double band = cos(SOAK_PI * i / H) - cos(SOAK_PI * (i + 1) / H);
        double *cc = env->col_cdf + (size_t)i * (W + 1);
        for (int j = 0; j < W; ++j) {
            const float *p = im->pixels + ((size_t)i * W + j) * C;
            double y = C >= 3 ? soak_rgb_luminance(soak_rgb3(p[0], p[1], p[2])) : p[0];
            cc[j + 1] = cc[j] + y * band;
        }
        env->row_cdf[i + 1] = env->row_cdf[i] + cc[W];
    }
    env->total = env->row_cdf[H];
    return SOAK_OK;
}

void rt_env_free(rt_env *env)
{
    free(env->row_cdf);
    free(env->col_cdf);
    memset(env, 0, sizeof *env);
}

/* Direction -> map coordinates (u right, v down from the zenith) in [0,1).
 * Cycles' orientation (direction_to_equirectangular, kernel/geom/geom.h:
 * u = 0.5 - azimuth / 2 pi): the map's centre column at azimuth `rotation`,
 * columns running clockwise seen from above, so a panorama seen from inside
 * is not mirrored and the same file lights soak render and Blender alike. */
static void env_uv(const soak_environment *e, soak_vec3 d, double *u, double *v)
{
    double phi = atan2(d.y, d.x) - e->rotation_deg * SOAK_PI / 180.0;
    double x = 0.5 - phi / (2 * SOAK_PI);
    x -= floor(x);
    *u = x;
    *v = acos(fmax(-1.0, fmin(1.0, d.z))) / SOAK_PI;
}

/* Bilinear between texel centres ((j + 0.5) / W, (i + 0.5) / H): wrapping
 * round the azimuth, clamped at the poles' half rows. A nearest lookup
 * showed a 1024-pixel panorama as blocks at a gallery camera's field of
 * view. Light sampling keeps its piecewise-constant pdf (rt_env_pdf): any
 * pdf that is non-zero wherever the map is keeps the MIS estimate unbiased,
 * and where a dark texel borders a bright one the BSDF samples carry it. */
static soak_rgb env_texel(const soak_image *im, int i, int j)
{
    const float *p = im->pixels + ((size_t)i * im->width + j) * im->channels;
    return im->channels >= 3 ? soak_rgb3(p[0], p[1], p[2]) : soak_rgb3(p[0], p[0], p[0]);
}

soak_rgb rt_env_eval(const rt_ctx *c, soak_vec3 d)
{
    const soak_environment *e = &c->scene->env;
    if (e->type == SOAK_ENV_CONSTANT) return e->radiance;
    if (e->type != SOAK_ENV_MAP) return soak_rgb3(0, 0, 0);
    double u, v;
    env_uv(e, d, &u, &v);
    const soak_image *im = &e->map;
    int W = im->width, H = im->height;
    double x = u * W - 0.5, y = fmin(fmax(v * H - 0.5, 0.0), H - 1.0);
    double fx = x - floor(x), fy = y - floor(y);
    int j0 = (int)floor(x), i0 = (int)y, i1 = i0 + 1 < H ? i0 + 1 : H - 1;
    j0 = ((j0 % W) + W) % W;
    int j1 = (j0 + 1) % W;
    soak_rgb top =
        soak_rgb_add(soak_rgb_scale(env_texel(im, i0, j0), 1 - fx), soak_rgb_scale(env_texel(im, i0, j1), fx));
    soak_rgb bot =
        soak_rgb_add(soak_rgb_scale(env_texel(im, i1, j0), 1 - fx), soak_rgb_scale(env_texel(im, i1, j1), fx));
    return soak_rgb_scale(soak_rgb_add(soak_rgb_scale(top, 1 - fy), soak_rgb_scale(bot, fy)), e->scale);
}

double rt_env_pdf(const rt_ctx *c, soak_vec3 d)
{
    const soak_environment *e = &c->scene->env;
    if (e->type != SOAK_ENV_MAP || !(c->env.total > 0)) return 0;
    double u, v;
    env_uv(e, d, &u, &v);
    int W = e->map.width, H = e->map.height;
    int j = (int)(u * W), i = (int)(v * H);
    j = j >= W ? W - 1 : j;
    i = i >= H ? H - 1 : i;
    const double *cc = c->env.col_cdf + (size_t)i * (W + 1);
    double w = cc[j + 1] - cc[j];
    double band = cos(SOAK_PI * i / H) - cos(SOAK_PI * (i + 1) / H);
    if (!(band > 0)) return 0;
    /* Pixel chosen with probability w/total, then uniform over its solid angle. */
    return w / c->env.total / (band * 2 * SOAK_PI / W);
}

static int upper_bound(const double *cdf, int n, double x)
{
    int lo = 0, hi = n; /* find i with cdf[i] <= x < cdf[i+1] */
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (cdf[mid] <= x) lo = mid;
        else hi = mid;
    }
    return lo;
}

static int env_sample(rt_thread *t, rt_light_sample *s)
{
    const rt_ctx *c = t->ctx;
    const soak_environment *e = &c->scene->env;
    if (e->type != SOAK_ENV_MAP || !(c->env.total > 0)) return 0;
    int W = e->map.width, H = e->map.height;
    double u_row, u_col, u_x, u_z;
    rt_rand2(t, &u_row, &u_col);
    rt_rand2(t, &u_x, &u_z);
    int i = upper_bound(c->env.row_cdf, H, u_row * c->env.total);
    const double *cc = c->env.col_cdf + (size_t)i * (W + 1);
    if (!(cc[W] > 0)) return 0;
    int j = upper_bound(cc, W, u_col * cc[W]);
    double u = (j + u_x) / W;
    /* Uniform in cos(theta) over the pixel's band = uniform in solid angle. */
    double z0 = cos(SOAK_PI * i / H), z1 = cos(SOAK_PI * (i + 1) / H);
    double z = z0 + (z1 - z0) * u_z;
    double phi = 2 * SOAK_PI * (0.5 - u) + e->rotation_deg * SOAK_PI / 180.0, r = sqrt(fmax(0.0, 1 - z * z));
    s->wi = soak_v3(r * cos(phi), r * sin(phi), z);
    s->L = rt_env_eval(c, s->wi);
    s->dist = INFINITY;
    s->pdf = rt_env_pdf(c, s->wi);
    return s->pdf > 0 && rgb_max(s->L) > 0;
}

int rt_light_count(const rt_ctx *c) { return c->scene->n_lights + (c->scene->env.type == SOAK_ENV_MAP); }

double rt_sphere_light_pdf(const soak_light *l, soak_vec3 p)
{
    double d2 = soak_v3_dot(soak_v3_sub(l->position, p), soak_v3_sub(l->position, p));
    double r2 = l->radius * l->radius;
    if (!(d2 > r2)) return 0;
    double s2 = r2 / d2, cosmax = sqrt(1 - s2);
    /* 1 - cos_max = s2 / (1 + cos_max), stable for small lights. */
    return 1.0 / (2 * SOAK_PI * s2 / (1 + cosmax));
}

int rt_light_sample_at(rt_thread *t, int light, soak_vec3 p, rt_light_sample *s)
{
    const soak_scene *sc = t->ctx->scene;
    if (light >= sc->n_lights) return env_sample(t, s);
    const soak_light *l = &sc->lights[light];
    switch (l->type) {
    case SOAK_LIGHT_DIRECTIONAL:
        s->wi = l->direction;
        s->dist = INFINITY;
        s->L = l->value;
        s->pdf = 0;
        return rgb_max(s->L) > 0;
    case SOAK_LIGHT_POINT: {
        soak_vec3 d = soak_v3_sub(l->position, p);
        double r2 = soak_v3_dot(d, d);
        if (!(r2 > 0)) return 0;
        s->dist = sqrt(r2);
        s->wi = soak_v3_scale(d, 1.0 / s->dist);
        s->L = soak_rgb_scale(l->value, 1.0 / r2);
        s->pdf = 0;
        return rgb_max(s->L) > 0;
    }
    case SOAK_LIGHT_SPHERE: {
        soak_vec3 d = soak_v3_sub(l->position, p);
        double dist = soak_v3_len(d), r = l->radius;
        if (!(dist > r)) return 0;
        soak_vec3 axis = soak_v3_scale(d, 1.0 / dist);
        double s2 = r * r / (dist * dist), cosmax = sqrt(1 - s2);
        double one_minus = s2 / (1 + cosmax);
        double u_cos, u_phi;
        rt_rand2(t, &u_cos, &u_phi);
        double cos_t = 1 - u_cos * one_minus, sin_t = sqrt(fmax(0.0, 1 - cos_t * cos_t));
        double phi = 2 * SOAK_PI * u_phi;
        rt_frame f = rt_frame_make(axis);
        s->wi = soak_v3_norm(rt_to_world(&f, soak_v3(sin_t * cos(phi), sin_t * sin(phi), cos_t)));
        /* Nearer root of the ray-sphere intersection. */
        double b = dist * cos_t, disc = r * r - dist * dist * sin_t * sin_t;
        s->dist = b - sqrt(fmax(0.0, disc));
        s->L = l->value;
        s->pdf = 1.0 / (2 * SOAK_PI * one_minus);
        return rgb_max(s->L) > 0;
    }
    }
    return 0;
}

int rt_visible(rt_thread *t, soak_vec3 p, soak_vec3 wi, double dist)
{
    /* Stop short of the light's own surface (sphere lights are geometry). */
    soak_ray r = {p, wi, 0.0, dist < INFINITY ? dist * (1 - 1e-5) : INFINITY};
    if (!(r.tfar > 0)) return 1;
    int occ = 1;
    t->n.rays++;
    if (soak_geometry_occluded(t->ctx->scene->geometry, &r, &occ) != SOAK_OK) {
        t->n.geom_errors++;
        return 0;
    }
    return !occ;
}
