/* soak render: not built yet; the owning issue replaces this file. */
#include "cli.h"

int soak_cmd_render(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    cli_error("render", "this command is not available in this build yet");
    return SOAK_EXIT_FAIL;
}
