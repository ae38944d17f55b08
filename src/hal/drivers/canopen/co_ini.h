/* co_ini.h: a small INI reader that keeps the line of every entry, for the cia402 driver's messages. */
#ifndef CO_INI_H
#define CO_INI_H

/* Message sink: one complete line of text without the newline. */
typedef void (*co_report_fn)(void *ctx, const char *text);

/* One KEY = VALUE line. */
typedef struct {
    const char *section;   /* section name without brackets */
    char *key;
    char *value;           /* blanks and a trailing " ; comment" or " # comment" removed */
    int line;
} co_ini_entry_t;

/* One [SECTION] header. */
typedef struct {
    char *name;
    int line;
} co_ini_section_t;

/* A whole file. */
typedef struct {
    const char *path;
    co_ini_entry_t *entries;
    int count;
    co_ini_section_t *sections;
    int section_count;
    int errors;            /* lines that were neither a section, a KEY = VALUE nor a comment */
} co_ini_t;

/* Read path; returns 0 (bad lines are reported as "path:line: ..." and counted in errors, the
   rest is kept), or -1 after reporting that the file cannot be read. */
int co_ini_load(co_ini_t *ini, const char *path, co_report_fn report, void *ctx);

/* Free what co_ini_load allocated. */
void co_ini_free(co_ini_t *ini);

#endif
