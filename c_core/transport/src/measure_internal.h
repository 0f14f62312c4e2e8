/* Private pieces of the gonio-reflectometer (soak/measure.h). */
#ifndef SOAK_MEASURE_INTERNAL_H
#define SOAK_MEASURE_INTERNAL_H

#include "soak/measure.h"
#include "soak/rng.h"
#include "soak/vec.h"

/* One photon of the COATED configuration, arriving along d (d.z < 0):
 * *r_out its weight leaving upwards (0 when absorbed), *events the
 * interface and body meetings, *capped 1 when max_events stopped it. */
soak_status measure_coated_path(const soak_measure_setup *s, soak_vec3 d, soak_rng *rng, double *r_out, long *events,
                                int *capped);

#endif
