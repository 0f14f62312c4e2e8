/* A preset's derived dry medium (soak_preset_derive, soak/preset.h): the
 * single-scattering albedo that gives the preset's diffuse albedo under its
 * phase function (van de Hulst's similarity inversion, soak/vdhulst.h), and
 * the scattering and absorption it splits the extinction into. */
#include "soak/preset.h"

#include "soak/hg.h"
#include "soak/vdhulst.h"

soak_status soak_preset_derive(soak_preset *p)
{
    if (!p) return SOAK_ERR_NULL;
    soak_rgb zero = {0.0, 0.0, 0.0};
    if (p->kind == SOAK_KIND_CONDUCTOR) {
        p->omega_dry = p->sigma_s_dry_per_m = p->sigma_a_dry_per_m = zero;
        return SOAK_OK;
    }
    if (soak_hg2_validate(&p->phase_dry) != SOAK_OK) return SOAK_ERR_ARG;
    double g = soak_hg2_mean_cosine(&p->phase_dry);
    soak_rgb omega = zero, ss = zero, sa = zero;
    for (int i = 0; i < 3; ++i) {
        double w = 0.0, sigma_t = soak_rgb_at(p->sigma_t_per_m, i);
        if (!soak_in_range(sigma_t, 0.0, SOAK_SIGMA_T_MAX_PER_M)) return SOAK_ERR_ARG;
        soak_status st = soak_vdhulst_invert(soak_rgb_at(p->albedo, i), g, &w);
        if (st != SOAK_OK) return st;
        soak_rgb_set(&omega, i, w);
        soak_rgb_set(&ss, i, w * sigma_t);
        soak_rgb_set(&sa, i, (1.0 - w) * sigma_t);
    }
    p->omega_dry = omega;
    p->sigma_s_dry_per_m = ss;
    p->sigma_a_dry_per_m = sa;
    return SOAK_OK;
}
