/* stderr_capture.h */
#define _GNU_SOURCE
#include "stderr_capture.h"

#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#define CAPTURE_KEEP 65536 /* bytes scanned for sanitizer reports */

void soak_stderr_capture_begin(soak_stderr_capture *c)
{
    c->saved = c->file = -1;
    fflush(stderr);
    int file = memfd_create("soak-library-stderr", MFD_CLOEXEC);
    if (file < 0) return;
    int saved = dup(STDERR_FILENO);
    if (saved < 0 || dup2(file, STDERR_FILENO) < 0) {
        if (saved >= 0) close(saved);
        close(file);
        return;
    }
    c->saved = saved;
    c->file = file;
}

/* Writes the captured text back when a sanitizer reported something. */
static void pass_sanitizer_reports(int file)
{
    static const char *const marks[] = {"Sanitizer", "runtime error:"};
    char buf[CAPTURE_KEEP + 1];
    ssize_t n = pread(file, buf, CAPTURE_KEEP, 0);
    if (n <= 0) return;
    buf[n] = '\0';
    for (size_t i = 0; i < sizeof marks / sizeof marks[0]; ++i)
        if (memmem(buf, (size_t)n, marks[i], strlen(marks[i]))) {
            ssize_t w = write(STDERR_FILENO, buf, (size_t)n);
            (void)w;
            return;
        }
}

void soak_stderr_capture_end(soak_stderr_capture *c)
{
    if (c->saved < 0) return;
    fflush(stderr);
    dup2(c->saved, STDERR_FILENO);
    close(c->saved);
    pass_sanitizer_reports(c->file);
    close(c->file);
    c->saved = c->file = -1;
}
