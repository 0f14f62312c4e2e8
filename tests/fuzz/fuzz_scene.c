/* Scene parser (soak_scene_parse): any text either loads or fails with a
 * message; nothing crashes, leaks or hangs. */
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "soak/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 1 << 20) return 0;
    char *text = malloc(size + 1);
    if (!text) return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    soak_scene scene;
    char err[1024] = "";
    if (soak_scene_parse(text, "fuzz.json", fuzz_temp_dir(), &scene, err, sizeof err) == SOAK_OK) soak_scene_free(&scene);
    else fuzz_check_message(err, "fuzz.json", NULL); /* every failure explains itself */
    free(text);
    return 0;
}
