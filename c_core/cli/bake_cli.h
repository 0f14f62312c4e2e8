/* Entry points of the `soak bake` kinds, each in its own CLI file.
 * cmd_bake.c dispatches `soak bake <kind> ...` to these; argv[0] is the kind
 * name ("volume", "rain", ...), the rest are that kind's options. Each returns a
 * process exit code (SOAK_EXIT_OK / SOAK_EXIT_FAIL / SOAK_EXIT_USAGE, cli.h),
 * prints its own --help with an example, and writes outputs atomically. */
#ifndef SOAK_BAKE_CLI_H
#define SOAK_BAKE_CLI_H

#include <stddef.h>
#include <stdint.h>

#include "cli.h"
#include "soak/bake.h"

/* Implemented in bake_volume_cli.c: parameter volumes (soak bake volume). */
int soak_bake_volume_main(int argc, char **argv);

/* Implemented in bake_rain_cli.c: rain drop wetting maps (soak bake rain). */
int soak_bake_rain_main(int argc, char **argv);

/* Implemented in bake_drops_cli.c and bake_ripples_cli.c: rain over time. */
int soak_bake_drops_main(int argc, char **argv);
int soak_bake_ripples_main(int argc, char **argv);
/* bake_beads_cli.c: beads by the contact angle (soak bake beads). */
int soak_bake_beads_main(int argc, char **argv);

/* The 2D kinds, each in bake_<kind>_cli.c. */
int soak_bake_turbulence_main(int argc, char **argv);
int soak_bake_waves_main(int argc, char **argv);
int soak_bake_drying_main(int argc, char **argv);
int soak_bake_combine_main(int argc, char **argv);

/* ---- shared option handling of the 2D kinds (bake_cli_common.c) ----
 * The options every kind shares are the tables below. An image sequence is
 * --frames A-B with a printf pattern in the output (wet.%04d.exr); frame f
 * is baked at time T + (f - F) DT (--time, --frame-time, --frame-origin,
 * default A), the same double for a given f whatever --frames range it is
 * baked in (bake_frame_time). */
#define BAKE_MAX_INPUTS 16 /* input images of one bake */

typedef struct bake_opts {
    const char *cmd; /* "bake <kind>", for messages */
    const char *output;
    const char *output_option; /* the option naming output in messages (NULL: "-o") */
    long width, height;
    int have_width, have_height;
    uint64_t seed;
    long threads; /* 0 = every core */
    int float_exr;
    int have_frames;
    long first, last;
    double time, frame_time;
    long origin; /* --frame-origin: the frame baked at `time` */
    int have_origin;
    /* 1: the command plans every output together afterwards
     * (bake_plan_check), so bake_opts_check checks each path but plans
     * none: a plan of -o alone would sweep a killed run's journal of the
     * whole set without knowing the set's other outputs. */
    int plan_later;
} bake_opts;

/* Defaults: 1024 x 1024, seed 0, time and frame_time as given. */
void bake_opts_init(bake_opts *o, const char *cmd, double time, double frame_time);

/* The shared options as tables of bake_opts (cli.h): every kind reads
 * -o, --width, --height, --seed and --threads; the kinds that bake image
 * sequences also --float, --frames, --time, --frame-time, --frame-origin. */
extern const cli_opt bake_image_opts[];
extern const size_t bake_image_opts_n;
extern const cli_opt bake_sequence_opts[];
extern const size_t bake_sequence_opts_n;
/* The most entries a shared table has (bake_table_help's copies). */
#define BAKE_SHARED_OPTS_MAX 8
/* Copies the shared table src (n <= BAKE_SHARED_OPTS_MAX entries) into dst
 * with the --help text of option `name` replaced by help: for a kind whose
 * default differs from the shared one. Returns n. */
size_t bake_table_help(const cli_opt *src, size_t n, cli_opt *dst, const char *name, const char *help);
/* --frame-origin's help where it defaults to 0 (bake drops, bake rain). */
#define BAKE_ORIGIN_ZERO_HELP                                                                                   \
    "frame baked at time T (default 0: frame f at T + f DT whatever\n"                                            \
    "range is baked, so chunks equal one run)"
/* What a --rate of the Marshall-Palmer drop sizes at Atlas et al.'s speeds
 * delivers (docs/rain.md: 1.17x at 5 mm/h, 1.16x at 10, 1.13x at 25). */
#define BAKE_DELIVERED_RATE_HELP "; delivers 1.13-1.17x it\n(Marshall-Palmer sizes at Atlas speeds, docs/rain.md)"
#define BAKE_IMAGE_TABLE(dst) {bake_image_opts, bake_image_opts_n, (dst)}
#define BAKE_SEQUENCE_TABLE(dst) {bake_sequence_opts, bake_sequence_opts_n, (dst)}
/* The noise of soak bake turbulence and soak bake volume, a table of
 * soak_turbulence_params: --turbulence, --octaves, --frequency,
 * --lacunarity, --gain, --threshold, --softness. */
extern const cli_opt bake_noise_opts[];
extern const size_t bake_noise_opts_n;
#define BAKE_NOISE_TABLE(dst) {bake_noise_opts, bake_noise_opts_n, (dst)}
/* The floor of the kinds' "(0, max]" settings (frequencies, periods,
 * lengths): the library takes anything above 0. */
#define BAKE_MIN_POSITIVE 1e-6

/* "unknown option 'X' (see --help)", usage printed on --help. */
#define BAKE_SPEC(cmd, usage, positional, ctx) {(cmd), "option", "--help", (usage), (positional), (ctx)}

/* Checks -o, the frames/pattern agreement and every output path against
 * every input (inputs may be patterns expanded per frame) and the output
 * folder. Returns 0 or the exit code after printing the error. */
int bake_opts_check(const bake_opts *o, const char *const *inputs, int n_inputs);

/* One output plan (output_plan.c, issue 51 item 1): every frame's path of
 * every output (a pattern expands over --frames, a plain path is one file)
 * and of every input, resolved (symbolic links, "..", hard links) before
 * any work; two outputs, or an output and an input, that are one file are
 * refused naming both options and the frame. Returns 0 or the exit code
 * after printing the error. */
typedef struct bake_output {
    const char *option; /* "-o", "--far", "mesh", ... */
    const char *path;   /* NULL or "": none */
} bake_output;
int bake_plan_check(const bake_opts *o, const bake_output *outs, int n_outs, const bake_output *ins, int n_ins);

/* Produces frame `frame` (the frame number, or -1 for a single image) at
 * `time` into out; err gets a message on failure. */
typedef soak_status (*bake_frame_fn)(void *ctx, int frame, double time, const soak_bake_exec *exec, soak_image *out,
                                     char *err, size_t errlen);

/* Time of frame f (-1: the single image): time + (f - origin) * frame_time,
 * origin = --frame-origin or the first frame. Depends only on f and the
 * three options, never on the --frames range when the origin is given. */
double bake_frame_time(const bake_opts *o, long f);

/* "frame F", or "the map" for a single image (f < 0): never "frame -1". */
const char *bake_frame_label(long f, char *buf, size_t n);

/* Every frame's time within [lo, hi], checked before any work (times are
 * linear in f: the first and last frames bound the rest). Returns 0 or the
 * exit code after naming the frame, its time and the options that set it. */
int bake_check_times(const bake_opts *o, double lo, double hi);

/* Runs the frames with a progress bar, writing each atomically; returns
 * the exit code. */
int bake_run(const bake_opts *o, bake_frame_fn fn, void *ctx);

/* The same for kinds with more outputs per frame (--film, --water, --far):
 * the frame function stages them into extra (soak_bake_stage), and each
 * frame's outputs, -o's included, are replaced together or not at all
 * (issue 51 item 4: a full disk leaves every frame from one run). */
struct soak_staged;
typedef soak_status (*bake_frame_staged_fn)(void *ctx, int frame, double time, const soak_bake_exec *exec,
                                            soak_image *out, struct soak_staged *extra, char *err, size_t errlen);
int bake_run_staged(const bake_opts *o, bake_frame_staged_fn fn, void *ctx);

/* Exit code and message for a library status (SOAK_ERR_ARG -> 2, else 1). */
int bake_fail(const char *cmd, soak_status st, const char *err);

#endif
