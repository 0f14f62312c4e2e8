/* The reproducible header every export writer opens with: generator, format
 * version and a fingerprint of the preset file. Its own file so that the
 * writers depend on it without depending on the table that dispatches to
 * them (export.c). */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "soak/export.h"

/* FNV-1a, 64 bit: a content fingerprint, not a security hash. */
static uint64_t fnv1a64(const unsigned char *p, size_t n, uint64_t h)
{
    for (size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ULL;
    }
    return h;
}

soak_status soak_export_header_make(const soak_preset_db *db, soak_export_header *h)
{
    if (!db || !h) return SOAK_ERR_NULL;
    memset(h, 0, sizeof *h);
    h->generator = SOAK_EXPORT_GENERATOR;
    h->format_version = SOAK_EXPORT_FORMAT_VERSION;
    const char *path = soak_presets_path(db);
    const char *slash = strrchr(path, '/');
    snprintf(h->materials_file, sizeof h->materials_file, "%s", slash ? slash + 1 : path);
    FILE *f = fopen(path, "rb");
    if (!f) return SOAK_ERR_IO;
    uint64_t hash = 0xcbf29ce484222325ULL;
    unsigned char buf[8192];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0) hash = fnv1a64(buf, n, hash);
    int bad = ferror(f);
    fclose(f);
    if (bad) return SOAK_ERR_IO;
    snprintf(h->materials_hash, sizeof h->materials_hash, "%016llx", (unsigned long long)hash);
    return SOAK_OK;
}

soak_status soak_export_begin(const soak_preset_db *db, FILE *out, char *err, size_t errlen, soak_export_header *h)
{
    if (!db || !out || !err || !errlen || !h) return SOAK_ERR_NULL;
    soak_status st = soak_export_header_make(db, h);
    if (st != SOAK_OK) snprintf(err, errlen, "%s: cannot read the preset file to hash it", soak_presets_path(db));
    return st;
}
