/* Image input (soak_image_read through OpenImageIO): the first byte picks the
 * file extension, the rest is the file. Decoded pixels must be finite. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>

#include "fuzz_common.h"
#include "soak/image.h"

#ifdef SOAK_FUZZ_INPROCESS
/* The decoder in this process (image_contain.c): a fuzzer must see the
 * library's crashes, which the reader's child would turn into messages,
 * and a fork per input ran 8 inputs a second. The replay uses the child. */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    setenv("SOAK_IMAGE_IN_PROCESS", "1", 1);
    return 0;
}
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const ext[] = {"png", "exr", "tif", "hdr", "jpg", "ppm"};
    if (size < 1 || size > 1 << 20) return 0;
    const char *path = fuzz_temp_file(data + 1, size - 1, ext[data[0] % 6]);
    if (!path) return 0;
    soak_image img;
    char err[1024] = "";
    if (soak_image_read(path, &img, err, sizeof err) == SOAK_OK) {
        size_t n = (size_t)img.width * img.height * img.channels;
        for (size_t i = 0; i < n; ++i)
            if (!isfinite(img.pixels[i])) abort();
        soak_image_free(&img);
    } else {
        fuzz_check_message(err, path, NULL);
    }
    return 0;
}
