/* The string escapes of generated sources (soak/export_escape.h, issue 51
 * item 2) against two independent references:
 *  - the languages' escape rules, written out by hand for quotes, newlines,
 *    '#', backslashes, directive text and non-UTF-8 bytes;
 *  - the languages' own readers: python3, node and povray parse a literal
 *    made from every ASCII byte (and UTF-8 text for Python and JavaScript)
 *    and write back exactly the input; a POV-Ray include with directive text
 *    in its literal writes no file. A missing reader is a skip. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "soak/export_escape.h"

typedef soak_status (*escape_fn)(const char *, char *, size_t);

static void expect(const char *lang, escape_fn fn, const char *in, const char *want)
{
    char out[256], what[160];
    soak_status st = fn(in, out, sizeof out);
    snprintf(what, sizeof what, "%s escape of a %zu-byte case", lang, strlen(in));
    if (check_status(what, st, SOAK_OK) && !check_true(what, strcmp(out, want) == 0))
        fprintf(stderr, "  got  [%s]\n  want [%s]\n", out, want);
}

static void test_rules(void)
{
    const char *directive = "x\";#fopen P \"pwned.txt\" write #declare Z=\"y";
    expect("povray", soak_escape_povray, directive, "x\\\";#fopen P \\\"pwned.txt\\\" write #declare Z=\\\"y");
    expect("povray", soak_escape_povray, "a\\b\nc\x7f", "a\\\\b\\u000Ac\\u007F");
    expect("povray", soak_escape_povray, "caf\xc3\xa9", "caf\xc3\xa9");
    expect("osl", soak_escape_osl, "m.json\n#define Wetness 0\n", "m.json\\n#define Wetness 0\\n");
    expect("osl", soak_escape_osl, "q\"\\\t\x01*/", "q\\\"\\\\\\t\\001*/");
    expect("python", soak_escape_python, "a'\"\\\n\r\t\x1b", "a\\'\\\"\\\\\\n\\r\\t\\x1b");
    expect("javascript", soak_escape_javascript, "a'\"\\\n\x1b\xe2\x80\xa8</script>",
           "a\\'\\\"\\\\\\n\\u001B\\u2028</script>");
    char out[64];
    check_status("python refuses a lone 0xff", soak_escape_python("a\xff", out, sizeof out), SOAK_ERR_ARG);
    check_status("javascript refuses an overlong '/'", soak_escape_javascript("\xc0\xaf", out, sizeof out),
                 SOAK_ERR_ARG);
    check_status("python refuses a surrogate", soak_escape_python("\xed\xa0\x80", out, sizeof out), SOAK_ERR_ARG);
    check_status("too small a buffer", soak_escape_povray("\"\"\"", out, 6), SOAK_ERR_NOMEM);
    check_true("a failure leaves an empty string", out[0] == '\0');
    char big[SOAK_ESCAPE_SIZE(4)];
    check_status("SOAK_ESCAPE_SIZE suffices", soak_escape_povray("\x01\x02\x03\x04", big, sizeof big), SOAK_OK);
}

static int on_path(const char *tool)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "command -v %s >/dev/null 2>&1", tool);
    return system(cmd) == 0;
}

/* Writes program to dir/name, runs command there and compares what the
 * reader wrote to dir/out.bin with want. */
static void run_reader(const char *what, const char *dir, const char *name, const char *program, const char *command,
                       const char *want)
{
    char path[512], cmd[1024], got[1024] = "";
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (!check_true(what, f != NULL)) return;
    fputs(program, f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "cd '%s' && rm -f out.bin && %s >/dev/null 2>&1", dir, command);
    int rc = system(cmd);
    snprintf(path, sizeof path, "%s/out.bin", dir);
    f = fopen(path, "rb");
    size_t n = f ? fread(got, 1, sizeof got - 1, f) : 0;
    if (f) fclose(f);
    got[n] = '\0';
    char label[256];
    snprintf(label, sizeof label, "%s: the reader (exit %d) gives back the %zu input bytes", what, rc, strlen(want));
    check_true(label, n == strlen(want) && memcmp(got, want, n) == 0);
}

static void ascii_bytes(char *s)
{
    for (int c = 1; c < 128; ++c) s[c - 1] = (char)c;
    s[127] = '\0';
}

static void test_readers(const char *dir)
{
    char ascii[128], lit[SOAK_ESCAPE_SIZE(160)], program[2048];
    ascii_bytes(ascii);
    char text[160];
    snprintf(text, sizeof text, "%s\xc3\xa9\xe2\x80\xa8\xf0\x9f\x92\xa7", ascii);
    if (on_path("python3")) {
        soak_escape_python(text, lit, sizeof lit);
        snprintf(program, sizeof program, "s = \"%s\"\nopen('out.bin', 'wb').write(s.encode('utf-8'))\n", lit);
        run_reader("python3", dir, "t.py", program, "python3 t.py", text);
    } else check_skip("python3 round trip", "python3 not on PATH");
    if (on_path("node")) {
        soak_escape_javascript(text, lit, sizeof lit);
        snprintf(program, sizeof program,
                 "const s = \"%s\";\nrequire('fs').writeFileSync('out.bin', Buffer.from(s, 'utf8'));\n", lit);
        run_reader("node", dir, "t.js", program, "node t.js", text);
    } else check_skip("node round trip", "node not on PATH");
    if (on_path("povray")) {
        /* POV-Ray's #write turns "\n" into the platform's line end and stops
         * at nothing else: printable ASCII, quotes and backslashes included. */
        const char *pov_text = "x\";#fopen P \"pwned.txt\" write #write(P,\"y\") #fclose P #declare Z=\"\\y";
        soak_escape_povray(pov_text, lit, sizeof lit);
        snprintf(program, sizeof program,
                 "#version 3.7;\n#declare S = \"%s\";\n#fopen F \"out.bin\" write\n#write (F, S)\n#fclose F\n", lit);
        run_reader("povray", dir, "t.pov", program, "povray +It.pov -D +W8 +H8 -GA +O/dev/null", pov_text);
        char pwned[512];
        snprintf(pwned, sizeof pwned, "%s/pwned.txt", dir);
        check_true("povray: directive text inside the literal wrote no file", access(pwned, F_OK) != 0);
    } else check_skip("povray round trip", "povray not on PATH");
}

int main(void)
{
    test_rules();
    char dir[] = "/tmp/soak_escape_XXXXXX";
    if (!mkdtemp(dir)) return 1;
    test_readers(dir);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
    return check_finish();
}
