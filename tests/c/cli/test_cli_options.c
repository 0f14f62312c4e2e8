/* The CLI's option tables (c_core/cli/options.c): every kind of option read
 * from argv into its field, and every error printed as the commands print
 * it (the texts are the ones tests/cli greps for), each case against values
 * and messages written out by hand here; and the options part of --help. */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "cli.h"

typedef struct t_opts {
    double d;
    int i, flag, mode, even, listed, seen_d;
    uint64_t seed;
    long long paths;
    long size, dims[3];
    const char *name;
    soak_rgb rgb;
    const char *pos[2];
    int n_pos;
} t_opts;

static int read_even(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    long v;
    if (!cli_parse_int(cmd, o->name, text, 0, 100, &v)) return 0;
    if (v % 2) {
        cli_error(cmd, "%s: %ld is odd", o->name, v);
        return 0;
    }
    ((t_opts *)dst)->even = (int)v;
    return 1;
}

static int run_list(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    (void)cmd, (void)o, (void)text;
    ((t_opts *)dst)->listed = 1;
    return CLI_OPT_STOP;
}

static const cli_choice modes[] = {{"a", 1, 0}, {"b", 2, 0}, {"B", 2, 1}, {"c", 3, 0}, {NULL, 0, 0}};

#define F(field) CLI_FIELD(t_opts, field)
static const cli_opt table[] = {
    {"--d", NULL, CLI_OPT_DOUBLE, .lo = 0.5, .hi = 2, F(d), CLI_SEEN(t_opts, seen_d), .meta = "D",
     .help = "a number, %R"},
    {"--i", NULL, CLI_OPT_INT, .ilo = -3, .ihi = 7, F(i), .meta = "N", .help = "whole, %R"},
    {"--seed", NULL, CLI_OPT_INT, .ilo = 0, .ihi = INT64_MAX, F(seed), .meta = "S", .help = "into a uint64_t"},
    {"--paths", NULL, CLI_OPT_INT, .ilo = 1, .ihi = 1000000000000L, F(paths), .meta = "N", .help = "into a long long"},
    {"--size", NULL, CLI_OPT_SIZE, .ihi = 100, F(size), .meta = "N", .help = "%R"},
    {"--name", "-n", CLI_OPT_STRING, F(name), .meta = "NAME", .help = "a string\non two lines"},
    {"--flag", NULL, CLI_OPT_FLAG, .flag = 5, F(flag), .help = "stores 5"},
    {"--rgb", NULL, CLI_OPT_RGB, .lo = 0, .hi = 1, F(rgb), .meta = "V|R,G,B", .help = "colour"},
    {"--dims", NULL, CLI_OPT_DIMS, .ihi = 10, .hi = 100, F(dims), .meta = "NX,NY,NZ", .help = "voxels"},
    {"(heading:)", NULL, CLI_OPT_HEADING, .help = "choices:"},
    {"--mode", NULL, CLI_OPT_CHOICE, .choices = modes, F(mode), .meta = "a|b|c", .help = "one of three"},
    {"--even", NULL, CLI_OPT_CUSTOM, .parse = read_even, .meta = "N", .help = "an even number"},
    {"--list", NULL, CLI_OPT_ACTION, .parse = run_list, .help = "stops"},
    {"--old", NULL, CLI_OPT_REJECT, .help = "does not apply here"},
    {"--hidden", NULL, CLI_OPT_FLAG, .flag = 1, F(listed)},
    {"--bad", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(i)}, /* a table that does not match its struct */
    {"--a-very-long-option-name", NULL, CLI_OPT_FLAG, .flag = 1, F(listed), .help = "its help goes below"},
};
#undef F

static void usage(FILE *out) { fprintf(out, "usage: t [options]\n"); }

static int positional(void *ctx, const char *arg)
{
    t_opts *o = ctx;
    if (o->n_pos == 2) {
        cli_error("t", "unexpected argument '%s': two at most", arg);
        return 0;
    }
    o->pos[o->n_pos++] = arg;
    return 1;
}

/* Runs the parser on the words of line with stdout and stderr caught; the
 * strings read point into words. */
typedef struct words {
    char text[512];
} words;

static int parse_line(const char *line, words *w, t_opts *o, char *out, char *err, size_t len)
{
    char *buf = w->text, *argv[32];
    int argc = 0;
    snprintf(buf, sizeof w->text, "t %s", line);
    for (char *w = strtok(buf, " "); w && argc < 32; w = strtok(NULL, " ")) argv[argc++] = w;
    memset(o, 0, sizeof *o);
    cli_spec spec = {"t", "option", "t --help", usage, positional, o};
    cli_opt_table tables[] = {CLI_TABLE(table, o)};
    FILE *fo = tmpfile(), *fe = tmpfile();
    fflush(stdout), fflush(stderr);
    int so = dup(1), se = dup(2);
    dup2(fileno(fo), 1), dup2(fileno(fe), 2);
    int rc = cli_opts_parse(&spec, tables, 1, argc, argv);
    fflush(stdout), fflush(stderr);
    dup2(so, 1), dup2(se, 2);
    close(so), close(se);
    rewind(fo), rewind(fe);
    out[fread(out, 1, len - 1, fo)] = '\0';
    err[fread(err, 1, len - 1, fe)] = '\0';
    fclose(fo), fclose(fe);
    return rc;
}

typedef struct value_case {
    const char *argv;
    t_opts want; /* every field; the parser starts from zeros */
} value_case;

static const value_case values[] = {
    {"--d 1.5", {.d = 1.5, .seen_d = 1}},
    {"--d=1.25", {.d = 1.25, .seen_d = 1}},
    {"--d 1 --d 0.5", {.d = 0.5, .seen_d = 1}},
    {"--i -3 --i=7", {.i = 7}},
    {"--seed 9223372036854775807", {.seed = UINT64_C(9223372036854775807)}},
    {"--paths 1000000000000", {.paths = 1000000000000LL}},
    {"--size 100", {.size = 100}},
    {"-n foo", {.name = "foo"}},
    {"--name=bar", {.name = "bar"}},
    {"-n=baz", {.name = "baz"}},
    {"--flag", {.flag = 5}},
    {"--rgb 0.25", {.rgb = {0.25, 0.25, 0.25}}},
    {"--rgb=0.1,0.2,0.3", {.rgb = {0.1, 0.2, 0.3}}},
    {"--dims 2,3,4", {.dims = {2, 3, 4}}},
    {"--mode b", {.mode = 2}},
    {"--mode=B", {.mode = 2}},
    {"--mode c", {.mode = 3}},
    {"--even 4", {.even = 4}},
    {"--hidden", {.listed = 1}},
    {"one -", {.pos = {"one", "-"}, .n_pos = 2}},
    {"one --d 2", {.d = 2, .seen_d = 1, .pos = {"one"}, .n_pos = 1}},
};

static int same_text(const char *a, const char *b) { return (!a && !b) || (a && b && strcmp(a, b) == 0); }

static int same(const t_opts *a, const t_opts *b)
{
    return a->d == b->d && a->i == b->i && a->flag == b->flag && a->mode == b->mode && a->even == b->even &&
           a->listed == b->listed && a->seen_d == b->seen_d && a->seed == b->seed && a->paths == b->paths &&
           a->size == b->size && a->dims[0] == b->dims[0] && a->dims[1] == b->dims[1] && a->dims[2] == b->dims[2] &&
           same_text(a->name, b->name) && a->rgb.r == b->rgb.r && a->rgb.g == b->rgb.g && a->rgb.b == b->rgb.b &&
           a->n_pos == b->n_pos && same_text(a->pos[0], b->pos[0]) && same_text(a->pos[1], b->pos[1]);
}

static void test_values(void)
{
    char out[1024], err[1024], what[2400];
    words w;
    for (size_t k = 0; k < sizeof values / sizeof values[0]; ++k) {
        t_opts o;
        int rc = parse_line(values[k].argv, &w, &o, out, err, sizeof out);
        snprintf(what, sizeof what, "'%s' is read (rc %d, stderr '%s')", values[k].argv, rc, err);
        check_true(what, rc == -1 && err[0] == '\0' && out[0] == '\0');
        snprintf(what, sizeof what, "'%s' gives the values written out", values[k].argv);
        check_true(what, same(&o, &values[k].want));
    }
}

typedef struct error_case {
    const char *argv;
    int rc;
    const char *err; /* the whole of stderr */
} error_case;

static const error_case errors[] = {
    {"--d nan", 2, "soak t: --d: expected a number in [0.5, 2], got 'nan'\n"},
    {"--d inf", 2, "soak t: --d: expected a number in [0.5, 2], got 'inf'\n"},
    {"--d 2.0001", 2, "soak t: --d: expected a number in [0.5, 2], got '2.0001'\n"},
    {"--d 0.4999", 2, "soak t: --d: expected a number in [0.5, 2], got '0.4999'\n"},
    {"--d=", 2, "soak t: --d: expected a number in [0.5, 2], got ''\n"},
    {"--d 1x", 2, "soak t: --d: expected a number in [0.5, 2], got '1x'\n"},
    {"--d", 2, "soak t: option --d needs a value\n"},
    {"--i 1 --d", 2, "soak t: option --d needs a value\n"},
    {"--i -4", 2, "soak t: --i: expected a whole number in [-3, 7], got '-4'\n"},
    {"--i 8", 2, "soak t: --i: expected a whole number in [-3, 7], got '8'\n"},
    {"--i=2.5", 2, "soak t: --i: expected a whole number in [-3, 7], got '2.5'\n"},
    {"--seed -1", 2, "soak t: --seed: expected a whole number in [0, 9223372036854775807], got '-1'\n"},
    {"--paths 0", 2, "soak t: --paths: expected a whole number in [1, 1000000000000], got '0'\n"},
    {"--size 0", 2, "soak t: --size: expected a size from 1 to 100, got '0'\n"},
    {"--size 101", 2, "soak t: --size: expected a size from 1 to 100, got '101'\n"},
    {"--rgb 1,2", 2, "soak t: --rgb: expected V or R,G,B, got '1,2'\n"},
    {"--rgb 0.5,nan,0", 2, "soak t: --rgb: expected a number in [0, 1], got 'nan'\n"},
    {"--dims 1,1", 2, "soak t: --dims: expected three sizes NX,NY,NZ, got '1,1'\n"},
    {"--dims 11,1,1", 2, "soak t: --dims: expected a size from 1 to 10, got '11' in '11,1,1'\n"},
    {"--dims 10,10,2", 2, "soak t: --dims: '10,10,2' is 200 voxels; the limit is 100\n"},
    {"--mode x", 2, "soak t: --mode: expected a, b or c, got 'x'\n"},
    {"--even 3", 2, "soak t: --even: 3 is odd\n"},
    {"--even 102", 2, "soak t: --even: expected a whole number in [0, 100], got '102'\n"},
    {"--bogus", 2, "soak t: unknown option '--bogus' (see t --help)\n"},
    {"-x", 2, "soak t: unknown option '-x' (see t --help)\n"},
    {"--flag=1", 2, "soak t: unknown option '--flag=1' (see t --help)\n"},
    {"--dd 1", 2, "soak t: unknown option '--dd' (see t --help)\n"},
    {"--old=3", 2, "soak t: option --old=3 does not apply here\n"},
    {"--bad 0.5", 2, "soak t: --bad: internal error: its table gives a field of 4 bytes\n"},
    {"a b c", 2, "soak t: unexpected argument 'c': two at most\n"},
    {"--d 1 --bogus --d 3", 2, "soak t: unknown option '--bogus' (see t --help)\n"},
    {"--list --bogus", 0, ""},
    {"--bogus --help", 2, "soak t: unknown option '--bogus' (see t --help)\n"},
    {"--d 1 -h --bogus", 0, ""},
};

static void test_errors(void)
{
    char out[1024], err[1024], what[2600];
    words w;
    for (size_t k = 0; k < sizeof errors / sizeof errors[0]; ++k) {
        t_opts o;
        int rc = parse_line(errors[k].argv, &w, &o, out, err, sizeof out);
        snprintf(what, sizeof what, "'%s': exit %d (want %d), stderr '%s' (want '%s')", errors[k].argv, rc,
                 errors[k].rc, err, errors[k].err);
        check_true(what, rc == errors[k].rc && strcmp(err, errors[k].err) == 0);
    }
    t_opts o;
    parse_line("--d 1 -h --bogus", &w, &o, out, err, sizeof out);
    check_true("-h prints the usage on stdout", strcmp(out, "usage: t [options]\n") == 0);
    parse_line("--list --d 1", &w, &o, out, err, sizeof out);
    check_true("an action stops the reading", o.listed == 1 && o.seen_d == 0);
    parse_line("--d 1 --bogus --i 3", &w, &o, out, err, sizeof out);
    check_true("nothing after an error is read", o.d == 1 && o.i == 0);
}

static const char help_text[] =
    "  --d D               a number, 0.5..2\n"
    "  --i N               whole, -3..7\n"
    "  --seed S            into a uint64_t\n"
    "  --paths N           into a long long\n"
    "  --size N            1..100\n"
    "  -n, --name NAME     a string\n"
    "                      on two lines\n"
    "  --flag              stores 5\n"
    "  --rgb V|R,G,B       colour\n"
    "  --dims NX,NY,NZ     voxels\n"
    "choices:\n"
    "  --mode a|b|c        one of three\n"
    "  --even N            an even number\n"
    "  --list              stops\n"
    "  --a-very-long-option-name\n"
    "                      its help goes below\n";

static void test_help(void)
{
    char text[4096];
    cli_opt_table tables[] = {CLI_TABLE(table, NULL)};
    FILE *f = tmpfile();
    cli_opts_help(f, tables, 1);
    rewind(f);
    text[fread(text, 1, sizeof text - 1, f)] = '\0';
    fclose(f);
    int ok = strcmp(text, help_text) == 0;
    if (!ok) printf("--help printed:\n%s--- want:\n%s", text, help_text);
    check_true("--help lists the options from the table (ranges, columns, headings; rejected and hidden left out)", ok);
}

int main(void)
{
    test_values();
    test_errors();
    test_help();
    return check_finish();
}
