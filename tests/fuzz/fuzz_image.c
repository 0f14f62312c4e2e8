/* Image input (soak_image_read through OpenImageIO): the first byte picks the
 * file extension, the rest is the file. Decoded pixels must be finite. */
#include <math.h>
#include <stdlib.h>

#include "fuzz_common.h"
#include "soak/image.h"

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
