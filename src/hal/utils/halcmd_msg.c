/* halcmd_msg.c: error, warning and info messages with the file:line: prefix. */
#include <stdarg.h>
#include <stdio.h>
#include "halcmd.h"

/* Print "file:line: " followed by the formatted text to a stream. */
static void hc_vmsg(FILE *out, const char *kind, const char *fmt, va_list ap)
{
    fflush(stdout);
    fprintf(out, "%s:%d: %s", hc.file ? hc.file : "<commandline>", hc.line, kind);
    vfprintf(out, fmt, ap);
    fputc('\n', out);
    fflush(out);
}

/* Report an error of the current line on stderr. */
void hc_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    hc_vmsg(stderr, "", fmt, ap);
    va_end(ap);
}

/* Report a warning of the current line on stderr. */
void hc_warning(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    hc_vmsg(stderr, "Warning: ", fmt, ap);
    va_end(ap);
}

/* Report an info message on stdout when -v was given. */
void hc_info(const char *fmt, ...)
{
    va_list ap;
    if (!hc.verbose)
        return;
    va_start(ap, fmt);
    hc_vmsg(stdout, "", fmt, ap);
    va_end(ap);
}

/* Print listing output unless -Q silenced it. */
void hc_out(const char *fmt, ...)
{
    va_list ap;
    if (hc.quiet)
        return;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}
