/* Runnels: a falling film too thin to wet its face gathers into rivulets
 * (soak/bake_rain.h step 3c), private to the bake layer and exposed to
 * white-box tests. */
#ifndef SOAK_BAKE_RAIN_RUNNELS_H
#define SOAK_BAKE_RAIN_RUNNELS_H

#include <stdint.h>

#include "bake_rain_flow.h"
#include "bake_rain_surface.h"

/* The film's breakdown flux q_min (m^2/s per unit width) at contact angle
 * theta (rad) on a face at sin_slope: Hartley & Murgatroyd's force
 * criterion, Gamma_min = 1.69 (mu rho / g')^(1/5) (sigma (1 - cos
 * theta))^(3/5) kg/(m s), q_min = Gamma_min / rho, g' = g sin_slope. 0 for
 * theta <= 0; +inf where sin_slope <= 0. */
double soak_rain_runnel_min_flux(double theta, double sin_slope);
/* Rivulet spacing (m) of a film h thick at sin_slope: the fingering
 * wavelength 14 l, l = (h l_c^2 / sin_slope)^(1/3), l_c = sqrt(sigma /
 * (rho g)) (Troian, Herbolzheimer, Safran & Joanny 1989). */
double soak_rain_runnel_spacing(double h, double sin_slope);
/* Half-width a (m) of a rivulet carrying Q (m^3/s) at contact angle theta
 * (rad) on a face at sin_slope: Q = 4 g sin_slope theta^3 a^4 / (105 nu),
 * the lubrication flux of the thin rivulet h(y) = theta (a^2 - y^2) / (2 a)
 * (Duffy & Moffatt 1995). */
double soak_rain_runnel_half_width(double flux, double theta, double sin_slope);
/* Mean film thickness over [y0, y1] (m, across the rivulet, centre 0) of a
 * rivulet of half-width a at contact angle theta. */
double soak_rain_runnel_mean_depth(double a, double theta, double y0, double y1);

typedef struct soak_rain_runnel_stats {
    int broken;     /* texels whose film broke into rivulets */
    double spacing; /* m, the rivulets' spacing (0 where none broke) */
} soak_rain_runnel_stats;

/* Replaces film (m, w x h) by rivulets where its flux is below q_min:
 * rivulet k runs along s = (k + phase) * spacing, s the texel's position
 * across the slope (p . unit(up x n)), phase from seed; the spacing is
 * soak_rain_runnel_spacing of the median broken film. A texel holds the
 * rivulet's mean depth over its width across the flow
 * (soak_rain_flow_width); a rivulet carries the flux of its spacing, so
 * water is conserved across every line of the face. theta in (0, pi/2]. */
soak_status soak_rain_runnels(const rain_surface *s, const soak_rain_flow_grid *g, soak_vec3 up, double theta,
                              uint64_t seed, double *film, soak_rain_runnel_stats *stats);

#endif
