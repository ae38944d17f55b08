/* lookup.c: a C program built against the installed inifile.h: prints one typed value per call. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include <inifile.h>

/* The text of a negative return code. */
static const char *code_text(int rc)
{
    return rc == -EINVAL ? "EINVAL" : rc == -ENOENT ? "ENOENT" : rc == -ENOSPC ? "ENOSPC" : "?";
}

/* Look up argv[3] (section argv[4], "-" for any) of file argv[1] as type argv[2]. */
int main(int argc, char **argv)
{
    char buf[INI_MAX_LINELEN];
    rtapi_s64 s = 0;
    rtapi_u64 u = 0;
    double r = 0;
    bool b = false;
    int n = 0, rc = -EINVAL;
    if (argc != 5) return 1;
    const char *sec = strcmp(argv[4], "-") == 0 ? NULL : argv[4];
    switch (argv[2][0]) {
    case 's': rc = iniFindString(argv[1], argv[3], sec, buf, 8); break;
    case 'i': rc = iniFindSInt(argv[1], argv[3], sec, &s); snprintf(buf, sizeof buf, "%lld", (long long)s); break;
    case 'u': rc = iniFindUInt(argv[1], argv[3], sec, &u); snprintf(buf, sizeof buf, "%llu", (unsigned long long)u); break;
    case 'r': rc = iniFindDouble(argv[1], argv[3], sec, &r); snprintf(buf, sizeof buf, "%.15g", r); break;
    case 'b': rc = iniFindBool(argv[1], argv[3], sec, &b); snprintf(buf, sizeof buf, "%s", b ? "true" : "false"); break;
    case 'n': rc = iniFindInt(argv[1], argv[3], sec, &n); snprintf(buf, sizeof buf, "%d", n); break;
    }
    if (rc == 0)
        printf("%s\n", buf);
    else
        printf("%s\n", code_text(rc));
    return rc == 0 ? 0 : 2;
}
