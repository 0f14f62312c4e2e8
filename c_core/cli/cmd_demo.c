/* soak demo: not built yet; the owning issue replaces this file. */
#include "cli.h"

int soak_cmd_demo(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    cli_error("demo", "this command is not available in this build yet");
    return SOAK_EXIT_FAIL;
}
