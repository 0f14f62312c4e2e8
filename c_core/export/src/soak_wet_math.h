/* soak_wet_math.h: the arithmetic of Soak's OSL shaders, written in the
 * common subset of C and OSL so that one text serves both. Its one source is
 * c_core/export/src/soak_wet_math.h: the C tests (tests/c/export/test_osl_math.c)
 * compile it and check it against the core, `soak export --target osl` (and
 * osl-legacy, osl-sheet, osl-wetmap) inlines it into the shipped,
 * self-contained shaders, and `soak export --target osl-math` writes it to
 * osl/soak_wet_math.h for shaders of your own. No physics is derived here:
 * the shaders only look up tables the core computed (soak/export.h) and apply
 * the pore-filling schedule.
 *
 * Subset rules: float and int only, no pointers in OSL (SOAK_ARR), no
 * library calls but sqrt and exp (C includers include <math.h> first), loops with
 * "i += 1", ternaries allowed. Define SOAK_OSL before including it in a
 * shader. */
#ifndef SOAK_WET_MATH_H
#define SOAK_WET_MATH_H

#ifdef SOAK_OSL
#define SOAK_ARR(name) float name[]
#define SOAK_FN float
#define SOAK_IFN int
#else
#define SOAK_ARR(name) const float *name
#define SOAK_FN static inline float
#define SOAK_IFN static inline int
#endif

SOAK_FN soak_clamp01(float x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }

/* Hnat et al. 2006 ([Hnat06] sec. 3.3.2): delivered liquid L = w P, the
 * progress P = clamp((t - t0) / t_fill, 0, 1), a step at t0 when t_fill = 0
 * (soak/wetness.h step 1). */
SOAK_FN soak_delivered(float wetness, float time, float t0, float t_fill)
{
    float progress = 0.0;
    if (t_fill <= 0.0) {
        progress = time >= t0 ? 1.0 : 0.0;
    } else {
        progress = soak_clamp01((time - t0) / t_fill);
    }
    return soak_clamp01(wetness) * progress;
}

/* Drying, the mirror of wetting: the liquid a point held (wetness) leaves
 * over t_fill from its start time t0 (a `soak bake drying` map). */
SOAK_FN soak_remaining(float wetness, float time, float t0, float t_fill)
{
    return soak_clamp01(wetness) - soak_delivered(wetness, time, t0, t_fill);
}

/* Unpolarised Fresnel reflectance of a smooth dielectric interface, cos_i
 * the cosine of incidence, eta = n_transmitted / n_incident (Born & Wolf,
 * sec. 1.5; the core's soak_fresnel_dielectric). The shaders weight the
 * liquid's mirror with it: Cycles' reflection() closure is a perfect mirror
 * with no Fresnel term of its own (kernel/osl/closures_setup.h), in 3.x and
 * 4.x alike. */
SOAK_FN soak_fresnel(float cos_i, float eta)
{
    if (eta == 1.0) return 0.0;
    float c = soak_clamp01(cos_i);
    float s2 = (1.0 - c * c) / (eta * eta);
    if (s2 >= 1.0) return 1.0;
    float ct = sqrt(1.0 - s2);
    float rs = (c - eta * ct) / (c + eta * ct);
    float rp = (eta * c - ct) / (eta * c + ct);
    return 0.5 * (rs * rs + rp * rp);
}

/* Index i of the cell [x[off+i], x[off+i+1]] holding v among n >= 2
 * increasing nodes (clamped to the first and last cell). */
SOAK_IFN soak_cell(SOAK_ARR(x), int off, int n, float v)
{
    int i = 0;
    while (i < n - 2 && v > x[off + i + 1]) i += 1;
    return i;
}

/* Weight of the upper node of cell i, clamped to [0,1] outside the nodes. */
SOAK_FN soak_cell_t(SOAK_ARR(x), int off, int i, float v)
{
    float a = x[off + i], b = x[off + i + 1];
    return soak_clamp01((v - a) / (b - a));
}

/* Linear interpolation over n knots x[xoff..] of values stored with a
 * stride (3 for colours: pass the channel in yoff). */
SOAK_FN soak_interp(SOAK_ARR(x), int xoff, int n, float v, SOAK_ARR(y), int yoff, int stride)
{
    int i = soak_cell(x, xoff, n, v);
    float t = soak_cell_t(x, xoff, i, v);
    float y0 = y[yoff + i * stride], y1 = y[yoff + (i + 1) * stride];
    return y0 + (y1 - y0) * t;
}

/* The same over values stored as logarithms (thin-sheet transmittance spans
 * decades; the export places its knots for log-linear interpolation). */
SOAK_FN soak_interp_log(SOAK_ARR(x), int xoff, int n, float v, SOAK_ARR(y), int yoff, int stride)
{
    return exp(soak_interp(x, xoff, n, v, y, yoff, stride));
}

/* Bilinear lookup of the wetness function for any base colour
 * (soak_export_base_nodes): values g[goff + iw * na + ia] of one channel
 * over dry albedo nodes a[aoff..] (na) and wetness nodes w[woff..] (nw). */
SOAK_FN soak_base_lookup(SOAK_ARR(a), int aoff, int na, SOAK_ARR(w), int woff, int nw, SOAK_ARR(g), int goff,
                         float albedo, float wet)
{
    int ia = soak_cell(a, aoff, na, albedo), iw = soak_cell(w, woff, nw, wet);
    float ta = soak_cell_t(a, aoff, ia, albedo), tw = soak_cell_t(w, woff, iw, wet);
    int r0 = goff + iw * na + ia, r1 = r0 + na;
    float lo = g[r0] + (g[r0 + 1] - g[r0]) * ta;
    float hi = g[r1] + (g[r1 + 1] - g[r1]) * ta;
    return lo + (hi - lo) * tw;
}

/* The view factor (soak_export_view_factors): the colour seen along a view
 * over the hemispherical one, bilinear over the knots x[xoff..] (n) and the
 * view cosines j / (SOAK_VIEW_N - 1); values of one channel at
 * f[foff + (i SOAK_VIEW_N + j) 3]. A diffuse closure cannot follow the
 * light's angle; its weight can follow the viewer's. */
#define SOAK_VIEW_N 17
SOAK_FN soak_view_lookup(SOAK_ARR(x), int xoff, int n, float v, SOAK_ARR(f), int foff, float cos_view)
{
    int i = soak_cell(x, xoff, n, v);
    float t = soak_cell_t(x, xoff, i, v);
    float u = soak_clamp01(cos_view) * (SOAK_VIEW_N - 1);
    int j = 0;
    while (j < SOAK_VIEW_N - 2 && u > j + 1) j += 1;
    float s = u - j;
    int r0 = foff + (i * SOAK_VIEW_N + j) * 3, r1 = r0 + SOAK_VIEW_N * 3;
    float lo = f[r0] + (f[r0 + 3] - f[r0]) * s;
    float hi = f[r1] + (f[r1 + 3] - f[r1]) * s;
    return lo + (hi - lo) * t;
}

#endif
