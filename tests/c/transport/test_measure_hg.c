/* (d) Mean cosine and P2 moment of the directions scattered by the walk. */
// ctest-label: slow
#include "measure_cases.h"

int main(void)
{
    case_hg(2000000);
    return check_finish();
}
