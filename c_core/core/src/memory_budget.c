/* A command's working-memory budget (soak/image.h): refused from an
 * estimate before the buffers are allocated, with the numbers. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "soak/image.h"

double soak_memory_budget(long long input_bytes)
{
    const char *e = getenv("SOAK_MAX_MEMORY_MB");
    if (e && *e) {
        char *end = NULL;
        double user = strtod(e, &end);
        if (*end == '\0' && soak_in_range(user, 64, 1e7)) return user * 1048576.0;
    }
    double b = SOAK_MEMORY_RATIO * (double)input_bytes;
    if (b < SOAK_MEMORY_FREE_BYTES) b = SOAK_MEMORY_FREE_BYTES;
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0 && b > 0.5 * (double)pages * page) b = 0.5 * (double)pages * page;
    return b;
}

soak_status soak_memory_check(const char *what, double estimate_bytes, long long input_bytes, char *err,
                              size_t errlen)
{
    double budget = soak_memory_budget(input_bytes);
    if (soak_in_range(estimate_bytes, 0, budget)) return SOAK_OK;
    if (err && errlen) {
        snprintf(err, errlen, "%s needs about %.0f MiB of working memory; the budget is %.0f MiB (the larger of %.0f "
                 "MiB and %.0f bytes per byte of compressed input, %lld bytes here, at most half the machine's "
                 "memory; SOAK_MAX_MEMORY_MB sets it)", what ? what : "this command", estimate_bytes / 1048576.0,
                 budget / 1048576.0, SOAK_MEMORY_FREE_BYTES / 1048576.0, SOAK_MEMORY_RATIO, input_bytes);
        soak_message_printable(err);
    }
    return SOAK_ERR_ARG;
}
