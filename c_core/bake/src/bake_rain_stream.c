/* Streams along the steepest descent with their sub-texel extent
 * (bake_rain_stream.h). */
#include "bake_rain_stream.h"

#include <math.h>

const soak_rain_box SOAK_RAIN_BOX_FULL = {0.0f, 1.0f, 0.0f, 1.0f};
const soak_rain_box SOAK_RAIN_BOX_EMPTY = {1.0f, 0.0f, 1.0f, 0.0f};

/* Shares below this go to the other neighbour: a stream along a grid axis
 * or diagonal goes to one texel, not a rounding error to its side. */
#define SHARE_MIN 1e-6
/* Boxes narrower than this (texels) are split as points. */
#define WIDTH_MIN 1e-6

/* The direction d with step (dx, dy), -1 if none. */
static int direction(int dx, int dy)
{
    for (int d = 0; d < 8; ++d)
        if (SOAK_RAIN_DX[d] == dx && SOAK_RAIN_DY[d] == dy) return d;
    return -1;
}

/* Whether the surface's edge at texel i faces down the descent (a, b) (water
 * runs off it) rather than along it: the outward direction, the sum of the
 * steps to the neighbours that are not adjacent, within 60 deg of the
 * descent. */
static int edge_faces_downhill(const soak_rain_flow_grid *g, size_t i, double a, double b)
{
    double ox = 0.0, oy = 0.0;
    for (int d = 0; d < 8; ++d)
        if (!(g->adj[i] >> d & 1u)) ox += SOAK_RAIN_DX[d], oy += SOAK_RAIN_DY[d];
    double dot = ox * a + oy * b, len = sqrt((ox * ox + oy * oy) * (a * a + b * b));
    return !(len > 0.0) || dot > 0.5 * len;
}

/* The interval [lo, hi] of the minor axis moved by s split over the cells
 * -1, 0, 1: frac[c + 1] of its water and the part [part_lo, part_hi] of the
 * cell (in its own coordinates). */
static void split_interval(double lo, double hi, double s, double frac[3], double part_lo[3], double part_hi[3])
{
    double a = lo + s, b = hi + s;
    for (int c = -1; c <= 1; ++c) {
        frac[c + 1] = 0.0;
        part_lo[c + 1] = part_hi[c + 1] = 0.0;
    }
    if (!(b - a > WIDTH_MIN)) { /* a point: the cell holding its middle */
        double m = 0.5 * (a + b);
        int c = (int)floor(m);
        c = c < -1 ? -1 : (c > 1 ? 1 : c);
        double t = m - c;
        t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
        frac[c + 1] = 1.0, part_lo[c + 1] = part_hi[c + 1] = t;
        return;
    }
    for (int c = -1; c <= 1; ++c) {
        double l = a > c ? a : c, h = b < c + 1 ? b : c + 1;
        if (!(h > l)) continue;
        frac[c + 1] = (h - l) / (b - a);
        part_lo[c + 1] = l - c, part_hi[c + 1] = h - c;
    }
    for (int c = 0; c < 3; ++c) /* slivers go to the rest */
        if (frac[c] > 0.0 && frac[c] < SHARE_MIN) {
            double keep = 1.0 - frac[c];
            frac[c] = 0.0;
            for (int k = 0; k < 3; ++k) frac[k] /= keep;
        }
}

/* The two targets of the moved box: directions to[], water share[] and
 * boxes; returns how many (1 or 2). */
static int move_box(double a, double b, soak_rain_box in, int to[2], double share[2], soak_rain_box box[2])
{
    int major_y = fabs(b) >= fabs(a);
    double m = major_y ? fabs(b) : fabs(a), s = (major_y ? a : b) / m;
    int step = (major_y ? b : a) > 0.0 ? 1 : -1;
    double frac[3], lo[3], hi[3];
    split_interval(major_y ? in.x0 : in.y0, major_y ? in.x1 : in.y1, s, frac, lo, hi);
    int n = 0;
    for (int c = -1; c <= 1 && n < 2; ++c) {
        if (!(frac[c + 1] > 0.0)) continue;
        to[n] = major_y ? direction(c, step) : direction(step, c);
        share[n] = frac[c + 1];
        box[n] = in;
        if (major_y) box[n].x0 = (float)lo[c + 1], box[n].x1 = (float)hi[c + 1];
        else box[n].y0 = (float)lo[c + 1], box[n].y1 = (float)hi[c + 1];
        ++n;
    }
    return n;
}

int soak_rain_stream_split(const soak_rain_flow_grid *g, size_t i, soak_rain_box in, double share[9],
                           soak_rain_box piece[8])
{
    for (int d = 0; d < 9; ++d) share[d] = 0.0;
    if (!g->descent) return 0;
    double a = g->descent[2 * i], b = g->descent[2 * i + 1];
    if (!(a * a + b * b > 0.0) || !(fabs(a) < 1e300 && fabs(b) < 1e300)) return 0;
    if (!(in.x1 >= in.x0 && in.y1 >= in.y0)) in = SOAK_RAIN_BOX_FULL;
    int to[2], on[2] = {0, 0};
    double s[2] = {0.0, 0.0};
    soak_rain_box box[2];
    int n = move_box(a, b, in, to, s, box);
    for (int k = 0; k < n; ++k) on[k] = g->adj[i] >> to[k] & 1u;
    if (n == 2 && on[0] != on[1] && !edge_faces_downhill(g, i, a, b)) { /* along an edge: stays on the surface */
        int keep = on[1];
        s[keep] = 1.0, s[!keep] = 0.0;
    }
    for (int k = 0; k < n; ++k) {
        if (!(s[k] > 0.0)) continue;
        if (!on[k]) { /* across an open edge (or a seam): this share drips */
            share[8] += s[k];
            continue;
        }
        size_t j = (size_t)((ptrdiff_t)i + (ptrdiff_t)SOAK_RAIN_DY[to[k]] * g->w + SOAK_RAIN_DX[to[k]]);
        if (!(g->level[j] < g->level[i])) {
            for (int d = 0; d < 9; ++d) share[d] = 0.0;
            return 0;
        }
        share[to[k]] = s[k];
        piece[to[k]] = box[k];
    }
    return 1;
}

static void grow(soak_rain_box *b, soak_rain_box p)
{
    if (!(b->x1 >= b->x0)) {
        *b = p;
        return;
    }
    b->x0 = p.x0 < b->x0 ? p.x0 : b->x0, b->x1 = p.x1 > b->x1 ? p.x1 : b->x1;
    b->y0 = p.y0 < b->y0 ? p.y0 : b->y0, b->y1 = p.y1 > b->y1 ? p.y1 : b->y1;
}

int soak_rain_stream_route(const soak_rain_flow_grid *g, const soak_rain_box *boxes, size_t i, int rained,
                           double share[9], soak_rain_box piece[8])
{
    soak_rain_box in = boxes && !rained ? boxes[i] : SOAK_RAIN_BOX_FULL;
    return soak_rain_stream_split(g, i, in, share, piece);
}

double soak_rain_stream_send(const soak_rain_flow_grid *g, soak_rain_box *boxes, size_t i, double q,
                             const double share[9], const soak_rain_box piece[8], double *inflow)
{
    for (int d = 0; d < 8; ++d) {
        if (!(share[d] > 0.0)) continue;
        size_t j = (size_t)((ptrdiff_t)i + (ptrdiff_t)SOAK_RAIN_DY[d] * g->w + SOAK_RAIN_DX[d]);
        inflow[j] += q * share[d];
        if (boxes) grow(&boxes[j], piece[d]);
    }
    return q * share[8];
}

double soak_rain_stream_pass(const soak_rain_flow_grid *g, soak_rain_box *boxes, size_t i, int rained, double q,
                             double *inflow)
{
    double share[9];
    soak_rain_box piece[8];
    if (!soak_rain_stream_route(g, boxes, i, rained, share, piece)) return -1.0;
    return soak_rain_stream_send(g, boxes, i, q, share, piece, inflow);
}
