/* The input policy (soak/input_file.h), each failure path provoked and its
 * message checked (issue 35): not a regular file (FIFO, folder, device),
 * over the cap (a sparse file), out of memory (RLIMIT_AS in a child), a
 * short read and a file that grows while it is read (files whose size
 * stat reports differently from their content: sysfs, /proc), missing; and a
 * successful read returns the bytes written, zero-terminated. */
#define _GNU_SOURCE
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check.h"
#include "soak/input_file.h"

#if defined(__SANITIZE_ADDRESS__)
#define UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UNDER_ASAN 1
#endif
#endif

static char dir[] = "/tmp/soak_input_file_XXXXXX";

static void path_in(char *out, size_t n, const char *name)
{
    snprintf(out, n, "%s/%s", dir, name);
}

/* status wanted and every word of want in the message */
static void expect(const char *what, soak_status got, soak_status want, const char *err, const char *const *words)
{
    check_status(what, got, want);
    for (; words && *words; ++words) {
        char label[256];
        snprintf(label, sizeof label, "%s: message '%s' contains '%s'", what, err, *words);
        check_true(label, strstr(err, *words) != NULL);
    }
}

static void refuses_what_is_not_a_file(void)
{
    char fifo[256], folder[256], err[512];
    char *text = NULL;
    path_in(fifo, sizeof fifo, "f.json");
    path_in(folder, sizeof folder, "d.json");
    if (mkfifo(fifo, 0600) != 0 || mkdir(folder, 0700) != 0) {
        check_skip("non-regular inputs", "cannot make a FIFO or folder in /tmp");
        return;
    }
    const char *fifo_words[] = {"f.json", "scene file", "FIFO", "not a regular file", NULL};
    expect("FIFO: refused without blocking", soak_input_read(fifo, SOAK_INPUT_SCENE, &text, NULL, err, sizeof err),
           SOAK_ERR_IO, err, fifo_words);
    const char *dir_words[] = {"d.json", "folder", NULL};
    expect("folder", soak_input_check(folder, SOAK_INPUT_IMAGE, NULL, err, sizeof err), SOAK_ERR_IO, err, dir_words);
    const char *dev_words[] = {"/dev/zero", "presets file", "device", NULL};
    expect("/dev/zero", soak_input_read("/dev/zero", SOAK_INPUT_PRESETS, &text, NULL, err, sizeof err), SOAK_ERR_IO,
           err, dev_words);
    const char *missing_words[] = {"missing.json", "No such file", NULL};
    char missing[256];
    path_in(missing, sizeof missing, "missing.json");
    expect("missing", soak_input_check(missing, SOAK_INPUT_SCENE, NULL, err, sizeof err), SOAK_ERR_IO, err,
           missing_words);
    check_true("nothing returned on failure", text == NULL);
}

static int make_sparse(const char *path, off_t size)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0) return -1;
    int r = ftruncate(fd, size);
    close(fd);
    return r;
}

static void caps_and_content(void)
{
    char big[256], small[256], err[512];
    path_in(big, sizeof big, "big.json");
    path_in(small, sizeof small, "small.json");
    /* 16 MiB + 1 byte: one over the scene cap (the README's 16 MiB). */
    if (make_sparse(big, 16 * 1048576 + 1) != 0) {
        check_skip("cap", "cannot make a sparse file");
        return;
    }
    const char *words[] = {"big.json", "16777217 bytes", "16 MiB", "SOAK_MAX_SCENE_MB", NULL};
    char *text = NULL;
    expect("over the cap", soak_input_read(big, SOAK_INPUT_SCENE, &text, NULL, err, sizeof err), SOAK_ERR_ARG, err, words);
    setenv("SOAK_MAX_SCENE_MB", "17", 1);
    long long size = 0;
    check_status("the variable raises the cap", soak_input_check(big, SOAK_INPUT_SCENE, &size, err, sizeof err), SOAK_OK);
    check_close("size reported", (double)size, 16.0 * 1048576 + 1, 0);
    check_close("cap in bytes", (double)soak_input_cap(SOAK_INPUT_SCENE), 17.0 * 1048576, 0);
    setenv("SOAK_MAX_SCENE_MB", "nonsense", 1);
    check_close("an unreadable value keeps the default", (double)soak_input_cap(SOAK_INPUT_SCENE), 16.0 * 1048576, 0);
    unsetenv("SOAK_MAX_SCENE_MB");
    FILE *f = fopen(small, "wb");
    fputs("{\"a\": 1}", f);
    fclose(f);
    size_t n = 0;
    check_status("a small file reads", soak_input_read(small, SOAK_INPUT_SCENE, &text, &n, err, sizeof err), SOAK_OK);
    check_true("its bytes, zero-terminated", text && n == 8 && !strcmp(text, "{\"a\": 1}"));
    free(text);
    long long total = 0;
    check_status("parts add up", soak_input_check_part(small, SOAK_INPUT_MESH, "buffer", &total, err, sizeof err),
                 SOAK_OK);
    soak_input_check_part(small, SOAK_INPUT_MESH, "buffer", &total, err, sizeof err);
    check_close("two parts of 8 bytes", (double)total, 16, 0);
    check_close("a sparse file's holes are not stored bytes", (double)soak_input_stored_bytes(1 << 30, 8), 4096, 0);
    check_close("small files count whole", (double)soak_input_stored_bytes(1000, 0), 1000, 0);
}

/* /proc files are regular but report size 0: the read finds more than the
 * size it was opened with, and stops. */
static void grows_while_read(void)
{
    char err[512];
    char *text = NULL;
    const char *words[] = {"/proc/self/status", "grew while it was read", NULL};
    expect("a file larger than its size", soak_input_read("/proc/self/status", SOAK_INPUT_SCENE, &text, NULL, err,
                                                            sizeof err),
           SOAK_ERR_IO, err, words);
}

/* Out of memory: a child with a small address space reads a 900 MiB
 * (sparse) scene with the cap raised; the message must name the file. */
static void out_of_memory(void)
{
#ifdef UNDER_ASAN
    check_skip("out of memory", "RLIMIT_AS cannot be used under AddressSanitizer");
#else
    char big[256];
    path_in(big, sizeof big, "oom.json");
    if (make_sparse(big, 900LL * 1048576) != 0) return check_skip("out of memory", "cannot make a sparse file");
    int fds[2];
    if (pipe(fds) != 0) return check_skip("out of memory", "no pipe");
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        struct rlimit rl = {512ull << 20, 512ull << 20};
        setrlimit(RLIMIT_AS, &rl);
        setenv("SOAK_MAX_SCENE_MB", "1000", 1);
        char err[512] = "";
        char *text = NULL;
        soak_status st = soak_input_read(big, SOAK_INPUT_SCENE, &text, NULL, err, sizeof err);
        dprintf(fds[1], "%d %s", (int)st, err);
        _exit(0);
    }
    close(fds[1]);
    char msg[600] = "";
    ssize_t got = read(fds[0], msg, sizeof msg - 1);
    msg[got > 0 ? got : 0] = '\0';
    close(fds[0]);
    waitpid(pid, NULL, 0);
    int st = atoi(msg);
    const char *m = strchr(msg, ' ') ? strchr(msg, ' ') + 1 : "";
    const char *words[] = {"oom.json", "out of memory", "943718400 bytes", "scene file", NULL};
    expect("out of memory under RLIMIT_AS", (soak_status)st, SOAK_ERR_NOMEM, m, words);
#endif
}

/* sysfs files are regular and report 4096 bytes but hold fewer: a short
 * read, refused rather than padded. */
static void short_read(void)
{
    const char *path = "/sys/devices/system/cpu/online";
    struct stat sb;
    if (stat(path, &sb) != 0 || !S_ISREG(sb.st_mode) || sb.st_size < 64)
        return check_skip("short read", "no sysfs file that reports more bytes than it holds");
    char err[512];
    char *text = NULL;
    const char *words[] = {path, "short read", "of the 4096 bytes", NULL};
    expect("a file shorter than its size", soak_input_read(path, SOAK_INPUT_SCENE, &text, NULL, err, sizeof err),
           SOAK_ERR_IO, err, words);
}

int main(void)
{
    if (!mkdtemp(dir)) {
        check_skip("input policy", "cannot make a folder in /tmp");
        return check_finish();
    }
    refuses_what_is_not_a_file();
    caps_and_content();
    grows_while_read();
    short_read();
    out_of_memory();
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
    return check_finish();
}
