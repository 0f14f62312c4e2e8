/* soak/json_writer.h, the one JSON writer of the exports, against texts
 * written out by hand: rounding to the stated significant digits (digits 0:
 * cJSON's 15), the zero threshold (no "-0"), integers never
 * rounded, strings escaped, NULL keys appending to arrays, and one failure
 * (a NULL parent) clearing ok so that printing refuses. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "soak/json_writer.h"

static int check_text(const char *what, const soak_json *j, const cJSON *root, const char *want)
{
    char *text = NULL;
    soak_status st = soak_json_print(j, root, &text);
    int ok = check_status(what, st, SOAK_OK) && text && strcmp(text, want) == 0;
    if (!ok) printf("     got  %s\n     want %s\n", text ? text : "(null)", want);
    free(text);
    return check_true(what, ok);
}

static void test_rounding(void)
{
    soak_json j = soak_json_writer(6, 5e-13);
    check_close("6 digits", soak_json_round(&j, 0.12345678), 0.123457, 0.0);
    check_close("6 digits, large", soak_json_round(&j, 1234567.0), 1234570.0, 0.0);
    check_close("below zero_below: 0", soak_json_round(&j, -4e-13), 0.0, 0.0);
    check_close("at zero_below: kept", soak_json_round(&j, 5e-13), 5e-13, 0.0);
    soak_json raw = soak_json_writer(0, 0.0);
    check_true("digits 0: the double itself", soak_json_round(&raw, 0.1 + 0.2) == 0.1 + 0.2);
    check_close("digits 0: 13 digits kept", soak_json_round(&raw, 0.1234567890123), 0.1234567890123, 0.0);
    soak_json seven = soak_json_writer(7, 0.0);
    check_close("7 digits", soak_json_round(&seven, 2.0 / 3.0), 0.6666667, 0.0);

    cJSON *root = cJSON_CreateObject();
    soak_json_num(&j, root, "a", 0.12345678);
    soak_json_num(&j, root, "tiny", -1e-14);
    soak_json_num(&j, root, "neg_zero", -0.0);
    soak_json_int(&j, root, "n", 1234567);
    cJSON *arr = soak_json_array(&j, root, "v");
    soak_json_num(&j, arr, NULL, 1e-9);
    soak_json_str(&j, arr, NULL, "q\"\\\n");
    soak_json_bool(&j, arr, NULL, 1);
    soak_json_rgb(&j, root, "c", (soak_rgb){0.25, 1.0 / 3.0, 2.0});
    soak_json_num(&raw, root, "raw", 0.1234567890123);
    check_text("formatted text", &j, root,
               "{\n\t\"a\":\t0.123457,\n\t\"tiny\":\t0,\n\t\"neg_zero\":\t0,\n\t\"n\":\t1234567,\n"
               "\t\"v\":\t[1e-09, \"q\\\"\\\\\\n\", true],\n\t\"c\":\t[0.25, 0.333333, 2],\n"
               "\t\"raw\":\t0.1234567890123\n}");
    cJSON_Delete(root);
}

static void test_failure(void)
{
    soak_json j = soak_json_writer(6, 0.0);
    cJSON *root = cJSON_CreateObject();
    soak_json_num(&j, root, "a", 1.0);
    check_true("ok after additions", j.ok);
    check_true("a NULL parent returns NULL", soak_json_array(&j, NULL, "lost") == NULL);
    check_true("... and clears ok", !j.ok);
    char *text = NULL;
    check_status("print refuses a failed tree", soak_json_print(&j, root, &text), SOAK_ERR_NOMEM);
    check_true("... and returns no text", text == NULL);
    FILE *f = tmpfile();
    if (f) {
        check_status("write refuses it too", soak_json_write(&j, root, f), SOAK_ERR_NOMEM);
        fclose(f);
    }
    cJSON_Delete(root);
}

static void test_write(void)
{
    soak_json j = soak_json_writer(7, 0.0);
    cJSON *root = cJSON_CreateObject();
    soak_json_num(&j, root, "x", 1.0 / 7.0);
    FILE *f = tmpfile();
    if (!f) {
        check_skip("write to a file", "tmpfile() failed");
        cJSON_Delete(root);
        return;
    }
    check_status("write", soak_json_write(&j, root, f), SOAK_OK);
    char buf[64] = {0};
    rewind(f);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    check_true("written text ends in a newline", n > 0 && strcmp(buf, "{\n\t\"x\":\t0.1428571\n}\n") == 0);
    cJSON_Delete(root);
}

int main(void)
{
    test_rounding();
    test_failure();
    test_write();
    return check_finish();
}
