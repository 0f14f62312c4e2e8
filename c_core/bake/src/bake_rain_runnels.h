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
    int broken;      /* texels whose film broke into rivulets */
    double spacing;  /* m, the rivulets' spacing (0 where none broke) */
    int from_relief; /* 1: the lattice's phase was set by the relief's grooves, 0: by the seed */
} soak_rain_runnel_stats;

/* What the runnels read of the surface, per texel, made once a bake (the
 * single map and every frame of a sequence use the same lattice). */
typedef struct soak_rain_runnel_field {
    int w, h;
    double theta;          /* contact angle, rad */
    float *sine;           /* slope sine; 0 where level or uncovered (no runnels) */
    double *across;        /* m, p . unit(up x n): the position across the slope */
    float *concave;        /* 1/m, >= 0: the across-slope concavity -dn_s/ds (grooves, joints) */
    double spacing, phase; /* the lattice: rivulet k along s = (k + phase) spacing; spacing 0: none */
} soak_rain_runnel_field;

/* Fills r from the rasterised surface s (theta in (0, pi/2]); on error
 * nothing is kept. */
soak_status soak_rain_runnel_field_make(const rain_surface *s, soak_vec3 up, double theta, soak_rain_runnel_field *r);
void soak_rain_runnel_field_free(soak_rain_runnel_field *r);
/* The lattice of r from the steady film (m, w x h): the spacing is
 * soak_rain_runnel_spacing of the median broken film; the phase puts the
 * rivulets where the relief concentrates flow (the concavity-weighted
 * circular mean of the broken texels' positions modulo the spacing) or,
 * on a surface without grooves, comes from the seed. */
soak_status soak_rain_runnel_place(soak_rain_runnel_field *r, const double *film, uint64_t seed,
                                   soak_rain_runnel_stats *stats);
/* Texel i's film h (m) as the lattice's rivulets: h itself where its flux
 * is at or above q_min, the rivulets would touch, or r has no lattice;
 * else the rivulets' mean depth over the texel's width across the flow
 * (soak_rain_flow_width), each rivulet carrying the flux of its spacing. */
double soak_rain_runnel_texel(const soak_rain_runnel_field *r, const soak_rain_flow_grid *g, size_t i, double h);

/* Replaces film (m, w x h) by rivulets where its flux is below q_min:
 * field, lattice and soak_rain_runnel_texel on every texel. theta in
 * (0, pi/2]. */
soak_status soak_rain_runnels(const rain_surface *s, const soak_rain_flow_grid *g, soak_vec3 up, double theta,
                              uint64_t seed, double *film, soak_rain_runnel_stats *stats);

#endif
