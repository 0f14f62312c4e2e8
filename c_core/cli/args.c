#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "soak/bake.h"
#include "soak/status.h"

_Static_assert(CLI_MAX_IMAGE_SIDE == SOAK_BAKE_MAX_SIZE, "one limit for every image side");

void cli_error(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "soak %s: ", cmd);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

int cli_parse_double(const char *cmd, const char *opt, const char *text, double lo, double hi, double *out)
{
    char *end = NULL;
    errno = 0;
    double v = text ? strtod(text, &end) : 0.0;
    if (!text || end == text || *end != '\0' || errno == ERANGE || !soak_in_range(v, lo, hi)) {
        cli_error(cmd, "%s: expected a number in [%g, %g], got '%s'", opt, lo, hi, text ? text : "");
        return 0;
    }
    *out = v;
    return 1;
}

int cli_parse_int(const char *cmd, const char *opt, const char *text, long lo, long hi, long *out)
{
    char *end = NULL;
    errno = 0;
    long v = text ? strtol(text, &end, 10) : 0;
    if (!text || end == text || *end != '\0' || errno == ERANGE || v < lo || v > hi) {
        cli_error(cmd, "%s: expected a whole number in [%ld, %ld], got '%s'", opt, lo, hi, text ? text : "");
        return 0;
    }
    *out = v;
    return 1;
}

int cli_parse_size(const char *cmd, const char *opt, const char *text, long max, long *out)
{
    char *end = NULL;
    errno = 0;
    long v = text ? strtol(text, &end, 10) : 0;
    if (!text || end == text || *end != '\0' || errno == ERANGE || v < 1 || v > max) {
        cli_error(cmd, "%s: expected a size from 1 to %ld, got '%s'", opt, max, text ? text : "");
        return 0;
    }
    *out = v;
    return 1;
}

int cli_parse_dims(const char *cmd, const char *opt, const char *text, long max_each, double max_total, long out[3])
{
    char buf[256], *parts[3];
    if (cli_split_commas(text, buf, sizeof buf, parts, 3) != 3) {
        cli_error(cmd, "%s: expected three sizes NX,NY,NZ, got '%s'", opt, text);
        return 0;
    }
    for (int k = 0; k < 3; ++k) {
        char *end = NULL;
        errno = 0;
        long v = strtol(parts[k], &end, 10);
        if (end == parts[k] || *end != '\0' || errno == ERANGE || v < 1 || v > max_each) {
            cli_error(cmd, "%s: expected a size from 1 to %ld, got '%s' in '%s'", opt, max_each, parts[k], text);
            return 0;
        }
        out[k] = v;
    }
    double total = (double)out[0] * (double)out[1] * (double)out[2];
    if (total > max_total) {
        cli_error(cmd, "%s: '%s' is %.0f voxels; the limit is %.0f", opt, text, total, max_total);
        return 0;
    }
    return 1;
}

int cli_is(const char *arg, const char *opt)
{
    size_t n = strlen(opt);
    return strncmp(arg, opt, n) == 0 && (arg[n] == '\0' || arg[n] == '=');
}

int cli_dispatch_help(int argc, char **argv, void (*usage)(FILE *out))
{
    if (argc < 2) {
        usage(stderr);
        return SOAK_EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return SOAK_EXIT_OK;
    }
    return -1;
}

int cli_man_commands(const soak_cli_command *table, int n)
{
    int rc = SOAK_EXIT_OK;
    for (int i = 0; i < n; ++i) {
        char name[64], man[] = "--man";
        snprintf(name, sizeof name, "%s", table[i].name);
        char *argv[] = {name, man, NULL};
        int r = table[i].run(2, argv);
        if (r != SOAK_EXIT_OK) rc = r;
    }
    return rc;
}

const soak_cli_command *cli_find(const soak_cli_command *table, int n, const char *name)
{
    for (int i = 0; i < n; ++i)
        if (strcmp(name, table[i].name) == 0) return &table[i];
    return NULL;
}

const char *cli_value(const char *cmd, int argc, char **argv, int *i)
{
    const char *eq = strchr(argv[*i], '=');
    if (eq && argv[*i][0] == '-') return eq + 1;
    if (*i + 1 >= argc) {
        cli_error(cmd, "option %s needs a value", argv[*i]);
        return NULL;
    }
    ++*i;
    return argv[*i];
}

double cli_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void cli_progress_start(cli_progress *p, const char *label, double total)
{
    const char *force = getenv("SOAK_PROGRESS");
    p->label = label;
    p->total = total > 0 ? total : 1;
    p->start_time = cli_now();
    p->last_print = 0;
    p->enabled = isatty(STDERR_FILENO) || (force && strcmp(force, "1") == 0);
}

void cli_progress_update(cli_progress *p, double done)
{
    if (!p->enabled) return;
    double now = cli_now();
    if (now - p->last_print < 0.2 && done < p->total) return;
    p->last_print = now;
    double frac = done / p->total;
    if (frac > 1) frac = 1;
    double elapsed = now - p->start_time;
    double eta = frac > 0 ? elapsed * (1 - frac) / frac : 0;
    char bar[31];
    int fill = (int)(frac * 30);
    for (int i = 0; i < 30; ++i) bar[i] = i < fill ? '#' : ' ';
    bar[30] = '\0';
    fprintf(stderr, "\r%s [%s] %3.0f%% %.1fs ETA %.1fs ", p->label, bar, 100 * frac, elapsed, eta);
    fflush(stderr);
}

void cli_progress_finish(cli_progress *p)
{
    if (!p->enabled) return;
    cli_progress_update(p, p->total);
    fputc('\n', stderr);
}

int cli_split_commas(const char *text, char *buf, size_t len, char **parts, int max)
{
    snprintf(buf, len, "%s", text);
    int n = 0;
    for (char *p = buf;;) {
        if (n == max) return max + 1;
        parts[n++] = p;
        char *comma = strchr(p, ',');
        if (!comma) break;
        *comma = '\0';
        p = comma + 1;
    }
    return n;
}

int cli_parse_rgb(const char *cmd, const char *opt, const char *text, double lo, double hi, soak_rgb *out)
{
    char buf[256], *parts[3];
    int n = cli_split_commas(text, buf, sizeof buf, parts, 3);
    if (n != 1 && n != 3) {
        cli_error(cmd, "%s: expected V or R,G,B, got '%s'", opt, text);
        return 0;
    }
    double v[3];
    for (int i = 0; i < n; ++i)
        if (!cli_parse_double(cmd, opt, parts[i], lo, hi, &v[i])) return 0;
    if (n == 1) v[1] = v[2] = v[0];
    *out = soak_rgb3(v[0], v[1], v[2]);
    return 1;
}
