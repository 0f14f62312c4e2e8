/* `soak report`'s two outputs written together through one staged set
 * (soak/staged.h): both files replace the old ones, or neither does. */
#include <stdio.h>

#include "report_internal.h"
#include "soak/staged.h"

soak_status soak_report_write(const soak_report *r, const char *json_path, const char *markdown_path, char *err,
                              size_t errlen)
{
    if (!r || !json_path || !markdown_path) return SOAK_ERR_NULL;
    soak_staged st;
    FILE *fj = NULL, *fm = NULL;
    char msg[1024];
    soak_status rc;
    soak_staged_init(&st);
    if ((rc = soak_staged_open(&st, json_path, &fj, msg, sizeof msg)) != SOAK_OK ||
        (rc = soak_staged_open(&st, markdown_path, &fm, msg, sizeof msg)) != SOAK_OK) {
        if (fj) fclose(fj);
        soak_staged_abort(&st);
        if (err && errlen) snprintf(err, errlen, "%s", msg);
        return rc;
    }
    report_write_json(fj, r);
    report_write_markdown(fm, r);
    soak_status s1 = soak_staged_close(fj, json_path, msg, sizeof msg);
    soak_status s2 = soak_staged_close(fm, markdown_path, s1 == SOAK_OK ? msg : msg + 512, 512);
    rc = s1 != SOAK_OK ? s1 : s2;
    if (rc == SOAK_OK) rc = soak_staged_commit(&st, msg, sizeof msg);
    else soak_staged_abort(&st);
    if (rc != SOAK_OK && err && errlen) snprintf(err, errlen, "%s", msg);
    return rc;
}
