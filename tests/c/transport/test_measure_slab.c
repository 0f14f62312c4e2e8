/* (c) Traced isotropic slab (scalar and RGB walks) vs adding-doubling. */
// ctest-label: slow
#include "measure_cases.h"

int main(void)
{
    case_slab(1000000, 2);
    case_slab_rgb(400000);
    return check_finish();
}
