/* The option tables of cli.h: one reader of argv and one printer of the
 * options part of --help (and of the manual page, --man) for every command. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

static int is_help(const char *arg) { return strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0; }

/* Options without a value match their exact name; the others "--name" and
 * "--name=value" (cli_is). */
static int matches(const cli_opt *o, const char *arg)
{
    switch (o->kind) {
    case CLI_OPT_HEADING:
        return 0;
    case CLI_OPT_FLAG:
    case CLI_OPT_ACTION:
        return strcmp(arg, o->name) == 0 || (o->alias && strcmp(arg, o->alias) == 0);
    default:
        return cli_is(arg, o->name) || (o->alias && cli_is(arg, o->alias));
    }
}

static const cli_opt *find(const cli_opt_table *tables, int n_tables, const char *arg, void **dst)
{
    for (int t = 0; t < n_tables; ++t)
        for (size_t k = 0; k < tables[t].n; ++k)
            if (matches(&tables[t].opts[k], arg)) {
                *dst = tables[t].dst;
                return &tables[t].opts[k];
            }
    return NULL;
}

static void *field_of(void *dst, const cli_opt *o) { return (char *)dst + o->offset; }

/* A table that does not match its struct: a bug of the command, named. */
static int bad_field(const char *cmd, const cli_opt *o)
{
    cli_error(cmd, "%s: internal error: its table gives a field of %zu bytes", o->name, o->size);
    return 0;
}

/* Whole numbers go into int or 64-bit fields (int, long, long long, or
 * uint64_t with a range from 0); memcpy keeps the types apart. */
_Static_assert(sizeof(long) == sizeof(int64_t), "64-bit fields are filled from a long");
static int store_whole(const char *cmd, const cli_opt *o, void *dst, long v)
{
    if (o->size == sizeof(int) && v >= INT_MIN && v <= INT_MAX) {
        int i = (int)v;
        memcpy(field_of(dst, o), &i, sizeof i);
        return 1;
    }
    if (o->size == sizeof(long)) {
        memcpy(field_of(dst, o), &v, sizeof v);
        return 1;
    }
    return bad_field(cmd, o);
}

/* "A, B or C" of the choices that are not aliases. */
static void choice_list(const cli_choice *c, char *buf, size_t len)
{
    int n = 0;
    for (const cli_choice *p = c; p->name; ++p) n += !p->alias;
    size_t used = 0;
    buf[0] = '\0';
    for (int k = 0; c->name; ++c) {
        if (c->alias) continue;
        const char *sep = k == 0 ? "" : (k == n - 1 ? " or " : ", ");
        int w = snprintf(buf + used, len - used, "%s%s", sep, c->name);
        if (w < 0 || (size_t)w >= len - used) return;
        used += (size_t)w;
        ++k;
    }
}

static int read_choice(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    for (const cli_choice *c = o->choices; c->name; ++c)
        if (strcmp(text, c->name) == 0) return store_whole(cmd, o, dst, c->value);
    char list[512];
    choice_list(o->choices, list, sizeof list);
    cli_error(cmd, "%s: expected %s, got '%s'", o->name, list, text);
    return 0;
}

/* 1 read, 0 after an error, CLI_OPT_STOP. */
static int read_value(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    long v = 0;
    switch (o->kind) {
    case CLI_OPT_STRING:
        if (o->size != sizeof text) break;
        memcpy(field_of(dst, o), &text, sizeof text);
        return 1;
    case CLI_OPT_DOUBLE:
        if (o->size != sizeof(double)) break;
        return cli_parse_double(cmd, o->name, text, o->lo, o->hi, (double *)field_of(dst, o));
    case CLI_OPT_INT:
        return cli_parse_int(cmd, o->name, text, o->ilo, o->ihi, &v) && store_whole(cmd, o, dst, v);
    case CLI_OPT_SIZE:
        return cli_parse_size(cmd, o->name, text, o->ihi, &v) && store_whole(cmd, o, dst, v);
    case CLI_OPT_RGB:
        if (o->size != sizeof(soak_rgb)) break;
        return cli_parse_rgb(cmd, o->name, text, o->lo, o->hi, (soak_rgb *)field_of(dst, o));
    case CLI_OPT_DIMS:
        if (o->size != 3 * sizeof(long)) break;
        return cli_parse_dims(cmd, o->name, text, o->ihi, o->hi, (long *)field_of(dst, o));
    case CLI_OPT_CHOICE:
        return read_choice(cmd, o, text, dst);
    case CLI_OPT_CUSTOM:
        return o->parse(cmd, o, text, dst);
    default:
        break;
    }
    return bad_field(cmd, o);
}

/* One argument of argv at *i: 1 read, 0 after an error, CLI_OPT_STOP. */
static int read_option(const cli_spec *spec, const cli_opt *o, void *dst, int argc, char **argv, int *i)
{
    const char *text = NULL;
    int r;
    if (o->kind == CLI_OPT_REJECT) {
        cli_error(spec->cmd, "option %s %s", argv[*i], o->help);
        return 0;
    }
    if (o->kind == CLI_OPT_FLAG) r = store_whole(spec->cmd, o, dst, o->flag);
    else if (o->kind == CLI_OPT_ACTION) r = o->parse(spec->cmd, o, NULL, dst);
    else if (!(text = cli_value(spec->cmd, argc, argv, i))) r = 0;
    else r = read_value(spec->cmd, o, text, dst);
    if (r == 1 && o->seen) {
        int one = 1;
        memcpy((char *)dst + o->seen - 1, &one, sizeof one);
    }
    return r;
}

static int not_an_option(const cli_spec *spec, const char *arg)
{
    if (spec->positional && !(arg[0] == '-' && arg[1] != '\0')) return spec->positional(spec->ctx, arg);
    cli_error(spec->cmd, "unknown %s '%s' (see %s)", spec->unknown ? spec->unknown : "option", arg, spec->see);
    return 0;
}

int cli_opts_parse(const cli_spec *spec, const cli_opt_table *tables, int n_tables, int argc, char **argv)
{
    for (int i = 1; i < argc; ++i) {
        if (is_help(argv[i])) {
            spec->usage(stdout);
            return SOAK_EXIT_OK;
        }
        if (strcmp(argv[i], "--man") == 0) {
            cli_man_command(stdout, spec, tables, n_tables);
            return SOAK_EXIT_OK;
        }
        void *dst = NULL;
        const cli_opt *o = find(tables, n_tables, argv[i], &dst);
        int r = o ? read_option(spec, o, dst, argc, argv, &i) : not_an_option(spec, argv[i]);
        if (r == 0) return SOAK_EXIT_USAGE;
        if (r == CLI_OPT_STOP) return SOAK_EXIT_OK;
    }
    return -1;
}

/* ---- --help ---- */
#define HELP_LABEL_MIN 18 /* the help column of short tables */
#define HELP_LABEL_MAX 24 /* longer labels put their help on the next line */

static int listed(const cli_opt *o) { return o->help && o->kind != CLI_OPT_REJECT && o->kind != CLI_OPT_HEADING; }

static int label_of(const cli_opt *o, char *buf, size_t len)
{
    int n = snprintf(buf, len, "%s%s%s%s%s", o->alias ? o->alias : "", o->alias ? ", " : "", o->name,
                     o->meta ? " " : "", o->meta ? o->meta : "");
    return n < 0 ? 0 : n;
}

static void print_range(FILE *out, const cli_opt *o)
{
    if (o->kind == CLI_OPT_INT) fprintf(out, "%ld..%ld", o->ilo, o->ihi);
    else if (o->kind == CLI_OPT_SIZE || o->kind == CLI_OPT_DIMS) fprintf(out, "1..%ld", o->ihi);
    else fprintf(out, "%g..%g", o->lo, o->hi);
}

static void print_help_text(FILE *out, const cli_opt *o, int column)
{
    for (const char *c = o->help; *c; ++c) {
        if (*c == '\n') fprintf(out, "\n%*s", column, "");
        else if (c[0] == '%' && c[1] == 'R') print_range(out, o), ++c;
        else fputc(*c, out);
    }
    fputc('\n', out);
}

void cli_opts_help(FILE *out, const cli_opt_table *tables, int n_tables)
{
    char label[128];
    int width = HELP_LABEL_MIN;
    for (int t = 0; t < n_tables; ++t)
        for (size_t k = 0; k < tables[t].n; ++k) {
            int n = listed(&tables[t].opts[k]) ? label_of(&tables[t].opts[k], label, sizeof label) : 0;
            if (n > width && n <= HELP_LABEL_MAX) width = n;
        }
    int column = 2 + width + 2;
    for (int t = 0; t < n_tables; ++t)
        for (size_t k = 0; k < tables[t].n; ++k) {
            const cli_opt *o = &tables[t].opts[k];
            if (o->kind == CLI_OPT_HEADING) fprintf(out, "%s\n", o->help);
            if (!listed(o)) continue;
            if (label_of(o, label, sizeof label) > width) fprintf(out, "  %s\n%*s", label, column, "");
            else fprintf(out, "  %-*s  ", width, label);
            print_help_text(out, o, column);
        }
}

/* ---- --man: the same text as man(7) source ---- */

/* Text as roff: backslashes and minus signs escaped, a line starting with a
 * control character guarded. Returns 1 when it ended a line. */
static int man_inline(FILE *out, const char *text)
{
    int line_start = 1;
    for (const char *c = text; *c; ++c) {
        if (line_start && (*c == '.' || *c == '\'')) fputs("\\&", out);
        if (*c == '\\') fputs("\\e", out);
        else if (*c == '-') fputs("\\-", out);
        else fputc(*c, out);
        line_start = *c == '\n';
    }
    return line_start;
}

/* The same, ending the last line. */
static void man_escaped(FILE *out, const char *text)
{
    if (!man_inline(out, text)) fputc('\n', out);
}

/* Text kept as printed (aligned lists, examples). */
static void man_block(FILE *out, const char *text)
{
    if (!text || !text[0]) return;
    fputs(".PP\n.nf\n", out);
    man_escaped(out, text);
    fputs(".fi\n", out);
}

/* What usage(memstream) printed, or NULL. */
static char *usage_text(void (*usage)(FILE *out))
{
    char *buf = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&buf, &len);
    if (!m) return NULL;
    usage(m);
    if (fclose(m) == 0) return buf;
    free(buf);
    return NULL;
}

static char *options_text(const cli_opt_table *tables, int n_tables)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&buf, &len);
    if (!m) return NULL;
    cli_opts_help(m, tables, n_tables);
    if (fclose(m) == 0) return buf;
    free(buf);
    return NULL;
}

/* One option: ".TP", its names in bold, its placeholder in italics, its help. */
static void man_option(FILE *out, const cli_opt *o)
{
    fputs(".TP\n\\fB", out);
    if (o->alias) man_inline(out, o->alias), fputs("\\fR, \\fB", out);
    man_inline(out, o->name);
    fputs("\\fR", out);
    if (o->meta) fputs(" \\fI", out), man_inline(out, o->meta), fputs("\\fR", out);
    fputc('\n', out);
    char *help = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&help, &len);
    if (!m) return;
    print_help_text(m, o, 0);
    if (fclose(m) == 0) man_escaped(out, help);
    free(help);
}

static void man_options(FILE *out, const cli_opt_table *tables, int n_tables)
{
    for (int t = 0; t < n_tables; ++t)
        for (size_t k = 0; k < tables[t].n; ++k) {
            const cli_opt *o = &tables[t].opts[k];
            if (o->kind == CLI_OPT_HEADING) fputs(".PP\n", out), man_escaped(out, o->help);
            if (listed(o)) man_option(out, o);
        }
}

void cli_man_usage(FILE *out, const char *title, void (*usage)(FILE *out))
{
    if (title) fprintf(out, ".SS \"%s\"\n", title);
    char *text = usage_text(usage);
    man_block(out, text);
    free(text);
}

/* The earliest of the tables' --help texts (each table printed alone) in
 * text: its index (its place and length in *at, *len), or -1. */
static int earliest_table(const char *text, const cli_opt_table *tables, int n_tables, const char **at, size_t *len)
{
    int best = -1;
    for (int t = 0; t < n_tables; ++t) {
        char *opts = options_text(&tables[t], 1);
        const char *hit = opts && opts[0] ? strstr(text, opts) : NULL;
        if (hit && (best < 0 || hit < *at)) {
            best = t;
            *at = hit;
            *len = strlen(opts);
        }
        free(opts);
    }
    return best;
}

/* Prints text up to each table's part in it, then that table's options;
 * returns the text after the last part. */
static char *man_each_table(FILE *out, char *text, const cli_opt_table *tables, int n_tables)
{
    const char *at = NULL;
    size_t len = 0;
    int t;
    while (text && (t = earliest_table(text, tables, n_tables, &at, &len)) >= 0) {
        char *hit = text + (at - text);
        *hit = '\0';
        man_block(out, text);
        man_options(out, &tables[t], 1);
        text = hit + len;
    }
    return text;
}

/* The usage text with each options part (cli_opts_help's text of all the
 * tables at once, else of each table alone, wherever usage prints it)
 * replaced by one tagged paragraph per option. */
void cli_man_command(FILE *out, const cli_spec *spec, const cli_opt_table *tables, int n_tables)
{
    fprintf(out, ".SS \"soak %s\"\n", spec->cmd);
    char *text = usage_text(spec->usage), *all = options_text(tables, n_tables);
    char *rest = text, *at = text && all && all[0] ? strstr(text, all) : NULL;
    if (at) {
        *at = '\0';
        man_block(out, rest);
        man_options(out, tables, n_tables);
        rest = at + strlen(all);
    } else {
        rest = man_each_table(out, text, tables, n_tables);
    }
    man_block(out, rest);
    free(text);
    free(all);
}
