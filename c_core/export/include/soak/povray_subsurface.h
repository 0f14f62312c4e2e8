/* POV-Ray 3.7's subsurface conventions, so that the exported translucency
 * gives POV-Ray's BSSRDF the core's diffusion length.
 *
 * What POV-Ray does (its source, backend/render/trace.cpp and
 * backend/lighting/subsurface.cpp, v3.7.0.10; measured in
 * tests/povray/subsurface.py): the pigment (times diffuse 1) is the total
 * diffuse reflectance Rd of Jensen et al. 2001 ("A practical model for
 * subsurface light transport", SIGGRAPH), inverted to the reduced albedo
 * alpha' through the closed form
 *     Rd(alpha') = alpha'/2 (1 + exp(-4/3 A s)) exp(-s),  s = sqrt(3 (1 - alpha'))
 * tabulated at Rd = i/100 (i = 0..100) and interpolated linearly;
 * A = (1 + Fdr)/(1 - Fdr) with POV-Ray's own fit
 *     Fdr(eta) = ((1 - 1/eta) + 3 (1 - 1/eta)^4.5) / 4
 * (not Jensen's Eq. of Egan & Hilgeman), eta the interior's ior. The
 * translucency T (mm) is read as 1/sigma'_s, so sigma'_t = sigma'_s/alpha',
 * sigma_a = sigma'_t - sigma'_s and the diffusion length is 1/sigma_tr with
 *     sigma_tr = sqrt(3 sigma_a sigma'_t) = sqrt(3 (1 - alpha')) / (alpha' T).
 * The lit level is fixed by the pigment; T is the one free parameter, and
 * soak_povray_translucency chooses it so that sigma_tr equals the core's
 * sqrt(3 sigma_a (sigma_a + (1 - g) sigma_s)). The depth of the dipole's
 * sources (1/sigma'_t) then differs from the core's where POV-Ray's alpha'
 * does (the film darkening of the pigment), which shapes the profile within
 * about one mean free path of a shadow edge only. */
#ifndef SOAK_POVRAY_SUBSURFACE_H
#define SOAK_POVRAY_SUBSURFACE_H

#include "soak/status.h"

/* Translucency is clamped into this range (mm): POV-Ray aborts on 0, and
 * alpha' -> 0 or sigma_tr -> 0 ask for an unbounded mean free path. */
#define SOAK_POVRAY_TRANSLUCENCY_MIN 1e-3
#define SOAK_POVRAY_TRANSLUCENCY_MAX 1e3

/* POV-Ray's reduced albedo for a diffuse reflectance rd in [0, 1] under a
 * boundary of relative index eta in [1, 10]. */
soak_status soak_povray_alpha_prime(double rd, double eta, double *alpha_prime);

/* Translucency giving POV-Ray's BSSRDF, with pigment rd and interior ior
 * eta, the core's diffusion coefficient sigma_tr_per_m (1/m, >= 0). The
 * result is in POV-Ray's unit, mm (its translucency is read through
 * global_settings' mm_per_unit): the one conversion out of the core's SI. */
soak_status soak_povray_translucency(double rd, double eta, double sigma_tr_per_m, double *translucency_mm);

#endif
