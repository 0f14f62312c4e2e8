/* The one rule for a number read from a JSON file soak loads (the preset file
 * `materials.json`, scene files): a JSON number, finite (cJSON reads 1e999 as
 * inf), inside [lo, hi] — or (lo, hi] with lo_open, for quantities that must
 * be positive. Each loader adds its file and the value's path to the phrase
 * written to `why` ("must be in [0, 1], got 1.5"), so presets and scenes word
 * the same mistake the same way. */
#ifndef SOAK_JSON_NUMBER_H
#define SOAK_JSON_NUMBER_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "soak/status.h"

/* SOAK_OK with *out set, or SOAK_ERR_PARSE (not a number) / SOAK_ERR_ARG (not
 * finite, out of range) with *out untouched and the reason in why. */
soak_status soak_json_number(const cJSON *v, double lo, double hi, int lo_open, double *out, char *why,
                             size_t why_len);

#endif
