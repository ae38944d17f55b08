/* halcmd.h: shared declarations of the halcmd command interpreter. */
#ifndef HALCMD_H
#define HALCMD_H

#include <stdio.h>
#include <stdint.h>

#define HC_MAX_TOKENS 32
#define HC_LINE_MAX 2048
#define HC_VARNAME_MAX 127
#define HC_PHYS_LINE_MAX (1024 * 1024)  /* longest physical line read from a file */

/* Global options and state of one halcmd run. */
typedef struct {
    const char *file;      /* name used in messages */
    int line;              /* line number used in messages */
    int keep_going;        /* -k */
    int script_mode;       /* -s */
    int quiet;             /* -Q: listings print nothing */
    int verbose;           /* -v: info messages */
    int echo;              /* -e / echo command */
    int argv_mode;         /* command given on the command line */
    int dos_warned;        /* DOS line ending warning already given */
    const char *ini_file;  /* -i */
    int comp_id;           /* halcmd's own component id */
    char progname[64];     /* halcmd<pid> */
    FILE *out;             /* command output (NULL = stdout); haltcl captures it */
    FILE *err;             /* error and warning text (NULL = stderr); haltcl captures it */
    int bare_messages;     /* messages without the "file:line: " prefix (haltcl's hal command) */
} halcmd_state_t;

extern halcmd_state_t hc;

/* Messages (halcmd_msg.c). */
void hc_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void hc_warning(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void hc_info(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void hc_out(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* Output that -Q does not silence (getp, ptype, help, echo). */
void hc_print(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* The streams commands write to: stdout/stderr unless haltcl redirected them. */
FILE *hc_stdout(void);
FILE *hc_stderr(void);

/* Line processing (halcmd_parse.c). */
int hc_strip_comment(char *line);
int hc_substitute(const char *in, char *out, size_t out_size);
int hc_tokenize(char *line, char *tokens[], int *ntokens);

/* INI lookup (halcmd_ini.c); returns malloc'd value or NULL. */
char *hc_ini_lookup(const char *file, const char *section, const char *key);
/* "LIB:name" -> $HALLIB_DIR/name (in buf); any other name is returned as it is. */
const char *hc_resolve_lib(const char *name, char *buf, size_t size);

/* One full source line through steps 2-10; returns 0 or -1. */
int hc_process_line(char *line);
/* Tokens through steps 5-10 (argv mode enters here); 1 = quit. */
int hc_run_tokens(int argc, char *argv[]);
/* Run lines from a stream; continuation enables backslash joining. */
int hc_run_stream(FILE *f, int continuation, int interactive);
/* Open a HAL file; NULL with errno set, EISDIR for a directory. */
FILE *hc_open_hal_file(const char *name);
/* A growing NUL-terminated text (zero-initialise; free text when done). */
typedef struct {
    char *text;
    size_t len, cap;
} hc_text_t;
/* Append n bytes of s; -1 (reported) when out of memory. */
int hc_text_append(hc_text_t *t, const char *s, size_t n);
/* Interactive readline loop (halcmd_interactive.c). */
int hc_run_interactive(void);

/* Command table (halcmd_table.c). */
typedef int (*hc_handler_t)(int argc, char *argv[]);
typedef struct {
    const char *name;
    hc_handler_t fn;
    int min_args, max_args;  /* max -1 = unlimited */
    int flags;
    const char *synopsis;    /* usage line shown by help */
    const char *text;        /* one-paragraph description shown by help NAME */
} hc_command_t;
#define HC_ARROWS 1   /* flag: drop arrow words (=>, <=, <=>) before counting arguments */
#define HC_TILDE 2    /* flag: expand a leading ~ in the arguments */
const hc_command_t *hc_find_command(const char *name);
const hc_command_t *hc_command_at(int i);

/* Help texts (halcmd_help.c). */
void hc_usage(void);
int hc_help_command(const char *name);
int hc_cmd_help(int argc, char *argv[]);

/* Values (halcmd_value.c). */
typedef union {
    uint8_t b;
    int32_t s32;
    uint32_t u32;
    int64_t s64;
    uint64_t u64;
    double f;
    int port;
} hc_value_t;
int hc_parse_value(int type, const char *text, hc_value_t *out);
void hc_format_value20(int type, const void *cell, char *buf, size_t size);
void hc_format_value_plain(int type, const void *cell, char *buf, size_t size);
const char *hc_type_name(int type);
const char *hc_type_name5(int type);
int hc_parse_type(const char *word);
int hc_parse_filter_type(const char *word);
void hc_format_value_script(int type, const void *cell, char *buf, size_t size);

/* Pattern matching for show/list (halcmd_show.c). */
int hc_match(char *patterns[], int npat, const char *name);

#endif
