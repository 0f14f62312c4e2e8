/* soak_mesh_load: Assimp in a child process with a time limit.
 *
 * Assimp 5.2 aborts, crashes or loops forever on some malformed files (an
 * 8-byte OFF trips an assertion in its triangulator, a PLY header without
 * end_header never returns). The import therefore runs in a forked child
 * that sends the finished arrays back through a pipe; the parent turns a
 * crash, a hang past the limit or a short message into a clear error naming
 * the file. Only the formats listed in soak/geometry.h are accepted. The
 * child reads plain OBJ, PLY and STL with soak's own reader (mesh_native.h) and
 * everything that reader declines with Assimp.
 *
 * Before the child starts, the parent refuses what is not a regular file (a
 * FIFO would block its open forever, a folder reads as garbage) and checks
 * the file's header against its size (mesh_check.c), so most malformed
 * files are refused at once. The child dies with its parent (SIGKILL on the
 * parent's death, even by SIGKILL), and a signal the parent catches while it
 * waits (an interrupt) kills the child at once.
 *
 * The child is bounded in memory as well as time (issue 35): its address
 * space may grow by MEMORY_BASE_MIB plus MEMORY_PER_BYTE bytes per stored
 * byte of the mesh and the files it names (mesh_external.c), at most half
 * the machine's memory, or SOAK_MESH_MEMORY_MB (RLIMIT_AS; not in a
 * sanitizer build, whose shadow memory needs terabytes of address space).
 * Its stderr goes to a memory file: Assimp's own lines ("ai_assert failure
 * ...") never reach the terminal; the first of them is folded into soak's
 * message when the reader fails. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "mesh_import.h"
#include "mesh_native.h"
#include "soak/child_process.h"
#include "soak/input_file.h"

/* The time limit is the last line of defence after mesh_check.c: a fixed
 * start-up allowance plus one second per MiB (Assimp reads ~10-50 MiB/s in a
 * release build; a sanitizer build about ten times slower). */
#define TIMEOUT_BASE_S 10.0
#define TIMEOUT_S_PER_MIB 1.0
#define MEMORY_BASE_MIB 1024.0
#define MEMORY_PER_BYTE 32.0
#define CHILD_STDERR_MAX (64 << 10)

#if defined(__SANITIZE_ADDRESS__)
#define SOAK_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SOAK_ASAN 1
#endif
#endif

typedef struct reply_header {
    int32_t status, has_uvs, has_tri_uv;
    uint64_t n_vertices, n_triangles;
    char message[1024];
} reply_header;

/* Bytes the reader's address space may grow by: SOAK_MESH_MEMORY_MB when
 * set to a number in [64, 1e7], else MEMORY_BASE_MIB + MEMORY_PER_BYTE x
 * stored, at most half of the physical memory. */
static double memory_budget(long long stored)
{
    double b = MEMORY_BASE_MIB * 1048576.0 + MEMORY_PER_BYTE * (double)stored;
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0 && b > 0.5 * (double)pages * page) b = 0.5 * (double)pages * page;
    const char *e = getenv("SOAK_MESH_MEMORY_MB");
    if (!e || !*e) return b;
    char *end = NULL;
    double user = strtod(e, &end);
    return (*end == '\0' && user >= 64 && user <= 1e7) ? user * 1048576.0 : b;
}

/* In the child: the address space it has now plus the budget. */
static void limit_memory(double budget)
{
#ifdef SOAK_ASAN
    (void)budget;
#else
    FILE *f = fopen("/proc/self/statm", "re");
    unsigned long long pages = 0;
    if (!f) return;
    int ok = fscanf(f, "%llu", &pages) == 1;
    fclose(f);
    if (!ok) return;
    double now = (double)pages * (double)sysconf(_SC_PAGESIZE);
    struct rlimit rl = {(rlim_t)(now + budget), (rlim_t)(now + budget)};
    setrlimit(RLIMIT_AS, &rl);
#endif
}

/* The OBJ check reads the whole file twice (mesh_check.c; 0.3 s of a
 * 1 M-triangle bake): with the native reader on, which checks as it reads,
 * the child makes it only for an OBJ the native reader declines, before
 * Assimp reads it, with the same message. */
static int check_in_child(const char *path)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    return soak_mesh_native_enabled() && dot && (!slash || dot > slash) && !strcasecmp(dot, ".obj");
}

/* The native reader for the plain OBJ, PLY and STL files it takes, Assimp for
 * every other file (mesh_native.h); both inside this child. */
static soak_status read_mesh(const char *path, const soak_mesh_request *rq, soak_mesh *m, char *msg, size_t n)
{
    char why[160];
    if (soak_mesh_native_read(path, rq, m, why, sizeof why)) return SOAK_OK;
    if (check_in_child(path)) {
        FILE *f = fopen(path, "rb");
        struct stat sb;
        soak_status st = f && fstat(fileno(f), &sb) == 0 ? soak_mesh_check_file(path, f, (long long)sb.st_size, msg, n)
                                                         : SOAK_ERR_IO;
        if (!f) snprintf(msg, n, "%s: cannot open mesh file (%s)", path, strerror(errno));
        if (f) fclose(f);
        if (st != SOAK_OK) return st;
    }
    return soak_mesh_import_rq(path, rq, m, msg, n);
}

static void child_main(int fd, int err_fd, double budget, const char *path, const soak_mesh_request *rq,
                       pid_t parent)
{
    /* Dies with the parent; the check after it catches a parent that died
     * before the request was made. */
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent) _exit(4);
    if (err_fd >= 0 && dup2(err_fd, STDERR_FILENO) >= 0) {
        struct rlimit fs = {CHILD_STDERR_MAX, CHILD_STDERR_MAX}; /* the memory file stays small */
        signal(SIGXFSZ, SIG_IGN);
        setrlimit(RLIMIT_FSIZE, &fs);
    }
    limit_memory(budget);
    signal(SIGPIPE, SIG_DFL);
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    reply_header h;
    memset(&h, 0, sizeof h);
    soak_mesh m = {0};
    h.status = read_mesh(path, rq, &m, h.message, sizeof h.message);
    if (h.status == SOAK_OK) {
        h.n_vertices = m.n_vertices;
        h.n_triangles = m.n_triangles;
        h.has_uvs = m.uvs != NULL;
        h.has_tri_uv = m.tri_uv != NULL;
    }
    int bad = soak_write_all(fd, &h, sizeof h);
    if (!bad && h.status == SOAK_OK) {
        size_t nv = m.n_vertices, nt = m.n_triangles;
        bad = soak_write_all(fd, m.positions, 3 * nv * sizeof(double)) ||
              soak_write_all(fd, m.normals, 3 * nv * sizeof(double)) ||
              (m.uvs && soak_write_all(fd, m.uvs, 2 * nv * sizeof(double))) ||
              soak_write_all(fd, m.indices, 3 * nt * sizeof(unsigned)) ||
              (m.tri_uv && soak_write_all(fd, m.tri_uv, nt));
    }
    _exit(bad ? 3 : 0); /* no atexit handlers, no leak report for Assimp's state */
}

/* The reader child and its limits. */
typedef struct reader {
    pid_t pid;
    int err_fd; /* the child's stderr (a memory file), -1 if none */
    double limit_s, budget;
    const char *path;
} reader;

/* The first line with a letter the child wrote to its stderr (a
 * sanitizer's report starts with a line of '='), printable, or "". */
static void child_said(const reader *r, char *line, size_t n)
{
    char buf[4096];
    line[0] = '\0';
    if (r->err_fd < 0 || n < 2) return;
    ssize_t got = pread(r->err_fd, buf, sizeof buf - 1, 0);
    if (got <= 0) return;
    buf[got] = '\0';
    for (char *at = buf, *nl; at && *at; at = nl ? nl + 1 : NULL) {
        nl = strchr(at, '\n');
        if (nl) *nl = '\0';
        if (strpbrk(at, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz")) {
            snprintf(line, n, "%.*s", (int)(n - 1), at);
            break;
        }
    }
    soak_message_printable(line);
}

/* Waits for the child (killing it first when told to) and, when err is
 * given, says why it ended without a complete reply. */
static void child_fate(const reader *r, int timed_out, char *err, size_t errlen)
{
    int ws = 0;
    struct rusage ru;
    memset(&ru, 0, sizeof ru);
    if (timed_out) kill(r->pid, SIGKILL);
    while (wait4(r->pid, &ws, 0, &ru) < 0 && errno == EINTR) {
    }
    if (!err || !errlen) return;
    char said[300], tail[340] = "";
    child_said(r, said, sizeof said);
    if (said[0]) snprintf(tail, sizeof tail, " (the reader said: %s)", said);
    double peak = (double)ru.ru_maxrss * 1024.0;
    (void)peak; /* unused in a sanitizer build: no memory limit there */
    if (timed_out == -3)
        snprintf(err, errlen, "%s: mesh import interrupted", r->path);
    else if (timed_out)
        snprintf(err, errlen, "%s: the mesh reader did not finish within %g s: malformed or far too large file "
                 "(SOAK_MESH_TIMEOUT sets the limit)", r->path, r->limit_s);
#ifndef SOAK_ASAN
    else if (peak > 0.5 * r->budget || strstr(said, "bad_alloc") || strstr(said, "memory"))
        snprintf(err, errlen, "%s: the mesh reader needed more than its memory limit of %.0f MiB for this file and "
                 "the files it names (SOAK_MESH_MEMORY_MB sets the limit)", r->path, r->budget / 1048576.0);
#endif
    else if (WIFSIGNALED(ws))
        snprintf(err, errlen, "%s: the mesh reader crashed on this file (signal %d, %s): malformed file%s", r->path,
                 WTERMSIG(ws), strsignal(WTERMSIG(ws)), tail);
    else
        /* A sanitizer build turns the crash into an exit status. */
        snprintf(err, errlen, "%s: the mesh reader crashed on this file (exit status %d): malformed file%s", r->path,
                 WIFEXITED(ws) ? WEXITSTATUS(ws) : -1, tail);
    soak_message_printable(err);
}

static soak_status receive(int fd, const reader *rd, double deadline, soak_mesh *out, char *err, size_t errlen)
{
    reply_header h;
    int r = soak_read_all(fd, &h, sizeof h, deadline);
    if (r != 0) {
        child_fate(rd, r == SOAK_READ_TIMEOUT ? 1 : r == SOAK_READ_INTERRUPTED ? -3 : 0, err, errlen);
        return SOAK_ERR_PARSE;
    }
    h.message[sizeof h.message - 1] = '\0';
    if (h.status != SOAK_OK) {
        if (err && errlen && (h.status == SOAK_ERR_NOMEM || strstr(h.message, "bad_alloc")))
            snprintf(err, errlen, "%s (the mesh reader's memory limit for this file and the files it names is %.0f "
                     "MiB; SOAK_MESH_MEMORY_MB sets it)", h.message, rd->budget / 1048576.0);
        else if (err && errlen)
            snprintf(err, errlen, "%s", h.message);
        child_fate(rd, 0, NULL, 0);
        return h.status > SOAK_OK && h.status <= SOAK_ERR_NUMERIC ? (soak_status)h.status : SOAK_ERR_PARSE;
    }
    soak_mesh m = {0};
    m.n_vertices = h.n_vertices;
    m.n_triangles = h.n_triangles;
    if (h.n_vertices > 0xFFFFFFFEu || h.n_triangles > SIZE_MAX / 24) {
        child_fate(rd, 1, NULL, 0);
        if (err && errlen) snprintf(err, errlen, "%s: too many vertices or triangles", rd->path);
        return SOAK_ERR_ARG;
    }
    m.positions = malloc(3 * m.n_vertices * sizeof(double) + 1);
    m.normals = malloc(3 * m.n_vertices * sizeof(double) + 1);
    m.uvs = h.has_uvs ? malloc(2 * m.n_vertices * sizeof(double) + 1) : NULL;
    m.indices = malloc(3 * m.n_triangles * sizeof(unsigned) + 1);
    m.tri_uv = h.has_tri_uv ? malloc(m.n_triangles + 1) : NULL;
    if (!m.positions || !m.normals || !m.indices || (h.has_uvs && !m.uvs) || (h.has_tri_uv && !m.tri_uv)) {
        soak_mesh_free(&m);
        child_fate(rd, 1, NULL, 0);
        if (err && errlen)
            snprintf(err, errlen, "%s: out of memory for a mesh of %llu vertices and %llu triangles", rd->path,
                     (unsigned long long)h.n_vertices, (unsigned long long)h.n_triangles);
        return SOAK_ERR_NOMEM;
    }
    r = soak_read_all(fd, m.positions, 3 * m.n_vertices * sizeof(double), deadline);
    if (!r) r = soak_read_all(fd, m.normals, 3 * m.n_vertices * sizeof(double), deadline);
    if (!r && m.uvs) r = soak_read_all(fd, m.uvs, 2 * m.n_vertices * sizeof(double), deadline);
    if (!r) r = soak_read_all(fd, m.indices, 3 * m.n_triangles * sizeof(unsigned), deadline);
    if (!r && m.tri_uv) r = soak_read_all(fd, m.tri_uv, m.n_triangles, deadline);
    if (r != 0) {
        soak_mesh_free(&m);
        child_fate(rd, r == SOAK_READ_TIMEOUT ? 1 : r == SOAK_READ_INTERRUPTED ? -3 : 0, err, errlen);
        return SOAK_ERR_PARSE;
    }
    child_fate(rd, 0, NULL, 0);
    soak_status st = soak_mesh_validate(&m, rd->path, err, errlen);
    if (st == SOAK_OK) *out = m;
    return st;
}

/* Refuses what is not a regular file before opening it for reading (a
 * FIFO's open would block), then opens it without blocking and checks its
 * format and header. */
static soak_status open_and_check(const char *path, long long *size, soak_mesh_inputs *in, char *err,
                                  size_t errlen)
{
    struct stat sb;
    soak_status st = soak_input_check(path, SOAK_INPUT_MESH, NULL, err, errlen);
    if (st != SOAK_OK) return st;
    if (!soak_mesh_format_ok(path, err, errlen)) return SOAK_ERR_UNSUPPORTED;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    FILE *f = fd >= 0 ? fdopen(fd, "rb") : NULL;
    if (!f) {
        if (err && errlen) snprintf(err, errlen, "%s: cannot open mesh file (%s)", path, strerror(errno));
        if (fd >= 0) close(fd);
        return SOAK_ERR_IO;
    }
    if (fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode)) {
        if (err && errlen) snprintf(err, errlen, "%s: is not a regular file", path);
        st = SOAK_ERR_IO;
    } else {
        *size = (long long)sb.st_size;
        st = check_in_child(path) ? SOAK_OK : soak_mesh_check_file(path, f, *size, err, errlen);
    }
    fclose(f);
    if (st == SOAK_OK) st = soak_mesh_external_files(path, in, err, errlen);
    return st;
}

/* Forks the reader: it imports path and sends the mesh through fds[1]. */
static soak_status start_reader(reader *r, int fds[2], const soak_mesh_request *rq, char *err, size_t errlen)
{
    if (pipe2(fds, O_CLOEXEC) != 0) {
        if (err && errlen) snprintf(err, errlen, "%s: cannot start the mesh reader: %s", r->path, strerror(errno));
        return SOAK_ERR_IO;
    }
    r->err_fd = memfd_create("soak-mesh-reader-stderr", MFD_CLOEXEC);
    pid_t parent = getpid();
    fflush(NULL); /* nothing buffered is written twice by the child */
    r->pid = fork();
    if (r->pid < 0) {
        if (err && errlen) snprintf(err, errlen, "%s: cannot start the mesh reader: %s", r->path, strerror(errno));
        close(fds[0]);
        close(fds[1]);
        if (r->err_fd >= 0) close(r->err_fd);
        return SOAK_ERR_IO;
    }
    if (r->pid == 0) {
        close(fds[0]);
        child_main(fds[1], r->err_fd, r->budget, r->path, rq, parent);
    }
    close(fds[1]);
    return SOAK_OK;
}

static soak_status load(const char *path, const soak_mesh_request *rq, soak_mesh *mesh, char *err, size_t errlen)
{
    if (!path || !mesh) return SOAK_ERR_NULL;
    memset(mesh, 0, sizeof *mesh);
    long long size = 0;
    soak_mesh_inputs in = {0, 0};
    soak_status st = open_and_check(path, &size, &in, err, errlen);
    if (st == SOAK_OK) st = soak_mesh_reader_open(path, err, errlen); /* in the parent: the child only imports */
    if (st != SOAK_OK) return st;
    double limit_s = soak_time_limit_s("SOAK_MESH_TIMEOUT", TIMEOUT_BASE_S, TIMEOUT_S_PER_MIB, in.stored_bytes);
    reader r = {-1, -1, limit_s, memory_budget(in.stored_bytes), path};
    int fds[2];
    st = start_reader(&r, fds, rq, err, errlen);
    if (st != SOAK_OK) return st;
    st = receive(fds[0], &r, soak_monotonic_s() + r.limit_s, mesh, err, errlen);
    close(fds[0]);
    if (r.err_fd >= 0) close(r.err_fd);
    return st;
}

soak_status soak_mesh_load(const char *path, int require_uvs, soak_mesh *mesh, char *err, size_t errlen)
{
    soak_mesh_request rq = {require_uvs, NULL};
    return load(path, &rq, mesh, err, errlen);
}

soak_status soak_mesh_load_uv(const char *path, const soak_mesh_uv_choice *uv, soak_mesh *mesh, char *err,
                              size_t errlen)
{
    if (uv && (!(uv->uv_index >= 0 && uv->uv_index < SOAK_MESH_UV_SETS) ||
               !memchr(uv->uv_name, '\0', sizeof uv->uv_name)))
        return SOAK_ERR_ARG;
    soak_mesh_request rq = {SOAK_MESH_UVS_SOME, uv};
    return load(path, &rq, mesh, err, errlen);
}
