/* The falling film of the rain bake (soak/bake_rain.h step 3b), private to
 * the bake layer and exposed to white-box tests. */
#ifndef SOAK_BAKE_RAIN_FILM_H
#define SOAK_BAKE_RAIN_FILM_H

#include "bake_rain_flow.h"

/* Film thickness (m) per texel under steady rain: source rain_m_s *
 * exposure * area per covered texel, routed by soak_rain_flow_discharge
 * with evaporation evap_m_s, q = discharge / soak_rain_flow_width per unit width,
 * thickness soak_rain_film_thickness(q, sin theta) with sin theta =
 * sqrt(1 - up_dot_n^2). Uncovered texels get 0. balance may be NULL. */
soak_status soak_rain_film_map(const soak_rain_flow_grid *g, const float *up_dot_n, const float *exposure,
                               double rain_m_s, double evap_m_s, double *film, soak_rain_flow_balance *balance);

#endif
