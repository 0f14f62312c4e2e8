/* Only soak speaks (issue 35): what a library writes to stderr while soak
 * calls it (libpng's "libpng error: ..." and "PNG read error" lines around
 * soak's own message) goes to a memory file and is dropped; the library's
 * error reaches the user through soak's message. Sanitizer reports are
 * written through. stderr is process-wide: captures take turns (a mutex),
 * and what another thread writes meanwhile is captured too (soak reads
 * images before a command's parallel work). */
#ifndef SOAK_STDERR_CAPTURE_H
#define SOAK_STDERR_CAPTURE_H

typedef struct soak_stderr_capture {
    int saved; /* the original stderr, -1 when nothing is captured */
    int file;  /* the memory file stderr points to meanwhile */
} soak_stderr_capture;

/* Starts capturing; on any failure stderr is left as it is. */
void soak_stderr_capture_begin(soak_stderr_capture *c);
/* Restores stderr and drops what was captured (but sanitizer reports). */
void soak_stderr_capture_end(soak_stderr_capture *c);

#endif
