/* stderr_capture.h */
#define _GNU_SOURCE
#include "stderr_capture.h"

#include <pthread.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#define CAPTURE_KEEP 65536 /* bytes scanned for sanitizer reports */

/* stderr is one per process: captures from several threads take turns (a
 * second begin would save the first one's memory file as "the original"). */
static pthread_mutex_t capture_turn = PTHREAD_MUTEX_INITIALIZER;

void soak_stderr_capture_begin(soak_stderr_capture *c)
{
    c->saved = c->file = -1;
    pthread_mutex_lock(&capture_turn);
    fflush(stderr);
    int file = memfd_create("soak-library-stderr", MFD_CLOEXEC);
    int saved = file >= 0 ? dup(STDERR_FILENO) : -1;
    if (saved < 0 || dup2(file, STDERR_FILENO) < 0) {
        if (saved >= 0) close(saved);
        if (file >= 0) close(file);
        pthread_mutex_unlock(&capture_turn);
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
    pthread_mutex_unlock(&capture_turn);
}
