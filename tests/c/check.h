/* Minimal test helpers: every check prints what it compared, so a failing
 * run says which reference was missed and by how much. A test's main returns
 * check_finish(). */
#ifndef SOAK_TEST_CHECK_H
#define SOAK_TEST_CHECK_H

#include "soak/status.h"

/* |got - want| <= tol */
int check_close(const char *what, double got, double want, double tol);
/* |got - want| <= rel * |want| */
int check_rel(const char *what, double got, double want, double rel);
int check_true(const char *what, int cond);
int check_status(const char *what, soak_status got, soak_status want);
/* Exit code of a test whose checks were all skipped: registered as
 * SKIP_RETURN_CODE in tests/CMakeLists.txt, so ctest reports "Skipped". */
#define CHECK_SKIP_EXIT 77
/* Prints "SKIPPED: <reason> (<what>)"; never counts as a pass. A reason for a
 * missing tool reads "<tool> not on PATH" (scripts/test_skips.py fails
 * `make test` on it for the tools the set-up installs). */
void check_skip(const char *what, const char *reason);
/* 1 when a check failed or none ran, CHECK_SKIP_EXIT when every check was
 * skipped, 0 otherwise. */
int check_finish(void);

#endif
