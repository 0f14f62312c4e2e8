/* Jensen-Legakis-Dorsey two-layer surface: [JLD99], Eq. 1-4. Readings and
 * corrections of the seed are listed in soak/jensen.h.
 *
 * Down: air (n1) -> liquid (n2) -> material (n3). Snell's invariant
 * n sin(theta) is the same in all three media (flat parallel interfaces),
 * so the refracted cosines follow from cos1 alone. Each crossing keeps the
 * fraction 1 - F of the flux (Fresnel reflectance F is the same both ways
 * through an interface at matching angles), the lower interface raised to k
 * as in the seed: T = (1 - F12(cos1)) (1 - F23(cos2)^k). Up is the same
 * product evaluated from cos3, so T_up(cos3) = T_down(cos1): reciprocity. */
#include "soak/jensen.h"

#include <math.h>
#include <stddef.h>

#include "soak/fresnel.h"

#define JENSEN_N_MIN 1.0
#define JENSEN_N_MAX 3.0
#define JENSEN_K_MIN 0.01
#define JENSEN_K_MAX 100.0

soak_status soak_jensen_validate(const soak_jensen_layer *l)
{
    if (!l) return SOAK_ERR_NULL;
    if (!soak_in_range(l->n1, JENSEN_N_MIN, JENSEN_N_MAX) || !soak_in_range(l->n2, JENSEN_N_MIN, JENSEN_N_MAX) ||
        !soak_in_range(l->n3, JENSEN_N_MIN, JENSEN_N_MAX) || !soak_in_range(l->k, JENSEN_K_MIN, JENSEN_K_MAX))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

/* Cosine in a medium of index n_to for Snell invariant s = n sin(theta),
 * or -1 when the direction cannot exist there (total internal reflection).
 * sin_t == 1 exactly is a grazing direction, left to the Fresnel term
 * (R = 1 unless the indices are equal, i.e. there is no interface). */
static double cos_in(double s, double n_to)
{
    double sin_t = s / n_to;
    if (sin_t > 1.0) return -1.0;
    return sqrt(1.0 - sin_t * sin_t);
}

/* Transmittance through both interfaces for a path with cosines c1 (air),
 * c2 (liquid): symmetric in the direction of travel. */
static double two_interface_transmittance(const soak_jensen_layer *l, double c1, double c2)
{
    double F12 = soak_fresnel_dielectric_raw(c1, l->n2 / l->n1, NULL);
    double F23 = soak_fresnel_dielectric_raw(c2, l->n3 / l->n2, NULL);
    double T = (1.0 - F12) * (1.0 - pow(F23, l->k));
    return T < 0.0 ? 0.0 : (T > 1.0 ? 1.0 : T);
}

soak_status soak_jensen_transmit_down(const soak_jensen_layer *l, double cos1, double *T, double *cos3)
{
    soak_status st = soak_jensen_validate(l);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(cos1, 0.0, 1.0)) return SOAK_ERR_ARG;
    double s = l->n1 * sqrt(fmax(0.0, 1.0 - cos1 * cos1));
    double c2 = cos_in(s, l->n2), c3 = cos_in(s, l->n3);
    /* a blocked path (n1 > n2 or n1 > n3 beyond the critical angle) transmits nothing */
    int blocked = c2 < 0.0 || c3 < 0.0;
    double t = blocked ? 0.0 : two_interface_transmittance(l, cos1, c2);
    if (T) *T = t;
    if (cos3) *cos3 = blocked ? 0.0 : c3;
    return SOAK_OK;
}

soak_status soak_jensen_transmit_up(const soak_jensen_layer *l, double cos3, double *T, double *cos1, int *tir)
{
    soak_status st = soak_jensen_validate(l);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(cos3, 0.0, 1.0)) return SOAK_ERR_ARG;
    double s = l->n3 * sqrt(fmax(0.0, 1.0 - cos3 * cos3));
    double c2 = cos_in(s, l->n2), c1 = cos_in(s, l->n1);
    int blocked = c2 < 0.0 || c1 < 0.0;
    double t = blocked ? 0.0 : two_interface_transmittance(l, c1, c2);
    if (T) *T = t;
    if (cos1) *cos1 = blocked ? 0.0 : c1;
    if (tir) *tir = blocked;
    return SOAK_OK;
}

soak_status soak_jensen_radiance_out(const soak_jensen_layer *l, double cos3, double *factor)
{
    if (!factor) return SOAK_ERR_NULL;
    double T = 0.0;
    soak_status st = soak_jensen_transmit_up(l, cos3, &T, NULL, NULL);
    if (st != SOAK_OK) return st;
    double ratio = l->n1 / l->n3;
    *factor = ratio * ratio * T;
    return SOAK_OK;
}

soak_status soak_jensen_reflect_top(const soak_jensen_layer *l, double cos1, double *R)
{
    if (!R) return SOAK_ERR_NULL;
    soak_status st = soak_jensen_validate(l);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(cos1, 0.0, 1.0)) return SOAK_ERR_ARG;
    *R = soak_fresnel_dielectric_raw(cos1, l->n2 / l->n1, NULL);
    return SOAK_OK;
}

soak_status soak_jensen_shadow(const soak_jensen_layer *l, double cos1, double *T)
{
    if (!T) return SOAK_ERR_NULL;
    return soak_jensen_transmit_down(l, cos1, T, NULL);
}
