/* Streams along the steepest descent with their sub-texel extent (the rain
 * bake's routing, soak/bake_rain.h step 3), private to the bake layer and
 * exposed to white-box tests.
 *
 * What leaves a texel occupies a box inside it, [x0, x1] x [y0, y1] of the
 * unit texel (x right, y down the image). One step moves the box along the
 * descent (a, b) by (a, b) / max(|a|, |b|): exactly one texel along the
 * major axis, a fraction along the minor one, so the moved box lies in at
 * most two texels and its water is split by the length of the box each one
 * holds (water spread evenly over the box). A texel the rain falls on
 * passes on a full box; one fed only from above passes on the bounding box
 * of the pieces it received. A stream beside a dry patch (a ledge's rain
 * shadow) therefore keeps its edge: the furthest extent of the boxes across
 * the flow moves with the flow and never grows, where splitting every
 * texel's water between two neighbours (the D-infinity routing of Tarboton
 * 1997, Water Resour. Res. 33(2) 309-319) spreads a stream sideways by
 * sqrt(n f (1 - f)) texels after n texels. On a texel fed by rain
 * everywhere the split is the line-crossing form of D-infinity, so a
 * uniform plane carries a uniform film. */
#ifndef SOAK_BAKE_RAIN_STREAM_H
#define SOAK_BAKE_RAIN_STREAM_H

#include <stddef.h>

#include "bake_rain_grid.h"

/* x0, x1, y0, y1; empty while x0 > x1. */
typedef struct soak_rain_box {
    float x0, x1, y0, y1;
} soak_rain_box;

extern const soak_rain_box SOAK_RAIN_BOX_FULL, SOAK_RAIN_BOX_EMPTY;

/* Where the water of texel i in box `in` goes along the descent:
 * share[d] to neighbour d (its box piece[d]), share[8] off the surface
 * (an open edge facing down the slope; along an edge parallel to the flow
 * the share goes to the other texel). Returns 0 (shares 0) where the grid
 * has no descent, the texel is level or a target is not lower: the caller
 * routes by level drops instead. */
int soak_rain_stream_split(const soak_rain_flow_grid *g, size_t i, soak_rain_box in, double share[9],
                           soak_rain_box piece[8]);

/* Passes q (any unit) from texel i on along the descent: to inflow[j] of
 * the neighbours, their boxes[j] grown to hold the pieces; returns the
 * part that drips off, or -1 (nothing passed) where split returns 0.
 * boxes (one per texel) NULL: every texel passes a full box. rained: the
 * texel's own rain is part of q (it passes a full box). */
double soak_rain_stream_pass(const soak_rain_flow_grid *g, soak_rain_box *boxes, size_t i, int rained, double q,
                             double *inflow);

/* The two halves of soak_rain_stream_pass: the shares and pieces of texel
 * i (0 where split returns 0), then q sent by them (returns the part that
 * drips off). */
int soak_rain_stream_route(const soak_rain_flow_grid *g, const soak_rain_box *boxes, size_t i, int rained,
                           double share[9], soak_rain_box piece[8]);
double soak_rain_stream_send(const soak_rain_flow_grid *g, soak_rain_box *boxes, size_t i, double q,
                             const double share[9], const soak_rain_box piece[8], double *inflow);

#endif
