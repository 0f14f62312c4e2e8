#include "check.h"

#include <math.h>
#include <stdio.h>

static int n_pass, n_fail, n_skip;

static int record(int ok, const char *what)
{
    if (ok) ++n_pass;
    else {
        ++n_fail;
        printf("FAIL %s\n", what);
    }
    return ok;
}

int check_close(const char *what, double got, double want, double tol)
{
    int ok = fabs(got - want) <= tol;
    printf("%s %s: got %.12g want %.12g (tol %.3g)\n", ok ? "ok  " : "FAIL", what, got, want, tol);
    return record(ok, what);
}

int check_rel(const char *what, double got, double want, double rel)
{
    int ok = fabs(got - want) <= rel * fabs(want);
    printf("%s %s: got %.12g want %.12g (rel %.3g)\n", ok ? "ok  " : "FAIL", what, got, want, rel);
    return record(ok, what);
}

int check_true(const char *what, int cond) { return record(cond != 0, what); }

int check_status(const char *what, soak_status got, soak_status want)
{
    int ok = got == want;
    if (!ok) printf("FAIL %s: status %s, want %s\n", what, soak_status_str(got), soak_status_str(want));
    return record(ok, what);
}

void check_skip(const char *what, const char *reason)
{
    ++n_skip;
    printf("SKIPPED: %s (%s)\n", reason, what);
}

int check_finish(void)
{
    printf("%d passed, %d failed, %d skipped\n", n_pass, n_fail, n_skip);
    if (n_fail) return 1;
    if (n_pass == 0 && n_skip > 0) return CHECK_SKIP_EXIT; /* ctest: Skipped, never Passed */
    if (n_pass == 0) {
        printf("FAIL no check ran\n");
        return 1;
    }
    return 0;
}
