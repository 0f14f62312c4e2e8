/* Length units at libsoak's boundaries (c_core/ARCHITECTURE.md, Units): a
 * length and its coefficients (extinction, scattering, absorption) share
 * one unit, named in the field when it is fixed (_m, _per_m: presets and
 * the wetness chain, in metres); a field without one is in the length unit
 * of whoever fills it (the scene's in the renderer). Files and front
 * ends keep their own documented units -- materials.json in mm and 1/mm,
 * POV-Ray's subsurface in mm, a scene or a baked volume in its length unit
 * -- and are converted here, once where they are read and once where they
 * are written, so that no other file multiplies by 1000.
 *
 * Division by SOAK_MM_PER_M, not multiplication by 1e-3: 1e-3 is not a
 * double, so x * 1e-3 is not the nearest double to x/1000 (x / 1000 is). */
#ifndef SOAK_UNITS_H
#define SOAK_UNITS_H

#include "soak/vec.h"

#define SOAK_MM_PER_M 1000.0

/* Lengths. */
static inline double soak_m_from_mm(double mm) { return mm / SOAK_MM_PER_M; }
static inline double soak_mm_from_m(double m) { return m * SOAK_MM_PER_M; }

/* Coefficients (per length). */
static inline double soak_per_m_from_per_mm(double per_mm) { return per_mm * SOAK_MM_PER_M; }
static inline double soak_per_mm_from_per_m(double per_m) { return per_m / SOAK_MM_PER_M; }

static inline soak_rgb soak_rgb_per_m_from_per_mm(soak_rgb per_mm)
{
    return soak_rgb3(soak_per_m_from_per_mm(per_mm.r), soak_per_m_from_per_mm(per_mm.g),
                     soak_per_m_from_per_mm(per_mm.b));
}
static inline soak_rgb soak_rgb_per_mm_from_per_m(soak_rgb per_m)
{
    return soak_rgb3(soak_per_mm_from_per_m(per_m.r), soak_per_mm_from_per_m(per_m.g),
                     soak_per_mm_from_per_m(per_m.b));
}

/* A length unit given in metres per unit (a scene's or a volume's): a
 * coefficient in 1/m becomes one per unit, a length in m a number of units. */
static inline double soak_per_unit_from_per_m(double per_m, double m_per_unit) { return per_m * m_per_unit; }
static inline soak_rgb soak_rgb_per_unit_from_per_m(soak_rgb per_m, double m_per_unit)
{
    return soak_rgb3(per_m.r * m_per_unit, per_m.g * m_per_unit, per_m.b * m_per_unit);
}
static inline double soak_units_from_m(double m, double m_per_unit) { return m / m_per_unit; }

#endif
