/* The falling film in time: Nusselt's film as a kinematic wave on the
 * routing graph (model in soak/bake_rain.h step 5). */
#include "bake_rain_wave.h"

#include <math.h>
#include <stdlib.h>

#include "soak/bake_rain.h"
#include "bake_rain_stream.h"

double soak_rain_wave_kappa(double width, double sin_theta)
{
    if (!(sin_theta > 0.0) || !(width > 0.0)) return 0.0;
    double s = sin_theta < 1.0 ? sin_theta : 1.0;
    return width * SOAK_RAIN_WATER_DENSITY * SOAK_RAIN_GRAVITY * s / (3.0 * SOAK_RAIN_WATER_VISCOSITY);
}

/* Newton from above on the convex, increasing f(h) = area h + c h^3 -
 * volume: every iterate stays above the root and falls, so the loop ends
 * when an iterate stops falling (at the root up to rounding). */
double soak_rain_wave_depth(double area, double c, double volume)
{
    if (!(volume > 0.0) || !(area > 0.0)) return 0.0;
    double h = volume / area;
    if (!(c > 0.0)) return h;
    double cap = cbrt(volume / c);
    if (cap < h) h = cap;
    for (int k = 0; k < 200; ++k) {
        double f = area * h + c * h * h * h - volume, next = h - f / (area + 3.0 * c * h * h);
        if (!(next < h)) break;
        h = next > 0.0 ? next : 0.0;
    }
    return h;
}

/* Texel i of the step: keeps its implicit depth and passes the rest on. */
static void wave_texel(const soak_rain_flow_grid *g, soak_rain_box *boxes, size_t i, const double *kappa,
                       double rain, double dt, double *depth, double *inflow, double *dripped)
{
    double a = g->area[i], have = depth[i] * a + rain + inflow[i], share[9];
    if (!(a > 0.0)) return;
    if (!(kappa[i] > 0.0 || g->drip[i] < 0.0f)) {
        depth[i] = have / a;
        return;
    }
    if (!soak_rain_flow_shares(g, i, share)) { /* a pit or flat */
        depth[i] = have / a;
        return;
    }
    depth[i] = g->drip[i] < 0.0f ? 0.0 : soak_rain_wave_depth(a, dt * kappa[i], have);
    double out = have - depth[i] * a;
    if (!(out > 0.0)) return;
    if (g->drip[i] < 0.0f) {
        *dripped += out;
        return;
    }
    double off = soak_rain_stream_pass(g, boxes, i, rain > 0.0, out, inflow);
    if (off >= 0.0) {
        *dripped += off;
        return;
    }
    int x = (int)(i % (size_t)g->w), y = (int)(i / (size_t)g->w);
    for (int d = 0; d < 8; ++d)
        if (share[d] > 0.0) inflow[(size_t)(y + SOAK_RAIN_DY[d]) * g->w + (x + SOAK_RAIN_DX[d])] += out * share[d];
    *dripped += out * share[8];
}

soak_status soak_rain_wave_step(const soak_rain_flow_grid *g, const size_t *order, size_t count, const double *kappa,
                                const double *source, double dt, double *depth, double *inflow, double *dripped)
{
    if (!g || (!order && count) || !kappa || !depth || !inflow || !dripped) return SOAK_ERR_NULL;
    if (!(dt >= 0.0 && dt < 1e300)) return SOAK_ERR_ARG;
    soak_rain_box *boxes = g->descent && count ? malloc((size_t)g->w * g->h * sizeof *boxes) : NULL;
    if (g->descent && count && !boxes) return SOAK_ERR_NOMEM;
    *dripped = 0.0;
    for (size_t k = 0; k < count; ++k) {
        inflow[order[k]] = 0.0;
        if (boxes) boxes[order[k]] = SOAK_RAIN_BOX_EMPTY;
    }
    for (size_t k = 0; k < count; ++k) {
        size_t i = order[k];
        wave_texel(g, boxes, i, kappa, source ? source[i] * dt : 0.0, dt, depth, inflow, dripped);
    }
    free(boxes);
    return SOAK_OK;
}
