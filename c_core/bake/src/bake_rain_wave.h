/* The falling film in time (soak/bake_rain.h step 5), private to the bake
 * layer and exposed to white-box tests. */
#ifndef SOAK_BAKE_RAIN_WAVE_H
#define SOAK_BAKE_RAIN_WAVE_H

#include "bake_rain_flow.h"
#include "bake_rain_stream.h"

/* kappa (m^3/s per m^3 of h^3) of a film texel carrying a stream `width`
 * wide (soak_rain_flow_width) at sin_theta: its outflow is kappa h^3,
 * Nusselt's q = rho g sin theta h^3 / (3 mu) per unit width times the
 * width. 0 for sin_theta <= 0 or NaN. */
double soak_rain_wave_kappa(double width, double sin_theta);

/* Depth h >= 0 (m) with area * h + c * h^3 = volume (c = dt * kappa >= 0,
 * volume >= 0): the implicit step of one texel. */
double soak_rain_wave_depth(double area, double c, double volume);

/* One implicit (backward Euler) step of dt seconds of the kinematic wave on
 * the routing graph, texels in `order` (highest first): a texel gets
 * depth * area + source * dt + what the texels above it sent it this step;
 * a film texel (kappa > 0) keeps the depth h of soak_rain_wave_depth and
 * passes the rest (dt kappa h^3) on along the descent with the streams'
 * boxes (bake_rain_stream.h; soak_rain_flow_shares where the texel has no
 * descent; off the surface into *dripped, m^3; all of it
 * where it faces down); any other texel keeps all it gets (for the sweeps).
 * source may be NULL (no rain); inflow and boxes are scratch (w * h; boxes
 * NULL: allocated here each step). Volume before + sources = volume after +
 * *dripped up to rounding; one pass, so the same bits at any thread count. */
soak_status soak_rain_wave_step(const soak_rain_flow_grid *g, const size_t *order, size_t count, const double *kappa,
                                const double *source, double dt, double *depth, double *inflow, soak_rain_box *boxes,
                                double *dripped);

#endif
