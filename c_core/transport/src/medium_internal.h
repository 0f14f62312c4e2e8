/* Private pieces of the random walk (soak/medium.h) shared by its files. */
#ifndef SOAK_MEDIUM_INTERNAL_H
#define SOAK_MEDIUM_INTERNAL_H

#include <math.h>

#include "soak/medium.h"

/* Largest guide_prob accepted: the analog strategy keeps at least 1 %, which
 * bounds the MIS weights (by albedo / (1 - guide_prob) / channel share). */
#define SOAK_GUIDE_PROB_MAX 0.99

typedef enum flight_end { FLIGHT_SURFACE, FLIGHT_COLLISION, FLIGHT_CAPPED } flight_end;

/* Distance to the surface from pos along dir into *dmax, for a flight whose
 * sampled length is t. With a within test that rules the surface out
 * before t, the closest-hit query is skipped and *dmax = INFINITY: the
 * flight then ends at its collision, exactly as it would against the true
 * distance (> t). Inline: medium.c and medium_guided.c both fly with it. */
static inline soak_status medium_surface_distance(const soak_boundary *b, soak_vec3 pos, soak_vec3 dir, double t,
                                                  double *dmax)
{
    if (b->within && t < INFINITY && !b->within(b->ctx, pos, dir, t)) {
        *dmax = INFINITY;
        return SOAK_OK;
    }
    *dmax = b->distance(b->ctx, pos, dir);
    return *dmax >= 0.0 ? SOAK_OK : SOAK_ERR_NUMERIC;
}

/* State of the guided walk (see soak_walk_options.guide_prob). */
typedef struct walk_guide {
    double prob; /* 0: off */
    soak_vec3 n; /* outward normal of the guiding plane */
    double v0[3], norm[3];
    int armed;        /* the current direction was sampled at a scattering: fly with MIS */
    int guided;       /* ... by the guide (else by the phase function) */
    int channel;      /* the guide's channel (its v0 and stretched extinction) */
    double phase_pdf; /* phase function at the sampled direction, per solid angle */
} walk_guide;

/* Sets the guide up for medium m (homogeneous) from the walk options. */
void walk_guide_init(walk_guide *g, const soak_medium_rgb *m, const soak_walk_options *opt);

/* Samples the direction leaving a scattering event (propagation *dir in,
 * out) from the guide or the phase function; weight is the throughput
 * there (it picks the guide's channel). Arms the next flight. */
soak_status walk_guide_scatter(walk_guide *g, const soak_hg2 *phase, soak_vec3 *dir, soak_rgb weight, soak_rng *rng);

/* The armed flight: distance from the chosen strategy, weights
 * phase x transmittance (x sigma_s at a collision) over the MIS pdf.
 * Disarms the guide. */
soak_status walk_guide_fly(walk_guide *g, const soak_medium_rgb *m, const soak_boundary *b, soak_walk_result_rgb *r,
                           soak_rng *rng, flight_end *end, double *dmax_out);

#endif
