/* soak/json_number.h, the number rule shared by the preset and scene loaders,
 * against JSON texts written by hand: every JSON type that is not a number is
 * refused by name, cJSON's overflow to infinity is refused, both bounds are
 * inclusive (or the lower one exclusive), and a refused value leaves *out as
 * it was. */
#include <string.h>

#include "check.h"
#include "soak/json_number.h"

static soak_status read_text(const char *text, double lo, double hi, int lo_open, double *out, char *why)
{
    cJSON *v = cJSON_Parse(text);
    soak_status st = soak_json_number(v, lo, hi, lo_open, out, why, 128);
    cJSON_Delete(v);
    return st;
}

static void expect_refused(const char *text, int lo_open, soak_status want, const char *phrase)
{
    double out = -7.0;
    char why[128] = "";
    soak_status st = read_text(text, 0.0, 1.0, lo_open, &out, why);
    check_status(text, st, want);
    check_true(phrase, strstr(why, phrase) != NULL);
    check_close("refused: out untouched", out, -7.0, 0.0);
}

int main(void)
{
    double out = 0.0;
    char why[128];
    check_status("0.25 in [0, 1]", read_text("0.25", 0.0, 1.0, 0, &out, why), SOAK_OK);
    check_close("0.25 read", out, 0.25, 0.0);
    check_status("lower bound inclusive", read_text("0", 0.0, 1.0, 0, &out, why), SOAK_OK);
    check_status("upper bound inclusive", read_text("1", 0.0, 1.0, 0, &out, why), SOAK_OK);
    check_status("open lower bound: just above", read_text("1e-300", 0.0, 1.0, 1, &out, why), SOAK_OK);

    expect_refused("\"0.5\"", 0, SOAK_ERR_PARSE, "got a string");
    expect_refused("true", 0, SOAK_ERR_PARSE, "got a boolean");
    expect_refused("null", 0, SOAK_ERR_PARSE, "got null");
    expect_refused("[0.5]", 0, SOAK_ERR_PARSE, "got an array");
    expect_refused("{}", 0, SOAK_ERR_PARSE, "got an object");
    expect_refused("1e999", 0, SOAK_ERR_ARG, "must be a finite number");
    expect_refused("-1e999", 0, SOAK_ERR_ARG, "must be a finite number");
    expect_refused("1.5", 0, SOAK_ERR_ARG, "must be in [0, 1], got 1.5");
    expect_refused("-0.001", 0, SOAK_ERR_ARG, "got -0.001");
    expect_refused("0", 1, SOAK_ERR_ARG, "must be > 0 and <= 1, got 0");

    out = -7.0;
    check_status("missing value (NULL)", soak_json_number(NULL, 0.0, 1.0, 0, &out, why, sizeof why), SOAK_ERR_PARSE);
    check_true("missing value named", strstr(why, "got nothing") != NULL);
    return check_finish();
}
