/* The image library in a child process with a time limit (issue 35).
 *
 * The byte checks (image_check*.c) and the compression-ratio rule bound
 * what a file can make the reader allocate, but not how long a decoder
 * may work on it (a progressive JPEG may hold thousands of scans, each a
 * pass over the whole image). So OpenImageIO decodes in a forked child
 * that streams the rows as floats through a pipe into the caller's
 * buffer; the parent gives up at the deadline, kills the child and says
 * so. The child's own buffers stay native (8-bit PNG: a quarter of the
 * floats), so the pair holds little more than the one float copy a read
 * in the process held. Its stderr goes to /dev/null (libpng's own lines);
 * its message comes back in a shared page. It dies with the parent. */
#define _GNU_SOURCE
#include "image_contain.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "soak/child_process.h"

/* A start-up allowance plus one second per MiB of compressed pixel data:
 * decoders run at tens to hundreds of MiB/s of output, and the ratio rule
 * bounds the output at 256 float bytes per byte (a sanitizer build is
 * about ten times slower: still within it for the test images). */
#define TIMEOUT_BASE_S 10.0
#define TIMEOUT_S_PER_MIB 1.0

typedef struct reply {
    int32_t status;
    char message[1024];
} reply;

typedef struct dims {
    int32_t width, height, channels;
} dims;

typedef struct child_sink {
    int fd;
} child_sink;

static int send_dims(void *ctx, int width, int height, int channels)
{
    dims d = {width, height, channels};
    return soak_write_all(((child_sink *)ctx)->fd, &d, sizeof d);
}

static int send_rows(void *ctx, const float *values, size_t n)
{
    return soak_write_all(((child_sink *)ctx)->fd, values, n * sizeof(float));
}

static void child_main(int fd, reply *out, const soak_image_plugin *p, const char *path, long long payload,
                       pid_t parent)
{
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent) _exit(4);
    int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0) dup2(null, STDERR_FILENO);
    signal(SIGPIPE, SIG_DFL);
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    child_sink cs = {fd};
    soak_image_sink sink = {&cs, send_dims, send_rows};
    out->status = p->read_to(path, payload, &sink, out->message, sizeof out->message);
    _exit(out->status == SOAK_OK ? 0 : 1); /* no atexit handlers, no leak report for the library's state */
}

typedef struct reader {
    pid_t pid;
    double limit_s;
    const char *path;
    reply *reply; /* shared with the child */
} reader;

/* Kills and reaps the child (once the pixels are all here, what it does
 * next does not matter; once its pipe is closed it has already exited, and
 * its status stays) and, when the read did not complete (how: a
 * soak_read_all result), says why: its own message, the time limit or a
 * crash. */
static soak_status child_fate(const reader *r, int how, char *err, size_t errlen)
{
    int ws = 0;
    kill(r->pid, SIGKILL);
    while (waitpid(r->pid, &ws, 0) < 0 && errno == EINTR) {
    }
    if (how == 0) return SOAK_OK;
    soak_status st = SOAK_ERR_IO;
    if (how == SOAK_READ_INTERRUPTED) {
        if (err && errlen) snprintf(err, errlen, "%s: image read interrupted", r->path);
    } else if (how == SOAK_READ_TIMEOUT) {
        if (err && errlen)
            snprintf(err, errlen, "%s: the image reader did not finish within %g s: malformed or far too large file "
                     "(SOAK_IMAGE_TIMEOUT sets the limit)", r->path, r->limit_s);
    } else if (WIFEXITED(ws) && WEXITSTATUS(ws) == 1 && r->reply->status != SOAK_OK) {
        r->reply->message[sizeof r->reply->message - 1] = '\0';
        if (err && errlen) snprintf(err, errlen, "%s", r->reply->message);
        st = r->reply->status > SOAK_OK && r->reply->status <= SOAK_ERR_NUMERIC ? (soak_status)r->reply->status
                                                                                 : SOAK_ERR_IO;
    } else if (err && errlen) {
        if (WIFSIGNALED(ws))
            snprintf(err, errlen, "%s: the image reader crashed on this file (signal %d, %s): malformed file",
                     r->path, WTERMSIG(ws), strsignal(WTERMSIG(ws)));
        else
            snprintf(err, errlen, "%s: the image reader crashed on this file (exit status %d): malformed file",
                     r->path, WIFEXITED(ws) ? WEXITSTATUS(ws) : -1);
    }
    if (err && errlen) soak_message_printable(err);
    return st;
}

/* The size, then the pixels into img, before the deadline. */
static soak_status receive(int fd, const reader *r, soak_image *img, char *err, size_t errlen)
{
    double deadline = soak_monotonic_s() + r->limit_s;
    dims d;
    int got = soak_read_all(fd, &d, sizeof d, deadline);
    if (got != 0) return child_fate(r, got, err, errlen);
    if (!(d.width >= 1 && d.width <= SOAK_IMAGE_MAX_SIDE && d.height >= 1 && d.height <= SOAK_IMAGE_MAX_SIDE &&
          d.channels >= 1 && d.channels <= 4)) {
        child_fate(r, SOAK_READ_EOF, NULL, 0);
        if (err && errlen) snprintf(err, errlen, "%s: the image reader sent a size out of range", r->path);
        return SOAK_ERR_IO;
    }
    soak_status st = soak_image_alloc(img, d.width, d.height, d.channels);
    if (st != SOAK_OK) {
        child_fate(r, SOAK_READ_EOF, NULL, 0);
        if (err && errlen)
            snprintf(err, errlen, "%s: out of memory for a %dx%dx%d image", r->path, d.width, d.height, d.channels);
        return st;
    }
    size_t n = (size_t)d.width * d.height * d.channels * sizeof(float);
    got = soak_read_all(fd, img->pixels, n, deadline);
    if (got != 0) {
        soak_image_free(img);
        return child_fate(r, got, err, errlen);
    }
    return child_fate(r, 0, NULL, 0);
}

/* SOAK_IMAGE_IN_PROCESS=1: the same sink, in this process (for a fuzzer,
 * which must see the library's crashes, and for a debugger). */
typedef struct local_sink {
    soak_image *img;
    size_t filled;
} local_sink;

static int alloc_image(void *ctx, int width, int height, int channels)
{
    local_sink *ls = ctx;
    return soak_image_alloc(ls->img, width, height, channels) != SOAK_OK;
}

static int copy_rows(void *ctx, const float *values, size_t n)
{
    local_sink *ls = ctx;
    size_t total = (size_t)ls->img->width * ls->img->height * ls->img->channels;
    if (!ls->img->pixels || n > total - ls->filled) return 1;
    memcpy(ls->img->pixels + ls->filled, values, n * sizeof(float));
    ls->filled += n;
    return 0;
}

static soak_status read_in_process(const soak_image_plugin *p, const char *path, long long payload, soak_image *img,
                                   char *err, size_t errlen)
{
    local_sink ls = {img, 0};
    soak_image_sink sink = {&ls, alloc_image, copy_rows};
    if (err && errlen) err[0] = '\0';
    soak_status st = p->read_to(path, payload, &sink, err, errlen);
    if (st == SOAK_OK && ls.filled != (size_t)img->width * img->height * img->channels) st = SOAK_ERR_IO;
    if (st != SOAK_OK && err && errlen && !err[0])
        snprintf(err, errlen, "%s: out of memory for the decoded image", path);
    if (st != SOAK_OK) soak_image_free(img);
    return st;
}

soak_status soak_image_read_contained(const soak_image_plugin *p, const char *path, long long payload,
                                      soak_image *img, char *err, size_t errlen)
{
    img->pixels = NULL;
    const char *local = getenv("SOAK_IMAGE_IN_PROCESS");
    if (local && !strcmp(local, "1")) return read_in_process(p, path, payload, img, err, errlen);
    reply *shared = mmap(NULL, sizeof(reply), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    int fds[2];
    if (shared == MAP_FAILED || pipe2(fds, O_CLOEXEC) != 0) {
        if (err && errlen) snprintf(err, errlen, "%s: cannot start the image reader: %s", path, strerror(errno));
        if (shared != MAP_FAILED) munmap(shared, sizeof(reply));
        return SOAK_ERR_IO;
    }
    memset(shared, 0, sizeof *shared);
    shared->status = SOAK_ERR_IO;
    reader r = {-1, soak_time_limit_s("SOAK_IMAGE_TIMEOUT", TIMEOUT_BASE_S, TIMEOUT_S_PER_MIB, payload), path, shared};
    pid_t parent = getpid();
    fflush(NULL); /* nothing buffered is written twice by the child */
    r.pid = fork();
    if (r.pid == 0) {
        close(fds[0]);
        child_main(fds[1], shared, p, path, payload, parent);
    }
    close(fds[1]);
    soak_status st = SOAK_ERR_IO;
    if (r.pid < 0) {
        if (err && errlen) snprintf(err, errlen, "%s: cannot start the image reader: %s", path, strerror(errno));
    } else {
        st = receive(fds[0], &r, img, err, errlen);
    }
    close(fds[0]);
    munmap(shared, sizeof(reply));
    return st;
}
