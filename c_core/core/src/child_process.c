/* soak/child_process.h */
#define _GNU_SOURCE
#include "soak/child_process.h"

#include <errno.h>
#include <poll.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#define LIMIT_MAX_S 1e6

double soak_monotonic_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int soak_write_all(int fd, const void *data, size_t n)
{
    const char *p = data;
    while (n > 0) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return -1;
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

int soak_read_all(int fd, void *data, size_t n, double deadline)
{
    char *p = data;
    while (n > 0) {
        double left = deadline - soak_monotonic_s();
        if (left <= 0) return SOAK_READ_TIMEOUT;
        struct pollfd pfd = {fd, POLLIN, 0};
        int r = poll(&pfd, 1, left > 1e6 ? 1000000000 : (int)(left * 1000) + 1);
        if (r < 0 && errno == EINTR) return SOAK_READ_INTERRUPTED;
        if (r < 0) return SOAK_READ_EOF;
        if (r == 0) continue;
        ssize_t got = read(fd, p, n);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return SOAK_READ_EOF;
        p += got;
        n -= (size_t)got;
    }
    return 0;
}

double soak_time_limit_s(const char *var, double base_s, double per_mib_s, long long bytes)
{
    double t = base_s + per_mib_s * (double)bytes / 1048576.0;
    if (!(t <= LIMIT_MAX_S)) t = LIMIT_MAX_S;
    const char *e = var ? getenv(var) : NULL;
    if (!e || !*e) return t;
    char *end = NULL;
    double user = strtod(e, &end);
    return (*end == '\0' && user > 0 && user <= LIMIT_MAX_S) ? user : t;
}
