/* Step 1 of the rain bake (soak/bake_rain.h): the mesh's faces drawn into
 * UV space under the rules of soak/bake_uv.h. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_rain_surface.h"

/* What one face puts in a texel, before the overlap rule picks among faces. */
typedef struct texel_value {
    float area;
    soak_vec3 ng, sx, sy;
} texel_value;

/* A face in texel space: corners X, Y (shifted to its tile), the barycentric
 * derivatives and what it stores. */
typedef struct face {
    double X[3], Y[3], dadx, dbdx, dady, dbdy;
    soak_vec3 P[3], e1, e2;
    texel_value v;
    int wrap; /* 1: texels past the map wrap around; 0: cut */
} face;

/* The overlap rule (soak/bake_uv.h): 1 when what (val, p) stores is
 * greater than what texel i holds. A total order on the stored values. */
static int wins(const rain_surface *s, size_t i, const texel_value *val, soak_vec3 p)
{
    double a[13] = {val->area,
                    p.x,
                    p.y,
                    p.z,
                    (float)val->ng.x,
                    (float)val->ng.y,
                    (float)val->ng.z,
                    (float)val->sx.x,
                    (float)val->sx.y,
                    (float)val->sx.z,
                    (float)val->sy.x,
                    (float)val->sy.y,
                    (float)val->sy.z};
    double b[13] = {s->area[i],        s->pos[3 * i],      s->pos[3 * i + 1], s->pos[3 * i + 2],  s->nrm[3 * i],
                    s->nrm[3 * i + 1], s->nrm[3 * i + 2],  s->dpdx[3 * i],    s->dpdx[3 * i + 1], s->dpdx[3 * i + 2],
                    s->dpdy[3 * i],    s->dpdy[3 * i + 1], s->dpdy[3 * i + 2]};
    for (int k = 0; k < 13; ++k)
        if (a[k] != b[k]) return a[k] > b[k];
    return 0;
}

static void store(rain_surface *s, size_t i, const texel_value *val, soak_vec3 p, soak_vec3 up, int t)
{
    s->tri[i] = t;
    s->pos[3 * i] = p.x, s->pos[3 * i + 1] = p.y, s->pos[3 * i + 2] = p.z;
    s->nrm[3 * i] = (float)val->ng.x, s->nrm[3 * i + 1] = (float)val->ng.y, s->nrm[3 * i + 2] = (float)val->ng.z;
    s->dpdx[3 * i] = (float)val->sx.x, s->dpdx[3 * i + 1] = (float)val->sx.y, s->dpdx[3 * i + 2] = (float)val->sx.z;
    s->dpdy[3 * i] = (float)val->sy.x, s->dpdy[3 * i + 1] = (float)val->sy.y, s->dpdy[3 * i + 2] = (float)val->sy.z;
    s->area[i] = val->area;
    s->level[i] = soak_v3_dot(p, up);
}

#define WRAP_TILES 4.0

/* Draws face f (index t); returns the texels it covers. hits counts the
 * faces over each texel (saturating at 2). */
static long long draw(rain_surface *s, const face *f, int t, soak_vec3 up, unsigned char *hits)
{
    double xmin = fmin(f->X[0], fmin(f->X[1], f->X[2])), xmax = fmax(f->X[0], fmax(f->X[1], f->X[2]));
    double ymin = fmin(f->Y[0], fmin(f->Y[1], f->Y[2])), ymax = fmax(f->Y[0], fmax(f->Y[1], f->Y[2]));
    double x0 = floor(xmin - 0.5), x1 = ceil(xmax - 0.5), y0 = floor(ymin - 0.5), y1 = ceil(ymax - 0.5);
    /* A face over more than WRAP_TILES tiles (corrupt UVs, not a layout) is cut at the map's border. */
    if (!f->wrap || xmax - xmin > WRAP_TILES * s->w || ymax - ymin > WRAP_TILES * s->h)
        x0 = fmax(x0, 0), y0 = fmax(y0, 0), x1 = fmin(x1, s->w - 1.0), y1 = fmin(y1, s->h - 1.0);
    const double eps = -1e-9;
    long long n = 0;
    for (long y = (long)y0; y <= (long)y1; ++y)
        for (long x = (long)x0; x <= (long)x1; ++x) {
            double px = x + 0.5 - f->X[0], py = y + 0.5 - f->Y[0];
            double a = px * f->dadx + py * f->dady, b = px * f->dbdx + py * f->dbdy;
            if (a < eps || b < eps || a + b > 1.0 - eps) continue;
            long wx = ((x % s->w) + s->w) % s->w, wy = ((y % s->h) + s->h) % s->h;
            size_t i = (size_t)wy * s->w + wx;
            soak_vec3 p = soak_v3_add(f->P[0], soak_v3_add(soak_v3_scale(f->e1, a), soak_v3_scale(f->e2, b)));
            ++n;
            if (hits[i] < 2) ++hits[i];
            if (s->tri[i] < 0 || wins(s, i, &f->v, p)) store(s, i, &f->v, p, up, t);
        }
    return n;
}

/* Face t's corners in texel space and what it stores; 0 when degenerate. */
static int setup(const soak_mesh *m, size_t t, double su, double sv, const rain_surface *s, face *f)
{
    const unsigned *ix = m->indices + 3 * t;
    for (int k = 0; k < 3; ++k) {
        f->X[k] = (m->uvs[2 * ix[k]] - su) * s->w;
        f->Y[k] = (1.0 - (m->uvs[2 * ix[k] + 1] - sv)) * s->h;
        f->P[k] = soak_rain_vget(m->positions, ix[k]);
    }
    double den = (f->X[1] - f->X[0]) * (f->Y[2] - f->Y[0]) - (f->X[2] - f->X[0]) * (f->Y[1] - f->Y[0]);
    f->e1 = soak_v3_sub(f->P[1], f->P[0]), f->e2 = soak_v3_sub(f->P[2], f->P[0]);
    soak_vec3 cr = soak_v3_cross(f->e1, f->e2);
    double area3 = 0.5 * soak_v3_len(cr);
    if (!(fabs(den) > 1e-12) || !(area3 > 0.0) || !soak_is_finite(den)) return 0;
    f->v.ng = soak_v3_scale(cr, 0.5 / area3);
    if (m->normals) {
        soak_vec3 vn = soak_v3_add(soak_v3_add(soak_rain_vget(m->normals, ix[0]), soak_rain_vget(m->normals, ix[1])),
                                   soak_rain_vget(m->normals, ix[2]));
        if (soak_v3_dot(vn, f->v.ng) < 0) f->v.ng = soak_v3_scale(f->v.ng, -1.0);
    }
    f->v.area = (float)(area3 / (0.5 * fabs(den)));
    /* World step per texel: P = P0 + a (P1-P0) + b (P2-P0) solved for X, Y. */
    double ia = 1.0 / den;
    f->dadx = (f->Y[2] - f->Y[0]) * ia, f->dbdx = -(f->Y[1] - f->Y[0]) * ia;
    f->dady = -(f->X[2] - f->X[0]) * ia, f->dbdy = (f->X[1] - f->X[0]) * ia;
    f->v.sx = soak_v3_add(soak_v3_scale(f->e1, f->dadx), soak_v3_scale(f->e2, f->dbdx));
    f->v.sy = soak_v3_add(soak_v3_scale(f->e1, f->dady), soak_v3_scale(f->e2, f->dbdy));
    return 1;
}

static void uv_box(const soak_mesh *m, size_t t, double lo[2], double hi[2], double mid[2])
{
    const unsigned *ix = m->indices + 3 * t;
    for (int c = 0; c < 2; ++c) {
        double a = m->uvs[2 * ix[0] + c], b = m->uvs[2 * ix[1] + c], d = m->uvs[2 * ix[2] + c];
        lo[c] = fmin(a, fmin(b, d)), hi[c] = fmax(a, fmax(b, d)), mid[c] = (a + b + d) / 3.0;
    }
}

/* The tile shift (su, sv) of face t under o, and whether its texels wrap;
 * 0: the face is left out (another UDIM tile, or skipped outside). */
static int place(const soak_mesh *m, size_t t, const soak_uv_options *o, soak_uv_stats *st, double *su, double *sv,
                 int *wrap)
{
    double lo[2], hi[2], mid[2];
    uv_box(m, t, lo, hi, mid);
    *wrap = 0;
    if (o->udim_tile) {
        int k = (o->udim_tile - SOAK_UDIM_FIRST) % 10, l = (o->udim_tile - SOAK_UDIM_FIRST) / 10;
        if (floor(mid[0]) != k || floor(mid[1]) != l) return ++st->other_tile_faces, 0;
        *su = k, *sv = l;
        if (lo[0] < k - SOAK_UV_TOL || hi[0] > k + 1 + SOAK_UV_TOL || lo[1] < l - SOAK_UV_TOL ||
            hi[1] > l + 1 + SOAK_UV_TOL)
            ++st->outside_faces;
        return 1;
    }
    *su = *sv = 0;
    if (lo[0] >= -SOAK_UV_TOL && lo[1] >= -SOAK_UV_TOL && hi[0] <= 1 + SOAK_UV_TOL && hi[1] <= 1 + SOAK_UV_TOL)
        return 1;
    ++st->outside_faces;
    if (o->outside != SOAK_UV_WRAP) return 0;
    *su = floor(lo[0] + SOAK_UV_TOL), *sv = floor(lo[1] + SOAK_UV_TOL);
    *wrap = 1;
    return 1;
}

static soak_status refuse_outside(const soak_mesh *m, const soak_uv_stats *st, char *err, size_t errlen)
{
    for (size_t t = 0; t < m->n_triangles; ++t) {
        double lo[2], hi[2], mid[2];
        if (m->tri_uv && !m->tri_uv[t]) continue;
        uv_box(m, t, lo, hi, mid);
        if (lo[0] >= -SOAK_UV_TOL && lo[1] >= -SOAK_UV_TOL && hi[0] <= 1 + SOAK_UV_TOL && hi[1] <= 1 + SOAK_UV_TOL)
            continue;
        if (err && errlen)
            snprintf(err, errlen,
                     "%lld of %lld faces have UVs outside [0, 1]^2 (face %zu spans u %g..%g, v %g..%g): "
                     "--uv-outside wrap bakes them as a repeating texture, skip leaves them out, or name the "
                     "output with <UDIM> for one map per tile",
                     st->outside_faces, st->faces, t + 1, lo[0], hi[0], lo[1], hi[1]);
        break;
    }
    return SOAK_ERR_ARG;
}

soak_status soak_rain_rasterise(const soak_mesh *m, const soak_uv_options *o, rain_surface *s, soak_vec3 up,
                                soak_uv_stats *st, char *err, size_t errlen)
{
    size_t n = (size_t)s->w * s->h;
    unsigned char *hits = calloc(n, 1);
    if (!hits) return SOAK_ERR_NOMEM;
    memset(st, 0, sizeof *st);
    st->texels = (long long)n;
    st->faces = (long long)m->n_triangles;
    st->outside_wrapped = o->outside == SOAK_UV_WRAP && !o->udim_tile;
    for (size_t i = 0; i < n; ++i) s->tri[i] = -1;
    for (size_t t = 0; t < m->n_triangles; ++t) {
        face f;
        double su, sv;
        if (m->tri_uv && !m->tri_uv[t]) {
            ++st->no_uv_faces;
            continue;
        }
        if (!place(m, t, o, st, &su, &sv, &f.wrap)) continue;
        if (o->outside == SOAK_UV_REFUSE && st->outside_faces && !o->udim_tile) continue;
        if (!setup(m, t, su, sv, s, &f)) {
            ++st->degenerate_faces;
            continue;
        }
        double uv_area = 0.5 * fabs((f.X[1] - f.X[0]) * (f.Y[2] - f.Y[0]) - (f.X[2] - f.X[0]) * (f.Y[1] - f.Y[0])) /
                         ((double)s->w * s->h);
        st->uv_area += uv_area;
        if (draw(s, &f, (int)(t < 0x7fffffff ? t : 0x7fffffff), up, hits) > 0) {
            ++st->baked_faces;
            st->uv_area_seen += uv_area;
        } else {
            ++st->unseen_faces;
        }
    }
    for (size_t i = 0; i < n; ++i) st->covered += hits[i] > 0, st->shared += hits[i] > 1;
    free(hits);
    if (o->outside == SOAK_UV_REFUSE && st->outside_faces && !o->udim_tile) return refuse_outside(m, st, err, errlen);
    return SOAK_OK;
}

/* Texture coordinates beyond this are not a texture layout but corrupt data
 * (a UV of 1e30 was called "not finite"). */
#define SOAK_RAIN_UV_MAX 1e6

soak_status soak_rain_check_mesh(const soak_mesh *m, char *err, size_t errlen)
{
    if (!m->positions || !m->indices || m->n_triangles == 0 || m->n_vertices == 0) {
        if (err && errlen) snprintf(err, errlen, "mesh has no triangles");
        return SOAK_ERR_ARG;
    }
    if (!m->uvs) {
        if (err && errlen) snprintf(err, errlen, "mesh has no UVs: the rain bake needs texture coordinates");
        return SOAK_ERR_ARG;
    }
    for (size_t i = 0; i < 3 * m->n_triangles; ++i)
        if (m->indices[i] >= m->n_vertices) {
            if (err && errlen) snprintf(err, errlen, "mesh index %zu out of range", i);
            return SOAK_ERR_ARG;
        }
    for (size_t i = 0; i < m->n_vertices; ++i) {
        for (int k = 0; k < 3; ++k)
            if (!soak_is_finite(m->positions[3 * i + k])) {
                if (err && errlen) snprintf(err, errlen, "mesh vertex %zu is not finite", i);
                return SOAK_ERR_ARG;
            }
        if (!soak_in_range(m->uvs[2 * i], -SOAK_RAIN_UV_MAX, SOAK_RAIN_UV_MAX) ||
            !soak_in_range(m->uvs[2 * i + 1], -SOAK_RAIN_UV_MAX, SOAK_RAIN_UV_MAX)) {
            if (err && errlen)
                snprintf(err, errlen, "mesh UV %zu (%g, %g) is out of range: UVs must be finite and within [-%g, %g]",
                         i, m->uvs[2 * i], m->uvs[2 * i + 1], SOAK_RAIN_UV_MAX, SOAK_RAIN_UV_MAX);
            return SOAK_ERR_ARG;
        }
    }
    return SOAK_OK;
}

/* ---- the report ---- */

void soak_uv_stats_add(soak_uv_stats *a, const soak_uv_stats *b)
{
    a->texels += b->texels, a->covered += b->covered, a->shared += b->shared;
    a->faces = b->faces; /* the same faces in every tile */
    a->baked_faces += b->baked_faces, a->degenerate_faces += b->degenerate_faces;
    a->outside_faces += b->outside_faces, a->unseen_faces += b->unseen_faces;
    a->no_uv_faces = b->no_uv_faces, a->other_tile_faces = 0;
    a->outside_wrapped = b->outside_wrapped;
    a->uv_area += b->uv_area, a->uv_area_seen += b->uv_area_seen;
}

static double pct(double a, double b) { return b > 0 ? 100.0 * a / b : 0.0; }

int soak_uv_stats_warning(const soak_uv_stats *s, char *msg, size_t n)
{
    char line[512];
    soak_uv_stats_line(s, line, sizeof line);
    const char *why = NULL;
    char buf[256];
    if (s->covered == 0) {
        why = "the map is empty: no face covers a texel centre";
    } else if (s->no_uv_faces > 0) {
        snprintf(buf, sizeof buf, "partial UVs: %lld of %lld faces have none and are not in the map", s->no_uv_faces,
                 s->faces);
        why = buf;
    } else if (s->uv_area > 0 && s->uv_area_seen < SOAK_UV_MIN_SEEN * s->uv_area) {
        snprintf(buf, sizeof buf,
                 "faces holding %.1f %% of the UV area (over the %.0f %% allowed) fall between "
                 "texel centres: raise --width/--height",
                 pct(s->uv_area - s->uv_area_seen, s->uv_area), 100.0 * (1.0 - SOAK_UV_MIN_SEEN));
        why = buf;
    }
    if (!why) return 0;
    if (msg && n) snprintf(msg, n, "%s (%s)", why, line);
    return 1;
}

void soak_uv_stats_line(const soak_uv_stats *s, char *buf, size_t n)
{
    snprintf(buf, n,
             "%lld of %lld texels covered (%.1f %%), %.1f %% of them by overlapping faces; %lld of %lld "
             "faces baked, %lld without UVs, %lld degenerate, %lld outside [0,1]^2 %s, %lld smaller than a texel",
             s->covered, s->texels, pct((double)s->covered, (double)s->texels),
             pct((double)s->shared, (double)s->covered), s->baked_faces, s->faces, s->no_uv_faces, s->degenerate_faces,
             s->outside_faces, s->outside_wrapped ? "(wrapped)" : "(left out or cut)", s->unseen_faces);
}

soak_status soak_uv_udim_tiles(const soak_mesh *m, int *tiles, int max, int *count, char *err, size_t errlen)
{
    unsigned char used[SOAK_UDIM_LAST - SOAK_UDIM_FIRST + 1] = {0};
    *count = 0;
    for (size_t t = 0; m->uvs && t < m->n_triangles; ++t) {
        double lo[2], hi[2], mid[2];
        if (m->tri_uv && !m->tri_uv[t]) continue;
        uv_box(m, t, lo, hi, mid);
        if (!(mid[0] >= 0 && mid[0] < 10 && mid[1] >= 0 && mid[1] < 100)) {
            if (err && errlen)
                snprintf(err, errlen,
                         "face %zu's UV centre (%g, %g) is outside the UDIM range u 0..10, v 0..100 "
                         "(tiles %d..%d)",
                         t + 1, mid[0], mid[1], SOAK_UDIM_FIRST, SOAK_UDIM_LAST);
            return SOAK_ERR_ARG;
        }
        used[(int)floor(mid[0]) + 10 * (int)floor(mid[1])] = 1;
    }
    for (int k = 0; k <= SOAK_UDIM_LAST - SOAK_UDIM_FIRST; ++k)
        if (used[k]) {
            if (*count < max) tiles[*count] = SOAK_UDIM_FIRST + k;
            ++*count;
        }
    return SOAK_OK;
}
