/* (a) Traced film over a Lambertian base vs Lekner-Dorf, written in the test. */
// ctest-label: slow
#include "measure_cases.h"

int main(void)
{
    case_film(2000000, 2);
    case_film_absorbing(500000, 2);
    return check_finish();
}
