/* Cases the porous BRDF's tests share. */
#ifndef SOAK_TEST_POROUS_CASES_H
#define SOAK_TEST_POROUS_CASES_H

#include "soak/porous.h"

/* [Lag13]'s paper: Sp = 1.3, Kd = 0.7, Ks = 0.05, Kwater = 0.02, m = 0.19,
 * power 2/m^2 - 2; porosity and Sp as given. */
static inline soak_porous_params porous_paper_params(double porosity, double sp)
{
    soak_porous_params p = {0.7, 0.05, 0.19,  2.0 / (0.19 * 0.19) - 2.0, porosity,
                            sp,  0.02, 200.0, SOAK_BLINN_NORM_ENERGY};
    return p;
}

#endif
