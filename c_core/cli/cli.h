/* Shared pieces of the `soak` command-line tool. Each subcommand lives in
 * its own cmd_<name>.c (the bake kinds in bake_<kind>_cli.c), is listed in
 * main.c's table and reads its options through a table (below). Every
 * subcommand:
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

/* The smallest tolerance of soak advise --tol and soak render --auto-model:
 * the library takes any tol in (0, SOAK_ADVISE_MAX_TOL]. */
#define CLI_ADVISE_MIN_TOL 1e-9
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

/* ---- Option tables (options.c) ----
 * Each command declares its options once, in a static const table: name,
 * kind, range (from the library's #defines), where the value goes in the
 * command's options struct, a placeholder and a help line. cli_opts_parse
 * reads argv against the tables and cli_opts_help prints the options part of
 * --help from the same tables, so a range or a name has one home. */
typedef enum cli_opt_kind {
    CLI_OPT_FLAG,    /* no value: stores .flag in an int (exact name only) */
    CLI_OPT_STRING,  /* const char *: the argument text */
    CLI_OPT_DOUBLE,  /* finite, in [lo, hi] (cli_parse_double) */
    CLI_OPT_INT,     /* whole number in [ilo, ihi] (cli_parse_int); an int or 64-bit field */
    CLI_OPT_SIZE,    /* 1..ihi (cli_parse_size); an int or 64-bit field */
    CLI_OPT_RGB,     /* V or R,G,B, each in [lo, hi] (cli_parse_rgb): a soak_rgb */
    CLI_OPT_DIMS,    /* NX,NY,NZ, each 1..ihi, at most hi in all (cli_parse_dims): long[3] */
    CLI_OPT_CHOICE,  /* one of .choices: stores its value in an int */
    CLI_OPT_CUSTOM,  /* .parse reads the value into the whole options struct */
    CLI_OPT_ACTION,  /* no value: .parse runs at once (exact name only) */
    CLI_OPT_REJECT,  /* an option of other commands: "option ARG <help>", exit 2 */
    CLI_OPT_HEADING, /* --help only: a section title printed as is */
} cli_opt_kind;

typedef struct cli_choice {
    const char *name;
    int value;
    int alias; /* 1: accepted, but left out of the "expected ..." list */
} cli_choice;

typedef struct cli_opt cli_opt;
/* What a CLI_OPT_CUSTOM or CLI_OPT_ACTION reader returns besides 1 (read) and 0 (error printed):
 * stop reading argv and exit 0 (an option that does its work at once). */
#define CLI_OPT_STOP 2
typedef int (*cli_opt_reader)(const char *cmd, const cli_opt *opt, const char *text, void *dst);

struct cli_opt {
    const char *name;  /* "--spp" */
    const char *alias; /* "-o", or NULL */
    cli_opt_kind kind;
    double lo, hi;     /* DOUBLE, RGB; hi: the DIMS total */
    long ilo, ihi;     /* INT; ihi: the SIZE and DIMS maximum */
    size_t offset, size; /* the value's field in the options struct: CLI_FIELD */
    size_t seen;       /* CLI_SEEN: an int set to 1 when the option is given; 0: none */
    int flag;          /* FLAG: the value stored */
    const cli_choice *choices; /* CHOICE: ends with {NULL} */
    cli_opt_reader parse;      /* CUSTOM, ACTION (text NULL) */
    const char *meta;  /* the value's placeholder in --help ("N", "FILE") */
    const char *help;  /* --help text; "\n" goes on at the help column, "%R"
                          prints the range; NULL: not listed */
};

#define CLI_FIELD(type, field) .offset = offsetof(type, field), .size = sizeof(((type *)0)->field)
#define CLI_SEEN(type, field) .seen = offsetof(type, field) + 1

/* The options of one struct: dst is where their values go (NULL for help). */
typedef struct cli_opt_table {
    const cli_opt *opts;
    size_t n;
    void *dst;
} cli_opt_table;
#define CLI_TABLE(opts, dst) {(opts), sizeof(opts) / sizeof((opts)[0]), (dst)}

typedef struct cli_spec {
    const char *cmd;          /* for messages: "render", "bake rain" */
    const char *unknown;      /* "option" or "argument": "unknown option '-x'" */
    const char *see;          /* "(see <see>)" after an unknown option */
    void (*usage)(FILE *out); /* printed on stdout by -h / --help */
    /* Arguments that are not options ("-" included); returns 1, or 0 after
     * printing an error. NULL: every argument must be an option. */
    int (*positional)(void *ctx, const char *arg);
    void *ctx;
} cli_spec;

/* Reads argv[1..argc-1] against the tables, left to right (the last of a
 * repeated option wins); "--opt value" and "--opt=value" alike. Returns -1
 * when every argument was read, SOAK_EXIT_OK after --help (or a CLI_OPT_STOP
 * option), SOAK_EXIT_USAGE after printing an error naming the argument. */
int cli_opts_parse(const cli_spec *spec, const cli_opt_table *tables, int n_tables, int argc, char **argv);

/* The options part of --help: one entry per listed option, help texts
 * aligned on one column over all the tables. */
void cli_opts_help(FILE *out, const cli_opt_table *tables, int n_tables);

/* The manual page (man(7) source, `soak --man`), from the same texts and
 * tables as --help: cli_opts_parse answers --man with cli_man_command (a
 * subsection "soak CMD": the usage text, each option a tagged paragraph);
 * a dispatcher prints its usage (cli_man_usage, under title unless NULL),
 * then runs each entry of its table with --man (cli_man_commands). */
void cli_man_command(FILE *out, const cli_spec *spec, const cli_opt_table *tables, int n_tables);
void cli_man_usage(FILE *out, const char *title, void (*usage)(FILE *out));
int cli_man_commands(const soak_cli_command *table, int n);

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

/* Every environment variable soak reads, parsed like an option (env_check.c):
 * 0, or SOAK_EXIT_USAGE after naming the variable and its valid range. */
int cli_check_environment(void);
/* The variables, their ranges and meaning, for --help. */
void cli_environment_help(FILE *out);

#endif
