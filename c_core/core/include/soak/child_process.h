/* Pieces shared by the readers that run in a child process with a time
 * limit (render/src/mesh_contain.c for Assimp, core/src/image_contain.c
 * for OpenImageIO): a monotonic clock, whole writes, and reads that give up
 * at a deadline. */
#ifndef SOAK_CHILD_PROCESS_H
#define SOAK_CHILD_PROCESS_H

#include <stddef.h>

/* Seconds on the monotonic clock. */
double soak_monotonic_s(void);

/* Writes all n bytes (retrying after EINTR): 0, or -1 on error. */
int soak_write_all(int fd, const void *data, size_t n);

/* Reads exactly n bytes before deadline (soak_monotonic_s): 0 when they
 * arrived, -1 on end of file or error, -2 at the deadline, -3 when a
 * signal the process catches interrupted the wait (an interrupt). */
#define SOAK_READ_EOF (-1)
#define SOAK_READ_TIMEOUT (-2)
#define SOAK_READ_INTERRUPTED (-3)
int soak_read_all(int fd, void *data, size_t n, double deadline);

/* A limit in seconds: the environment variable var when it holds a number
 * in (0, 1e6], else base_s + per_mib_s per MiB of bytes, at most 1e6. */
double soak_time_limit_s(const char *var, double base_s, double per_mib_s, long long bytes);

#endif
