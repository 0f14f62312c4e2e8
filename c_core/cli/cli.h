/* Shared pieces of the `soak` command-line tool. Each subcommand lives in
 * its own cmd_<name>.c and is listed in main.c's table. Every subcommand:
 *  - prints usage with an example on --help / -h and exits 0;
 *  - names the offending argument in every error and exits 2 for bad usage,
 *    1 for failures while working;
 *  - reports progress on stderr for long work, results on stdout. */
#ifndef SOAK_CLI_H
#define SOAK_CLI_H

#include <stddef.h>
#include <stdio.h>

#include "soak/vec.h"

typedef struct soak_cli_command {
    const char *name;
    const char *summary;
    int (*run)(int argc, char **argv); /* argv[0] is the subcommand name */
} soak_cli_command;

#define SOAK_EXIT_OK 0
#define SOAK_EXIT_FAIL 1
#define SOAK_EXIT_USAGE 2

int soak_cmd_materials(int argc, char **argv);
int soak_cmd_albedo(int argc, char **argv);
int soak_cmd_eval(int argc, char **argv);
int soak_cmd_demo(int argc, char **argv);
int soak_cmd_render(int argc, char **argv);
int soak_cmd_measure(int argc, char **argv);
int soak_cmd_bake(int argc, char **argv);
int soak_cmd_export(int argc, char **argv);
int soak_cmd_report(int argc, char **argv);
int soak_cmd_advise(int argc, char **argv);

struct soak_advice;
/* The table of `soak advise` (also printed by `soak render --auto-model`). */
void cli_advise_print(FILE *f, const struct soak_advice *a, int n, double tol);

/* Prints "soak <cmd>: <message>" to stderr. */
void cli_error(const char *cmd, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Parses a finite number in [lo, hi]. On failure prints an error naming the
 * option and the accepted range, returns 0. */
int cli_parse_double(const char *cmd, const char *opt, const char *text, double lo, double hi, double *out);
int cli_parse_int(const char *cmd, const char *opt, const char *text, long lo, long hi, long *out);

/* Sizes: every --width, --height, render size and --dims goes through these
 * two, with one message style naming the option and the value:
 *   "soak CMD: OPT: expected a size from 1 to MAX, got 'TEXT'". */
#define CLI_MAX_IMAGE_SIDE 16384 /* pixels per side of any image a command makes (= SOAK_BAKE_MAX_SIZE) */
int cli_parse_size(const char *cmd, const char *opt, const char *text, long max, long *out);
/* "NX,NY,NZ", each a size from 1 to max_each, at most max_total in all. */
int cli_parse_dims(const char *cmd, const char *opt, const char *text, long max_each, double max_total, long out[3]);

/* Splits text at commas into at most max parts of buf; returns the count,
 * or max + 1 when there are more. */
int cli_split_commas(const char *text, char *buf, size_t len, char **parts, int max);

/* "V" or "R,G,B", each in [lo, hi]; on failure prints an error naming the
 * option and returns 0. */
int cli_parse_rgb(const char *cmd, const char *opt, const char *text, double lo, double hi, soak_rgb *out);

/* Returns the value following option argv[*i] (advancing *i), or NULL after
 * printing "option X needs a value". Accepts "--opt=value" too. */
const char *cli_value(const char *cmd, int argc, char **argv, int *i);

/* 1 if argv[i] is opt or starts with "opt=". */
int cli_is(const char *arg, const char *opt);

/* Start of a dispatcher (soak, soak bake): with no argument prints usage on
 * stderr and returns SOAK_EXIT_USAGE; for --help, -h or help prints it on
 * stdout and returns SOAK_EXIT_OK; otherwise returns -1 (dispatch argv[1]). */
int cli_dispatch_help(int argc, char **argv, void (*usage)(FILE *out));
/* The entry of table named name, or NULL. */
const soak_cli_command *cli_find(const soak_cli_command *table, int n, const char *name);

/* Simple progress bar on stderr: "label [#####     ] 42% ETA 3s". Quiet when
 * stderr is not a terminal unless force is set by SOAK_PROGRESS=1. */
typedef struct cli_progress {
    const char *label;
    double total;
    double start_time;
    double last_print;
    int enabled;
} cli_progress;
void cli_progress_start(cli_progress *p, const char *label, double total);
void cli_progress_update(cli_progress *p, double done);
void cli_progress_finish(cli_progress *p);
double cli_now(void);

#endif
