/* Beading: rain standing as beads on surfaces of high contact angle
 * (`soak bake beads`, issue 48 item 4; docs/rain.md "Beading").
 *
 * Shape. A drop smaller than the capillary length l_c = sqrt(sigma / (rho g))
 * (2.7 mm for water at 20 C) is shaped by surface tension alone: a spherical
 * cap meeting the surface at the contact angle theta (P.-G. de Gennes,
 * F. Brochard-Wyart, D. Quere, "Capillarity and Wetting Phenomena",
 * Springer 2004, sec. 1.2 and 2.1). With R the sphere's radius, the contact
 * radius is r = R sin theta and the height h = R (1 - cos theta), so
 *   h / r = (1 - cos theta) / sin theta = tan(theta / 2),
 * and the volume, summing discs of radius^2 R^2 - z^2 from z = R - h to R,
 *   V = pi h^2 (3 R - h) / 3 = pi h (3 r^2 + h^2) / 6
 * (R = (r^2 + h^2) / (2 h)). For a given V and t = tan(theta / 2):
 *   r = cbrt(6 V / (pi t (3 + t^2))),  h = t r.
 * Seen from above, a cap with theta > 90 deg overhangs its contact line:
 * its outline is the sphere's equator (radius R), and a height map holds
 * the upper surface z(rho) = h - R + sqrt(R^2 - rho^2) over rho < R, whose
 * column volume pi R^2 (h - R) + 2 pi R^3 / 3 = pi R^3 (2/3 - cos theta)
 * includes the air under the overhang. For theta <= 90 deg the outline is
 * the contact circle and the column volume is V.
 *
 * Beads. The raindrops of `soak bake drops` (the same seed, rate and texel
 * give the same impacts, soak/bake_drops.h) land as beads of their own
 * volume pi D^3 / 6 instead of spread discs. A bead whose outline overlaps
 * another's coalesces with it into one bead of the summed volume at their
 * volume-weighted centre (coalescence conserves volume and momentum: the
 * centre of mass stays), repeated until no outlines overlap; the map wraps
 * (a tiling plane). Not modelled: gravity (beads wider than l_c flatten into
 * puddles of height 2 l_c sin(theta / 2), de Gennes et al. sec. 2.1.2: the
 * bake counts them), evaporation, sliding on slopes, contact-angle
 * hysteresis and impact splashing.
 *
 * Map: 4 channels. RGB = (n + 1) / 2, the upper surface's unit normal in
 * tangent space, v up (OpenGL/Blender, as `bake ripples`), averaged over
 * supersample^2 points per texel; A = height / height_range, the mean
 * height over the texel, clipped to [0, 1]. */
#ifndef SOAK_BAKE_BEADS_H
#define SOAK_BAKE_BEADS_H

#include <stddef.h>
#include <stdint.h>

#include "soak/bake.h"
#include "soak/image.h"
#include "soak/status.h"

#define SOAK_BEAD_ANGLE_MIN 1.0   /* deg: below, a "bead" is a film wider than any map */
#define SOAK_BEAD_ANGLE_MAX 179.0 /* deg */
#define SOAK_BEADS_MAX_SUPERSAMPLE 16
#define SOAK_BEADS_MAX_DROPS 50000000UL

typedef struct soak_bead_shape {
    double contact_radius_m; /* r */
    double height_m;         /* h */
    double sphere_radius_m;  /* R */
    double outline_m;        /* radius seen from above: r (theta <= 90) or R */
    double theta_rad;
} soak_bead_shape;

/* The cap of volume V > 0 (m^3) at contact angle theta_deg in
 * [SOAK_BEAD_ANGLE_MIN, SOAK_BEAD_ANGLE_MAX]. SOAK_ERR_ARG otherwise. */
soak_status soak_bead_cap(double volume_m3, double theta_deg, soak_bead_shape *out);
/* Height of the upper surface at distance rho (m) from the centre; 0 at or
 * beyond the outline. */
double soak_bead_surface(const soak_bead_shape *b, double rho_m);
/* Volume under the upper surface, m^3: V (theta <= 90) or
 * pi R^3 (2/3 - cos theta) (see above). */
double soak_bead_column_volume(const soak_bead_shape *b);

typedef struct soak_beads_params {
    uint64_t seed;
    double rate_mm_h;         /* (0, 500] */
    double texel_m;           /* metres per texel, (0, 100] */
    double duration;          /* s of rain, [0, 1e6] */
    double min_diameter_mm;   /* smallest drop, [0, D_MAX) */
    double contact_angle_deg; /* [SOAK_BEAD_ANGLE_MIN, SOAK_BEAD_ANGLE_MAX] */
    double height_range_m;    /* alpha 1, (0, 1] m */
    int supersample;          /* points per texel side, 1..SOAK_BEADS_MAX_SUPERSAMPLE */
} soak_beads_params;

/* seed 0, 10 mm/h, 0.25 mm texels, 10 s, all drops, 90 deg, 6 mm, 4. */
void soak_beads_defaults(soak_beads_params *p);
soak_status soak_beads_check(const soak_beads_params *p);

typedef struct soak_bead_drop {
    double x, y;      /* texels from the top-left corner */
    double volume_m3; /* > 0 */
} soak_bead_drop;

typedef struct soak_beads_stats {
    size_t drops, beads;
    double drop_volume_m3;   /* sum of the drops' volumes */
    double bead_volume_m3;   /* sum of the beads' cap volumes (equal: coalescence conserves it) */
    double column_volume_m3; /* sum of the beads' column volumes (the map's, before clipping) */
    double largest_contact_radius_m;
    size_t beyond_capillary; /* beads with r > l_c: the cap model no longer holds */
    size_t clipped_texels;   /* texels whose height exceeds height_range */
} soak_beads_stats;

/* Beads from the given drops (in order) on a width x height map that wraps;
 * out is allocated here (4 channels); stats may be NULL. */
soak_status soak_beads_from_drops(const soak_beads_params *p, int width, int height, const soak_bead_drop *drops,
                                  size_t n, const soak_bake_exec *exec, soak_image *out, soak_beads_stats *stats);
/* The rain's drops over [0, duration) (soak_drops_impacts with the same
 * seed, rate, texel and min_diameter), then soak_beads_from_drops. */
soak_status soak_beads_bake(const soak_beads_params *p, int width, int height, const soak_bake_exec *exec,
                            soak_image *out, soak_beads_stats *stats);

#endif
