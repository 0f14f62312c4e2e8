/* The neighbour steps of the rain bake's grid (bake_rain_grid.h). */
#include "bake_rain_grid.h"

const int SOAK_RAIN_DX[8] = SOAK_RAIN_DX_INIT;
const int SOAK_RAIN_DY[8] = SOAK_RAIN_DY_INIT;
