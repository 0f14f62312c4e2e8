/* Dwivedi sampling: the zero-variance-based guide of a random walk toward a
 * plane boundary ([KdE14] Krivanek & d'Eon 2014, after [Dwi82] Dwivedi 1982;
 * used for subsurface walks in [MHK16] Meng, Hanika, Dachsbacher 2016 and in
 * Cycles' random-walk subsurface scattering).
 *
 * In a half-space of isotropic scatterers with single-scattering albedo a,
 * the probability that a particle at depth z below the surface ever reaches
 * it decays as exp(-sigma_t z / v0) far from the surface, v0 > 1 the
 * diffusion eigenvalue, the root of ([KdE14]; [CZ67])
 *     (a v0 / 2) ln((v0 + 1) / (v0 - 1)) = 1,   i.e.  a v0 atanh(1/v0) = 1.
 * Sampling in proportion to that importance gives, with mu the cosine
 * between the flight direction and the outward normal of the plane:
 *  - directions with pdf  p(mu) = 1 / (L (v0 - mu)), L = ln((v0+1)/(v0-1)),
 *    per unit mu on [-1, 1] (per solid angle: divide by 2 pi);
 *  - distances with the stretched extinction sigma_t (1 - mu / v0): a flight
 *    toward the surface goes farther, one away from it shorter.
 * These only shape where samples go; the walk weights them by the true
 * phase function and transmittance over the pdf (one-sample MIS with the
 * analog walk, soak/medium.h), so any v0 > 1 is unbiased and v0 only
 * decides how well the guide fits. For an anisotropic phase function the
 * walk takes v0 at the similarity-reduced albedo a (1 - g) / (1 - a g)
 * (the similarity relation of diffusion theory; our choice). */
#ifndef SOAK_DWIVEDI_H
#define SOAK_DWIVEDI_H

/* Largest v0 returned: at albedo 1 (or so close that v0 would exceed this) the
 * guide is uniform in mu to 1e-8 and distances are not stretched. */
#define SOAK_DWIVEDI_V0_MAX 1e8
/* Smallest v0 returned (albedo below about 0.14): keeps p(mu) finite. */
#define SOAK_DWIVEDI_V0_MIN (1.0 + 1e-6)

/* v0 for albedo a in [0, 1]; NaN or out of range gives SOAK_DWIVEDI_V0_MAX
 * (no guiding). Accurate to 1e-12 relative within [V0_MIN, V0_MAX]. */
double soak_dwivedi_v0(double albedo);

/* L = ln((v0 + 1) / (v0 - 1)), the normalisation of p(mu), v0 > 1. */
double soak_dwivedi_norm(double v0);

/* Cosine mu in [-1, 1] with pdf p(mu) for u in [0, 1); norm = soak_dwivedi_norm(v0). */
double soak_dwivedi_sample_cos(double v0, double norm, double u);

/* p(mu) per unit mu (not per solid angle). */
double soak_dwivedi_pdf_cos(double v0, double norm, double mu);

#endif
