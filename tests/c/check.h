/* Minimal test helpers: every check prints what it compared, so a failing
 * run says which reference was missed and by how much. A test's main returns
 * check_finish(), non-zero when any check failed. */
#ifndef SOAK_TEST_CHECK_H
#define SOAK_TEST_CHECK_H

#include "soak/status.h"

/* |got - want| <= tol */
int check_close(const char *what, double got, double want, double tol);
/* |got - want| <= rel * |want| */
int check_rel(const char *what, double got, double want, double rel);
int check_true(const char *what, int cond);
int check_status(const char *what, soak_status got, soak_status want);
/* Prints SKIPPED with a reason; never counts as a pass. */
void check_skip(const char *what, const char *reason);
int check_finish(void);

#endif
