/* soak: git-style entry point; each subcommand is in its own cmd_*.c. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "soak/image.h"
#include "soak/input_file.h"

#ifndef SOAK_VERSION
#define SOAK_VERSION "0.1.0"
#endif

static const soak_cli_command commands[] = {
    {"materials", "list the material presets (--json for machine-readable output)", soak_cmd_materials},
    {"albedo", "dry and wet albedo of a preset, or the closed-form film albedo", soak_cmd_albedo},
    {"eval", "evaluate a BRDF model or fast path at given angles, or tabulate it (--csv)", soak_cmd_eval},
    {"demo", "the main job: wet-vs-dry table, swatch sheet, bakes and renders of the default scene", soak_cmd_demo},
    {"render", "render a JSON scene with the reference path tracer", soak_cmd_render},
    {"measure", "virtual gonio-reflectometer: traced reflectance of canonical configurations", soak_cmd_measure},
    {"export", "the core's data for renderer front ends (json, povray, blender, osl)", soak_cmd_export},
    {"report", "error against the full material and cost of every model (docs/ACCURACY.md)", soak_cmd_report},
    {"advise", "the cheapest model per material of a scene within an error tolerance", soak_cmd_advise},
    {"bake", "bake wet maps and parameter volumes (turbulence, waves, drying, rain, combine, volume)", soak_cmd_bake},
};
static const int n_commands = (int)(sizeof commands / sizeof commands[0]);

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak <command> [options]\n"
            "       soak <command> --help\n\n"
            "Physically based wet materials: models, reference tracer and bakers.\n\n"
            "commands:\n");
    for (int i = 0; i < n_commands; ++i) fprintf(out, "  %-10s %s\n", commands[i].name, commands[i].summary);
    fprintf(out, "\ninput limits (every command; an environment variable raises each, in MiB):\n");
    for (int k = 0; k < SOAK_INPUT_KINDS; ++k)
        fprintf(out, "  %-13s %6lld MiB  %s\n", soak_input_kind_name((soak_input_kind)k),
                soak_input_cap((soak_input_kind)k) / 1048576, soak_input_kind_env((soak_input_kind)k));
    fprintf(out,
            "  a mesh counts with the files it names; its reader's memory: SOAK_MESH_MEMORY_MB, time:\n"
            "  SOAK_MESH_TIMEOUT (s); working memory of a bake: SOAK_MAX_MEMORY_MB (default the larger\n"
            "  of 1024 MiB and 256 bytes per byte of compressed input); images: at most %d pixels a\n"
            "  side and 1024 MiB as float, their decoder's time: SOAK_IMAGE_TIMEOUT (s, default 10 + 1\n"
            "  per MiB). Inputs must be regular files (README: Outputs and inputs).\n",
            SOAK_IMAGE_MAX_SIDE);
    fprintf(out,
            "\nother options:\n"
            "  --version  the version\n"
            "  --man      this help and every command's as a manual page (man(7) source)\n"
            "\ndata folder (presets, export schema, demo scene, POV-Ray includes): the first\n"
            "of these that holds materials.json\n"
            "  1. $SOAK_DATA_DIR, when set (only it is searched)\n"
            "  2. share/soak beside the folder of the soak executable\n"
            "     (PREFIX/bin/soak reads PREFIX/share/soak, wherever PREFIX is)\n"
            "  3. the source tree, for a soak that runs from its build tree\n");
    cli_environment_help(out);
    fprintf(out, "\nexample:\n  soak albedo --material sand --wetness 1\n");
}

/* `soak --man`: the manual page, from --help's texts and the option tables. */
static int print_man(void)
{
    printf(".TH SOAK 1 \"\" \"soak %s\" \"User Commands\"\n"
           ".SH NAME\nsoak \\- physically based wet materials: models, reference tracer and bakers\n"
           ".SH SYNOPSIS\n\\fBsoak\\fR \\fIcommand\\fR [\\fIoptions\\fR]\n"
           ".br\n\\fBsoak\\fR \\fIcommand\\fR \\fB\\-\\-help\\fR\n"
           ".SH DESCRIPTION\n",
           SOAK_VERSION);
    cli_man_usage(stdout, NULL, usage);
    printf(".SH COMMANDS\n");
    return cli_man_commands(commands, n_commands);
}

/* Results that never reached stdout (a full disk, /dev/full, a closed pipe)
 * turn a successful exit into a failure. */
static int check_stdout(const char *name, int rc)
{
    if (fflush(stdout) == 0 && !ferror(stdout)) return rc;
    if (rc != SOAK_EXIT_OK) return rc; /* the command has reported its failure */
    int e = errno;
    fprintf(stderr, "soak%s%s: cannot write the results to standard output: %s\n", name ? " " : "", name ? name : "",
            strerror(e ? e : EIO));
    return rc == SOAK_EXIT_OK ? SOAK_EXIT_FAIL : rc;
}

int main(int argc, char **argv)
{
    int rc = cli_dispatch_help(argc, argv, usage);
    if (rc >= 0) return check_stdout(NULL, rc);
    if (strcmp(argv[1], "--version") == 0) {
        printf("soak %s\n", SOAK_VERSION);
        return check_stdout(NULL, SOAK_EXIT_OK);
    }
    if (strcmp(argv[1], "--man") == 0) return check_stdout(NULL, print_man());
    const soak_cli_command *cmd = cli_find(commands, n_commands, argv[1]);
    if (cmd && (rc = cli_check_environment()) != 0) return rc;
    if (cmd) return check_stdout(cmd->name, cmd->run(argc - 1, argv + 1));
    fprintf(stderr, "soak: unknown command '%s' (see 'soak --help')\n", argv[1]);
    return SOAK_EXIT_USAGE;
}
