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

/* Where texel i's outflow goes: 2 along the descent (share, piece), 1 by
 * the level drops or off a down-facing face (share), 0 nowhere (a pit or
 * flat). */
static int wave_route(const soak_rain_flow_grid *g, const soak_rain_box *boxes, size_t i, int rained, double share[9],
                      soak_rain_box piece[8])
{
    if (g->drip[i] >= 0.0f && soak_rain_stream_route(g, boxes, i, rained, share, piece)) return 2;
    return soak_rain_flow_shares(g, i, share);
}

/* Texel i of the step: keeps its implicit depth and passes the rest on. */
static void wave_texel(const soak_rain_flow_grid *g, soak_rain_box *boxes, size_t i, const double *kappa, double rain,
                       double dt, double *depth, double *inflow, double *dripped)
{
    double a = g->area[i], have = depth[i] * a + rain + inflow[i], share[9];
    soak_rain_box piece[8];
    if (!(a > 0.0)) return;
    int how = kappa[i] > 0.0 || g->drip[i] < 0.0f ? wave_route(g, boxes, i, rain > 0.0, share, piece) : 0;
    if (!how) { /* not a film texel, or a pit or flat */
        depth[i] = have / a;
        return;
    }
    depth[i] = g->drip[i] < 0.0f ? 0.0 : soak_rain_wave_depth(a, dt * kappa[i], have);
    double out = have - depth[i] * a;
    if (!(out > 0.0)) return;
    if (how == 2) {
        *dripped += soak_rain_stream_send(g, boxes, i, out, share, piece, inflow);
        return;
    }
    int x = (int)(i % (size_t)g->w), y = (int)(i / (size_t)g->w);
    for (int d = 0; d < 8; ++d)
        if (share[d] > 0.0) inflow[(size_t)(y + SOAK_RAIN_DY[d]) * g->w + (x + SOAK_RAIN_DX[d])] += out * share[d];
    *dripped += out * share[8];
}

soak_status soak_rain_wave_step(const soak_rain_flow_grid *g, const size_t *order, size_t count, const double *kappa,
                                const double *source, double dt, double *depth, double *inflow, soak_rain_box *scratch,
                                double *dripped)
{
    if (!g || (!order && count) || !kappa || !depth || !inflow || !dripped) return SOAK_ERR_NULL;
    if (!(dt >= 0.0 && dt < 1e300)) return SOAK_ERR_ARG;
    soak_rain_box *own = g->descent && count && !scratch ? malloc((size_t)g->w * g->h * sizeof *own) : NULL;
    soak_rain_box *boxes = g->descent && count ? (scratch ? scratch : own) : NULL;
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
    free(own);
    return SOAK_OK;
}
