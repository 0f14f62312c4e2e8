/* Image I/O round trips through OpenImageIO: EXR keeps floats to half
 * precision, linear 16-bit PNG keeps values to 1/65535 and carries gAMA 1.0. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "soak/image.h"

static int png_has_gama_one(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    unsigned char buf[4096];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    for (size_t i = 0; i + 12 <= n; ++i)
        if (memcmp(buf + i, "gAMA", 4) == 0) {
            unsigned v = (unsigned)buf[i + 4] << 24 | (unsigned)buf[i + 5] << 16 | (unsigned)buf[i + 6] << 8 | buf[i + 7];
            return v == 100000; /* gamma 1.0 is stored as 1/gamma * 100000 */
        }
    return 0;
}

int main(void)
{
    mkdir("test_tmp", 0755);
    soak_image img;
    check_status("alloc", soak_image_alloc(&img, 7, 5, 3), SOAK_OK);
    for (int i = 0; i < 7 * 5 * 3; ++i) img.pixels[i] = (float)(i % 11) / 10.0f;
    char err[512] = "";

    const char *exts[] = {"exr", "png", "tif"};
    double tols[] = {1e-3, 1.0 / 65535 + 1e-7, 1.0 / 65535 + 1e-7};
    for (int e = 0; e < 3; ++e) {
        char path[64];
        snprintf(path, sizeof path, "test_tmp/roundtrip.%s", exts[e]);
        check_status(path, soak_image_write(path, &img, NULL, err, sizeof err), SOAK_OK);
        soak_image back;
        if (!check_status("read back", soak_image_read(path, &back, err, sizeof err), SOAK_OK)) {
            printf("%s\n", err);
            continue;
        }
        double maxerr = 0;
        for (int i = 0; i < 7 * 5 * 3; ++i) {
            double d = back.pixels[i] - img.pixels[i];
            if (d < 0) d = -d;
            if (d > maxerr) maxerr = d;
        }
        check_true("same size", back.width == 7 && back.height == 5 && back.channels == 3);
        check_close(path, maxerr, 0.0, tols[e]);
        soak_image_free(&back);
    }
    check_true("linear PNG has gAMA 1.0", png_has_gama_one("test_tmp/roundtrip.png"));

    check_status("missing folder rejected", soak_image_write("no/such/dir/x.png", &img, NULL, err, sizeof err), SOAK_ERR_IO);
    check_true("message names the folder", strstr(err, "no/such/dir") != NULL);
    soak_image none;
    check_status("unreadable file", soak_image_read("test_tmp/does_not_exist.exr", &none, err, sizeof err), SOAK_ERR_IO);
    FILE *f = fopen("test_tmp/truncated.png", "wb");
    fwrite("\x89PNG\r\n\x1a\n\0\0", 1, 10, f);
    fclose(f);
    check_status("truncated png", soak_image_read("test_tmp/truncated.png", &none, err, sizeof err), SOAK_ERR_IO);
    soak_image_free(&img);
    return check_finish();
}
