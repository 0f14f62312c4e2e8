/* soak measure: not built yet; the owning issue replaces this file. */
#include "cli.h"

int soak_cmd_measure(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    cli_error("measure", "this command is not available in this build yet");
    return SOAK_EXIT_FAIL;
}
