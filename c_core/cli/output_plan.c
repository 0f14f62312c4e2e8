/* One output plan per bake command (issue 51 item 1): every path every
 * frame of every output will be written to, and every input, resolved to
 * the file it names before any work, so that no two outputs and no output
 * and input are one file.
 *
 * A path's identity: an existing file (symbolic links followed, as the
 * staged writer follows them) is its device and inode, so hard links match
 * too; a file still to be written is its folder's canonical path (realpath:
 * links and ".." resolved) plus its name. Entries are sorted by identity
 * and neighbours compared, so 100 000 frames of four outputs cost one sort. */
#define _DEFAULT_SOURCE
#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "bake_cli.h"
#include "soak/staged.h"

typedef struct plan_entry {
    char *id;
    const char *option;
    int rank;   /* the option's place in the command's list: inputs first */
    long frame; /* -1: not a sequence */
    int input;
} plan_entry;

typedef struct plan {
    plan_entry *e;
    size_t n, cap;
    char last_dir[PATH_MAX], last_real[PATH_MAX]; /* consecutive frames share a folder */
    const char *cmd;
} plan;

/* How a message names a frame; here, below bake_cli_common.c, which calls
 * the plan. */
const char *bake_frame_label(long f, char *buf, size_t n)
{
    if (f < 0) snprintf(buf, n, "the map");
    else snprintf(buf, n, "frame %ld", f);
    return buf;
}

/* "i:<dev>:<ino>" for an existing file, else "p:<canonical folder>/<name>"
 * (the path as given when its folder does not resolve: writing it then
 * fails in the folder checks). */
static char *identity(plan *p, const char *path)
{
    struct stat st;
    char buf[2 * PATH_MAX + 64];
    if (stat(path, &st) == 0) {
        snprintf(buf, sizeof buf, "i:%ju:%ju", (uintmax_t)st.st_dev, (uintmax_t)st.st_ino);
        return strdup(buf);
    }
    const char *slash = strrchr(path, '/');
    char dir[PATH_MAX];
    if (!slash) snprintf(dir, sizeof dir, ".");
    else if (slash == path) snprintf(dir, sizeof dir, "/");
    else snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
    if (strcmp(dir, p->last_dir) != 0) {
        if (!realpath(dir, p->last_real)) p->last_real[0] = '\0';
        snprintf(p->last_dir, sizeof p->last_dir, "%s", dir);
    }
    if (!p->last_real[0]) snprintf(buf, sizeof buf, "p:%s", path);
    else snprintf(buf, sizeof buf, "p:%s/%s", p->last_real, slash ? slash + 1 : path);
    return strdup(buf);
}

static int add(plan *p, const char *option, int rank, long frame, int input, const char *path)
{
    if (p->n == p->cap) {
        size_t cap = p->cap ? 2 * p->cap : 64;
        plan_entry *e = realloc(p->e, cap * sizeof *e);
        if (!e) return 0;
        p->e = e;
        p->cap = cap;
    }
    char *id = identity(p, path);
    if (!id) return 0;
    p->e[p->n++] = (plan_entry){id, option, rank, frame, input};
    return 1;
}

static int by_identity(const void *a, const void *b)
{
    const plan_entry *x = a, *y = b;
    int c = strcmp(x->id, y->id);
    if (c) return c;
    if (x->rank != y->rank) return x->rank - y->rank;
    return (x->frame > y->frame) - (x->frame < y->frame);
}

/* The staged writer names a finished file ".<name>.tmp<pid>.<n>" before its
 * final rename (soak/staged.h): 1 + 4 + 7 (pid_max 4194304) + 1 + 3 bytes
 * beyond the name. */
#define TEMP_SUFFIX_BYTES 16

/* A name that is valid but leaves no room for the temporary's, refused
 * before any work rather than after the bake. Returns 0 or the exit code. */
static int check_name_length(const bake_opts *o, const char *option, long frame, const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    char dir[PATH_MAX];
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path) + 1 : 1, slash ? path : ".");
    long name_max = pathconf(dir, _PC_NAME_MAX);
    if (name_max <= 0) name_max = 255;
    size_t n = strlen(base);
    if (n + TEMP_SUFFIX_BYTES <= (size_t)name_max && strlen(path) + TEMP_SUFFIX_BYTES < PATH_MAX) return 0;
    char label[32];
    cli_error(o->cmd,
              "%s%s%s: the name '%.40s...' has %zu bytes (path %zu): with the temporary's %d-byte suffix "
              "it exceeds the folder's limit of %ld (paths %d); use a name of at most %ld bytes",
              option, frame >= 0 ? " " : "", frame >= 0 ? bake_frame_label(frame, label, sizeof label) : "", base, n,
              strlen(path), TEMP_SUFFIX_BYTES, name_max, PATH_MAX - 1, name_max - TEMP_SUFFIX_BYTES);
    return SOAK_EXIT_USAGE;
}

/* Every frame of one file or pattern. Returns 0 on allocation failure, -1
 * after refusing a name. */
static int add_all(plan *p, const bake_opts *o, const bake_output *f, int rank, int input)
{
    if (!f->path || !f->path[0]) return 1;
    int sequence = o->have_frames && soak_bake_pattern_kind(f->path) == 1;
    long first = sequence ? o->first : -1, last = sequence ? o->last : -1;
    for (long fr = first; fr <= last; ++fr) {
        char path[PATH_MAX];
        if (fr >= 0 && soak_bake_frame_path(f->path, (int)fr, path, sizeof path) != SOAK_OK) continue;
        if (!input && (fr == first || fr == last) && check_name_length(o, f->option, fr, fr >= 0 ? path : f->path))
            return -1;
        if (!add(p, f->option, rank, fr, input, fr >= 0 ? path : f->path)) return 0;
    }
    return 1;
}

static void describe(const plan_entry *e, const bake_opts *o, const bake_output *outs, const bake_output *ins,
                     char *buf, size_t n)
{
    const bake_output *f = e->input ? &ins[e->rank] : &outs[e->rank - BAKE_MAX_INPUTS];
    char path[PATH_MAX];
    if (e->frame < 0 || soak_bake_frame_path(f->path, (int)e->frame, path, sizeof path) != SOAK_OK)
        snprintf(path, sizeof path, "%s", f->path);
    (void)o;
    if (e->frame >= 0) snprintf(buf, n, "%s frame %ld ('%s')", e->option, e->frame, path);
    else snprintf(buf, n, "%s '%s'", e->option, path);
}

/* The first clash in sorted order, reported; 0 when there is none. */
static int report_clash(const plan *p, const bake_opts *o, const bake_output *outs, const bake_output *ins)
{
    for (size_t i = 0; i + 1 < p->n; ++i) {
        const plan_entry *a = &p->e[i], *b = &p->e[i + 1];
        if (strcmp(a->id, b->id) != 0 || b->input) continue;
        char da[PATH_MAX + 128], db[PATH_MAX + 128];
        describe(a, o, outs, ins, da, sizeof da);
        describe(b, o, outs, ins, db, sizeof db);
        if (a->input) cli_error(o->cmd, "%s is the same file as the input %s; refusing to overwrite it", db, da);
        else cli_error(o->cmd, "%s and %s are the same file; refusing to write one over the other", da, db);
        return SOAK_EXIT_USAGE;
    }
    return 0;
}

/* A temporary of ours, ".<name>.tmp<pid>.<n>" (soak/staged.h): *name_len
 * gets the length of <name> and *pid the writer's process id. */
static int our_temporary(const char *entry, size_t *name_len, long *pid)
{
    const char *tmp = strstr(entry, ".tmp"), *next;
    if (entry[0] != '.' || !tmp || tmp == entry + 1) return 0;
    for (next = strstr(tmp + 1, ".tmp"); next; next = strstr(next + 1, ".tmp")) tmp = next;
    char *end = NULL;
    *pid = strtol(tmp + 4, &end, 10);
    if (end == tmp + 4 || *end != '.' || *pid <= 0) return 0;
    const char *index = end + 1;
    strtol(index, &end, 10);
    if (end == index || *end) return 0;
    *name_len = (size_t)(tmp - entry - 1);
    return 1;
}

static int planned_output(plan *p, const char *path)
{
    char *id = identity(p, path);
    if (!id) return 0;
    plan_entry key = {id, NULL, 0, 0, 0};
    size_t lo = 0, hi = p->n;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (strcmp(p->e[mid].id, key.id) < 0) lo = mid + 1;
        else hi = mid;
    }
    int hit = 0;
    for (size_t i = lo; i < p->n && !strcmp(p->e[i].id, id) && !hit; ++i) hit = !p->e[i].input;
    free(id);
    return hit;
}

/* A journal of ours, ".<name>.journal<pid>" (soak/staged.h). */
static int our_journal(const char *entry, long *pid)
{
    const char *j = strstr(entry, ".journal"), *next;
    if (entry[0] != '.' || !j || j == entry + 1) return 0;
    for (next = strstr(j + 1, ".journal"); next; next = strstr(next + 1, ".journal")) j = next;
    char *end = NULL;
    *pid = strtol(j + 8, &end, 10);
    return end != j + 8 && !*end && *pid > 0;
}

static int gone(long pid) { return pid != getpid() && kill((pid_t)pid, 0) != 0 && errno == ESRCH; }

static int planned_cb(void *ctx, const char *path) { return planned_output(ctx, path); }

/* One folder (dir, with its '/'; "" for the working folder): first the
 * journals of killed runs, whose renames are completed (a set of outputs
 * cut between two renames becomes the killed run's, whole), then the
 * temporaries left, removed. */
static void sweep_folder(plan *p, const char *dir)
{
    DIR *d = opendir(dir[0] ? dir : ".");
    if (!d) return;
    for (int pass = 0; pass < 2; ++pass, rewinddir(d)) {
        for (struct dirent *e = readdir(d); e; e = readdir(d)) {
            size_t name_len;
            long pid;
            char path[PATH_MAX + NAME_MAX + 2], final[PATH_MAX + NAME_MAX + 2];
            snprintf(path, sizeof path, "%s%s", dir, e->d_name);
            if (pass == 0 && our_journal(e->d_name, &pid) && gone(pid)) {
                int n = soak_staged_journal_recover(path, planned_cb, p);
                if (n >= 0)
                    fprintf(stderr,
                            "soak %s: completed %d rename%s of a set of outputs an interrupted run left half "
                            "renamed (%s)\n",
                            p->cmd, n, n == 1 ? "" : "s", path);
            } else if (pass == 1 && our_temporary(e->d_name, &name_len, &pid) && gone(pid)) {
                snprintf(final, sizeof final, "%s%.*s", dir, (int)name_len, e->d_name + 1);
                if (planned_output(p, final) && unlink(path) == 0)
                    fprintf(stderr, "soak %s: removed %s, left by an interrupted run\n", p->cmd, path);
            }
        }
    }
    closedir(d);
}

/* The folder part of path with its '/' ("" when it has none). */
static void folder_of(const char *path, char *dir, size_t n)
{
    const char *slash = strrchr(path, '/');
    snprintf(dir, n, "%.*s", slash ? (int)(slash - path) + 1 : 0, path);
}

/* Completes or removes what a killed earlier run of these outputs left
 * (issue 51 item 4: a signal between naming and renaming a finished file,
 * or SIGKILL): ours by name, for a planned output, of a process that is
 * gone. Each output folder once; a pattern whose folder holds the frame
 * number, each frame's folder. */
static void sweep_stale(plan *p, const bake_opts *o, const bake_output *outs, int n_outs)
{
    for (int k = 0; k < n_outs; ++k) {
        if (!outs[k].path || !outs[k].path[0]) continue;
        char dir[PATH_MAX], last[PATH_MAX] = "", path[PATH_MAX];
        folder_of(outs[k].path, dir, sizeof dir);
        int per_frame = o->have_frames && soak_bake_pattern_kind(outs[k].path) == 1 && soak_bake_pattern_kind(dir) == 1;
        if (!per_frame) {
            sweep_folder(p, dir);
            continue;
        }
        for (long fr = o->first; fr <= o->last; ++fr) {
            if (soak_bake_frame_path(outs[k].path, (int)fr, path, sizeof path) != SOAK_OK) continue;
            folder_of(path, dir, sizeof dir);
            if (strcmp(dir, last) != 0) sweep_folder(p, dir);
            snprintf(last, sizeof last, "%s", dir);
        }
    }
}

int bake_plan_check(const bake_opts *o, const bake_output *outs, int n_outs, const bake_output *ins, int n_ins)
{
    if (n_ins > BAKE_MAX_INPUTS) n_ins = BAKE_MAX_INPUTS;
    plan *p = calloc(1, sizeof *p);
    int ok = p != NULL;
    for (int k = 0; ok == 1 && k < n_ins; ++k) ok = add_all(p, o, &ins[k], k, 1);
    for (int k = 0; ok == 1 && k < n_outs; ++k) ok = add_all(p, o, &outs[k], BAKE_MAX_INPUTS + k, 0);
    int rc = 0;
    if (ok < 0) {
        rc = SOAK_EXIT_USAGE;
    } else if (!ok) {
        cli_error(o->cmd, "out of memory while planning the outputs");
        rc = SOAK_EXIT_FAIL;
    } else {
        qsort(p->e, p->n, sizeof *p->e, by_identity);
        rc = report_clash(p, o, outs, ins);
        p->cmd = o->cmd;
        if (rc == 0) sweep_stale(p, o, outs, n_outs);
    }
    for (size_t i = 0; p && i < p->n; ++i) free(p->e[i].id);
    if (p) free(p->e);
    free(p);
    return rc;
}
