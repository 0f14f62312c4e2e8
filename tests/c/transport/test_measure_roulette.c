/* (e) Russian roulette unbiased at albedo 0.9999; capped paths reported. */
// ctest-label: slow
#include "measure_cases.h"

int main(void)
{
    case_roulette(150000, 2);
    return check_finish();
}
