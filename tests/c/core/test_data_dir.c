/* The data folder search of soak/data_dir.h: $SOAK_DATA_DIR alone when set,
 * the build tree's source files for a test that runs from the build tree,
 * and errors that name what was tried. The installed layout (PREFIX/bin next
 * to PREFIX/share/soak, moved away from the source tree) is tested on the
 * installed soak by tests/cli/install.sh. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "soak/data_dir.h"

static int readable(const char *path) { return access(path, R_OK) == 0; }

static void check_env_folder(void)
{
    char dir[] = "/tmp/soak_data_dir_XXXXXX";
    if (!mkdtemp(dir)) {
        check_true("mkdtemp", 0);
        return;
    }
    char out[512] = "", err[2048] = "", want[600];
    setenv("SOAK_DATA_DIR", dir, 1);
    check_status("SOAK_DATA_DIR without materials.json -> NOT_FOUND",
                 soak_data_path("materials.json", out, sizeof out, err, sizeof err), SOAK_ERR_NOT_FOUND);
    check_true("the message names SOAK_DATA_DIR and its value",
               strstr(err, "SOAK_DATA_DIR") != NULL && strstr(err, dir) != NULL);
    check_true("no fallback past SOAK_DATA_DIR: out untouched", out[0] == '\0');

    snprintf(want, sizeof want, "%s/materials.json", dir);
    FILE *f = fopen(want, "w");
    check_true("marker written", f && fputs("{}", f) >= 0 && fclose(f) == 0);
    check_status("SOAK_DATA_DIR with materials.json",
                 soak_data_path("materials.json", out, sizeof out, err, sizeof err), SOAK_OK);
    check_true("materials.json of SOAK_DATA_DIR", strcmp(out, want) == 0);
    check_status("a scene under SOAK_DATA_DIR",
                 soak_data_path("scenes/default_wet_dry.json", out, sizeof out, err, sizeof err), SOAK_OK);
    snprintf(want, sizeof want, "%s/scenes/default_wet_dry.json", dir);
    check_true("scenes/ under the same folder (installed layout)", strcmp(out, want) == 0);

    char tiny[12] = "keep";
    check_status("path longer than out -> ARG", soak_data_path("materials.json", tiny, sizeof tiny, err, sizeof err),
                 SOAK_ERR_ARG);
    check_true("too long: out untouched", strcmp(tiny, "keep") == 0);
    check_status("NULL relative -> NULL", soak_data_path(NULL, out, sizeof out, NULL, 0), SOAK_ERR_NULL);
    unsetenv("SOAK_DATA_DIR");
    snprintf(want, sizeof want, "%s/materials.json", dir);
    unlink(want);
    rmdir(dir);
}

/* A test runs from the build tree: its files are the source tree's. */
static void check_build_tree(void)
{
    setenv("SOAK_DATA_DIR", "", 1); /* empty: not set */
    char out[4096], err[2048];
    const char *files[] = {"materials.json", "export.schema.json", "scenes/default_wet_dry.json", "povray/soak.inc"};
    for (size_t i = 0; i < sizeof files / sizeof *files; ++i) {
        char what[4300];
        snprintf(what, sizeof what, "build tree: %s found", files[i]);
        check_status(what, soak_data_path(files[i], out, sizeof out, err, sizeof err), SOAK_OK);
        snprintf(what, sizeof what, "build tree: %s readable (%s)", files[i], out);
        check_true(what, readable(out));
    }
    unsetenv("SOAK_DATA_DIR");
}

int main(void)
{
    check_env_folder();
    check_build_tree();
    return check_finish();
}
