/* A float image's pixel buffer (soak/image.h): allocated within the size
 * limits every reader shares, freed to an empty image. */
#include <stdlib.h>

#include "soak/image.h"

soak_status soak_image_alloc(soak_image *img, int width, int height, int channels)
{
    if (!img) return SOAK_ERR_NULL;
    img->pixels = NULL;
    if (!(width >= 1 && width <= 65536 && height >= 1 && height <= 65536 && channels >= 1 && channels <= 4))
        return SOAK_ERR_ARG;
    size_t n = (size_t)width * (size_t)height * (size_t)channels;
    img->pixels = calloc(n, sizeof(float));
    if (!img->pixels) return SOAK_ERR_NOMEM;
    img->width = width;
    img->height = height;
    img->channels = channels;
    return SOAK_OK;
}

void soak_image_free(soak_image *img)
{
    if (!img) return;
    free(img->pixels);
    img->pixels = NULL;
    img->width = img->height = img->channels = 0;
}
