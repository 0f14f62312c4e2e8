/* Former name of the staged output set; the API is in soak/staged.h. */
#ifndef SOAK_STAGED_FILES_H
#define SOAK_STAGED_FILES_H
#include "soak/staged.h"
#endif
