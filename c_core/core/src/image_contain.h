/* soak_image_read's decoding step, in a child process with a time limit
 * (image_contain.c). */
#ifndef SOAK_IMAGE_CONTAIN_H
#define SOAK_IMAGE_CONTAIN_H

#include "image_plugin.h"

/* Decodes path through p->read_to in a child into img (allocated here,
 * soak_image_free frees it); a hang past the limit (SOAK_IMAGE_TIMEOUT,
 * else 10 s + 1 s per MiB of payload), a crash or the reader's own refusal
 * is an error naming the file. */
soak_status soak_image_read_contained(const soak_image_plugin *p, const char *path, long long payload,
                                      soak_image *img, char *err, size_t errlen);

#endif
