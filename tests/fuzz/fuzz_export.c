/* `soak export`: byte 0 picks the target (json povray blender osl ...), the
 * rest is the preset file. A file the loader accepts must export (every
 * target computes from presets the loader validated) without a NaN or
 * infinity in the output text; every failure sets a message. Finding of the
 * first replay: --target osl-sheet on a file without a thin_sheet preset
 * failed with "argument out of range (or NaN/Inf)" (corpus/export seeds). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "soak/export.h"
#include "soak/preset.h"

/* No "nan" or "inf" as a printed number: either one means a non-finite value
 * reached a writer. */
static void check_numbers(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) abort();
    char buf[1 << 16];
    size_t n;
    char prev = ' ';
    while ((n = fread(buf, 1, sizeof buf - 1, f)) > 0) {
        buf[n] = '\0';
        for (size_t i = 0; i + 3 <= n; ++i) {
            char before = i ? buf[i - 1] : prev;
            int word_start = !(before >= 'a' && before <= 'z') && !(before >= 'A' && before <= 'Z') && before != '_';
            if (word_start && (!strncmp(buf + i, "nan", 3) || !strncmp(buf + i, "inf", 3)) &&
                (i + 3 == n || !((buf[i + 3] >= 'a' && buf[i + 3] <= 'z') || buf[i + 3] == '_')))
                abort();
        }
        prev = buf[n - 1];
    }
    fclose(f);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || size > 1 << 16) return 0;
    int count = 0;
    const soak_export_target *targets = soak_export_targets(&count);
    const soak_export_target *t = &targets[data[0] % count];
    const char *in = fuzz_temp_named("materials.json", data + 1, size - 1);
    if (!in) return 0;
    soak_preset_db *db = NULL;
    char err[1024] = "";
    if (soak_presets_load(in, &db, err, sizeof err) != SOAK_OK) {
        fuzz_check_message(err, in, NULL);
        return 0;
    }
    char out[512];
    snprintf(out, sizeof out, "%s/out.export", fuzz_temp_dir());
    err[0] = '\0';
    soak_status st = soak_export_run(t, db, out, err, sizeof err);
    soak_presets_free(db);
    /* Presets the loader accepted are in range: the export must succeed,
     * unless the file lacks the class of preset a target needs (a thin sheet
     * for osl-sheet), which the message then says, naming the file. */
    if (st != SOAK_OK) {
        if (!strstr(err, "materials.json holds no")) {
            fprintf(stderr, "export --target %s failed on accepted presets: %s\n", t->name, err);
            abort();
        }
        fuzz_check_message(err, "materials.json", NULL);
        return 0;
    }
    check_numbers(out);
    remove(out);
    return 0;
}
