/* soak_mesh_load: Assimp in a child process with a time limit.
 *
 * Assimp 5.2 aborts, crashes or loops forever on some malformed files (an
 * 8-byte OFF trips an assertion in its triangulator, a PLY header without
 * end_header never returns). The import therefore runs in a forked child
 * that sends the finished arrays back through a pipe; the parent turns a
 * crash, a hang past the limit or a short message into a clear error naming
 * the file. Only the formats listed in soak/geometry.h are accepted.
 *
 * Before the child starts, the parent refuses what is not a regular file (a
 * FIFO would block its open forever, a folder reads as garbage) and checks
 * the file's header against its size (mesh_check.c), so most malformed
 * files are refused at once. The child dies with its parent (SIGKILL on the
 * parent's death, even by SIGKILL), and a signal the parent catches while it
 * waits (an interrupt) kills the child at once. */
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
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "mesh_import.h"
#include "soak/input_file.h"

/* The time limit is the last line of defence after mesh_check.c: a fixed
 * start-up allowance plus one second per MiB (Assimp reads ~10-50 MiB/s in a
 * release build; a sanitizer build about ten times slower). */
#define TIMEOUT_BASE_S 10.0
#define TIMEOUT_S_PER_MIB 1.0
#define TIMEOUT_MAX_S 1e6

typedef struct reply_header {
    int32_t status, has_uvs;
    uint64_t n_vertices, n_triangles;
    char message[1024];
} reply_header;

int soak_mesh_format_ok(const char *path)
{
    static const char *const ok[] = {"obj", "ply", "stl", "off", "gltf", "glb"};
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(path, '.');
    if (!dot || (slash && dot < slash)) return 0;
    for (size_t i = 0; i < sizeof ok / sizeof ok[0]; ++i)
        if (strcasecmp(dot + 1, ok[i]) == 0) return 1;
    return 0;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* Seconds the import of a file of size bytes may take: SOAK_MESH_TIMEOUT
 * when set to a number in (0, 1e6], else proportional to the size. */
static double timeout_s(long long size)
{
    double t = TIMEOUT_BASE_S + TIMEOUT_S_PER_MIB * (double)size / 1048576.0;
    if (t > TIMEOUT_MAX_S) t = TIMEOUT_MAX_S;
    const char *e = getenv("SOAK_MESH_TIMEOUT");
    if (!e || !*e) return t;
    char *end = NULL;
    double user = strtod(e, &end);
    return (*end == '\0' && user > 0 && user <= TIMEOUT_MAX_S) ? user : t;
}

static int write_all(int fd, const void *data, size_t n)
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

/* 0 when n bytes arrived before the deadline, -1 on EOF/error, -2 on
 * timeout, -3 when a caught signal interrupted the wait. */
static int read_all(int fd, void *data, size_t n, double deadline)
{
    char *p = data;
    while (n > 0) {
        double left = deadline - now_s();
        if (left <= 0) return -2;
        struct pollfd pfd = {fd, POLLIN, 0};
        int r = poll(&pfd, 1, left > 1e6 ? 1000000000 : (int)(left * 1000) + 1);
        if (r < 0 && errno == EINTR) return -3; /* a signal the process catches: an interrupt */
        if (r < 0) return -1;
        if (r == 0) continue;
        ssize_t got = read(fd, p, n);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return -1;
        p += got;
        n -= (size_t)got;
    }
    return 0;
}

static void child_main(int fd, const char *path, int require_uvs, pid_t parent)
{
    /* Dies with the parent; the check after it catches a parent that died
     * before the request was made. */
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent) _exit(4);
    signal(SIGPIPE, SIG_DFL);
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    reply_header h;
    memset(&h, 0, sizeof h);
    soak_mesh m = {0};
    h.status = soak_mesh_import(path, require_uvs, &m, h.message, sizeof h.message);
    if (h.status == SOAK_OK) {
        h.n_vertices = m.n_vertices;
        h.n_triangles = m.n_triangles;
        h.has_uvs = m.uvs != NULL;
    }
    int bad = write_all(fd, &h, sizeof h);
    if (!bad && h.status == SOAK_OK) {
        size_t nv = m.n_vertices, nt = m.n_triangles;
        bad = write_all(fd, m.positions, 3 * nv * sizeof(double)) || write_all(fd, m.normals, 3 * nv * sizeof(double)) ||
              (m.uvs && write_all(fd, m.uvs, 2 * nv * sizeof(double))) ||
              write_all(fd, m.indices, 3 * nt * sizeof(unsigned));
    }
    _exit(bad ? 3 : 0); /* no atexit handlers, no leak report for Assimp's state */
}

/* Why the child ended without a complete reply. */
static void child_fate(pid_t pid, int timed_out, double limit, const char *path, char *err, size_t errlen)
{
    int ws = 0;
    if (timed_out) kill(pid, SIGKILL);
    while (waitpid(pid, &ws, 0) < 0 && errno == EINTR) {
    }
    if (!err || !errlen) return;
    if (timed_out == -3)
        snprintf(err, errlen, "%s: mesh import interrupted", path);
    else if (timed_out)
        snprintf(err, errlen, "%s: the mesh reader did not finish within %g s: malformed or far too large file "
                 "(SOAK_MESH_TIMEOUT sets the limit)", path, limit);
    else if (WIFSIGNALED(ws))
        snprintf(err, errlen, "%s: the mesh reader crashed on this file (signal %d, %s): malformed file", path,
                 WTERMSIG(ws), strsignal(WTERMSIG(ws)));
    else
        /* A sanitizer build turns the crash into an exit status. */
        snprintf(err, errlen, "%s: the mesh reader crashed on this file (exit status %d): malformed file", path,
                 WIFEXITED(ws) ? WEXITSTATUS(ws) : -1);
}

static soak_status receive(int fd, pid_t pid, double deadline, double limit, const char *path, soak_mesh *out,
                           char *err, size_t errlen)
{
    reply_header h;
    int r = read_all(fd, &h, sizeof h, deadline);
    if (r != 0) {
        child_fate(pid, r == -2 ? 1 : r == -3 ? -3 : 0, limit, path, err, errlen);
        return SOAK_ERR_PARSE;
    }
    h.message[sizeof h.message - 1] = '\0';
    if (h.status != SOAK_OK) {
        if (err && errlen) snprintf(err, errlen, "%s", h.message);
        child_fate(pid, 0, limit, path, NULL, 0);
        return h.status > SOAK_OK && h.status <= SOAK_ERR_NUMERIC ? (soak_status)h.status : SOAK_ERR_PARSE;
    }
    soak_mesh m = {0};
    m.n_vertices = h.n_vertices;
    m.n_triangles = h.n_triangles;
    if (h.n_vertices > 0xFFFFFFFEu || h.n_triangles > SIZE_MAX / 24) {
        child_fate(pid, 1, limit, path, NULL, 0);
        if (err && errlen) snprintf(err, errlen, "%s: too many vertices or triangles", path);
        return SOAK_ERR_ARG;
    }
    m.positions = malloc(3 * m.n_vertices * sizeof(double) + 1);
    m.normals = malloc(3 * m.n_vertices * sizeof(double) + 1);
    m.uvs = h.has_uvs ? malloc(2 * m.n_vertices * sizeof(double) + 1) : NULL;
    m.indices = malloc(3 * m.n_triangles * sizeof(unsigned) + 1);
    if (!m.positions || !m.normals || !m.indices || (h.has_uvs && !m.uvs)) {
        soak_mesh_free(&m);
        child_fate(pid, 1, limit, path, NULL, 0);
        return SOAK_ERR_NOMEM;
    }
    r = read_all(fd, m.positions, 3 * m.n_vertices * sizeof(double), deadline);
    if (!r) r = read_all(fd, m.normals, 3 * m.n_vertices * sizeof(double), deadline);
    if (!r && m.uvs) r = read_all(fd, m.uvs, 2 * m.n_vertices * sizeof(double), deadline);
    if (!r) r = read_all(fd, m.indices, 3 * m.n_triangles * sizeof(unsigned), deadline);
    if (r != 0) {
        soak_mesh_free(&m);
        child_fate(pid, r == -2 ? 1 : r == -3 ? -3 : 0, limit, path, err, errlen);
        return SOAK_ERR_PARSE;
    }
    child_fate(pid, 0, limit, path, NULL, 0);
    soak_status st = soak_mesh_validate(&m, path, err, errlen);
    if (st == SOAK_OK) *out = m;
    return st;
}

/* Refuses what is not a regular file before opening it for reading (a
 * FIFO's open would block), then opens it without blocking and checks its
 * format and header. */
static soak_status open_and_check(const char *path, long long *size, char *err, size_t errlen)
{
    struct stat sb;
    soak_status st = soak_input_check(path, SOAK_INPUT_MESH, NULL, err, errlen);
    if (st != SOAK_OK) return st;
    if (!soak_mesh_format_ok(path)) {
        if (err && errlen)
            snprintf(err, errlen, "%s: unsupported mesh format (use .obj, .ply, .stl, .off, .gltf or .glb)", path);
        return SOAK_ERR_UNSUPPORTED;
    }
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
        st = soak_mesh_check_file(path, f, *size, err, errlen);
    }
    fclose(f);
    return st;
}

soak_status soak_mesh_load(const char *path, int require_uvs, soak_mesh *mesh, char *err, size_t errlen)
{
    if (!path || !mesh) return SOAK_ERR_NULL;
    memset(mesh, 0, sizeof *mesh);
    long long size = 0;
    soak_status st = open_and_check(path, &size, err, errlen);
    if (st == SOAK_OK) st = soak_mesh_reader_open(path, err, errlen); /* in the parent: the child only imports */
    if (st != SOAK_OK) return st;
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) {
        if (err && errlen) snprintf(err, errlen, "%s: cannot start the mesh reader: %s", path, strerror(errno));
        return SOAK_ERR_IO;
    }
    double limit = timeout_s(size);
    pid_t parent = getpid();
    fflush(NULL); /* nothing buffered is written twice by the child */
    pid_t pid = fork();
    if (pid < 0) {
        if (err && errlen) snprintf(err, errlen, "%s: cannot start the mesh reader: %s", path, strerror(errno));
        close(fds[0]);
        close(fds[1]);
        return SOAK_ERR_IO;
    }
    if (pid == 0) {
        close(fds[0]);
        child_main(fds[1], path, require_uvs, parent);
    }
    close(fds[1]);
    st = receive(fds[0], pid, now_s() + limit, limit, path, mesh, err, errlen);
    close(fds[0]);
    return st;
}
