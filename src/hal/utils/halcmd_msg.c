/* halcmd_msg.c: error, warning and info messages with the file:line: prefix. */
#include <stdarg.h>
#include <stdio.h>
#include "halcmd.h"

halcmd_state_t hc;

/* The stream command output goes to. */
FILE *hc_stdout(void)
{
    return hc.out ? hc.out : stdout;
}

/* The stream errors and warnings go to. */
FILE *hc_stderr(void)
{
    return hc.err ? hc.err : stderr;
}

/* Print "file:line: " followed by the formatted text to a stream. */
static void hc_vmsg(FILE *out, const char *kind, const char *fmt, va_list ap)
{
    fflush(hc_stdout());
    if (hc.bare_messages)
        fputs(kind, out);
    else
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
    hc_vmsg(hc_stderr(), "", fmt, ap);
    va_end(ap);
}

/* Report a warning of the current line on stderr. */
void hc_warning(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    hc_vmsg(hc_stderr(), "Warning: ", fmt, ap);
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
    vfprintf(hc_stdout(), fmt, ap);
    va_end(ap);
}

/* Print output that -Q leaves alone. */
void hc_print(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(hc_stdout(), fmt, ap);
    va_end(ap);
}
