/* (b) Traced index-matched isotropic half-space vs Chandrasekhar's H-function. */
// ctest-label: slow
#include "measure_cases.h"

int main(void)
{
    case_halfspace(400000, 2, 4);
    return check_finish();
}
