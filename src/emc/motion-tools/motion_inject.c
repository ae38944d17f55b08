/* motion_inject.c: motion-inject, a script-driven command injector: queues motion commands and reads status (tests, no task). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "motion_client.h"
#include "motion_fields.h"

#define MAX_WORDS 64

typedef struct inject {
    emcmot_client_t *client;
    double timeout_s;
    const char *file;
    int line;
    int failed;
    int no_wait;                /* -n: push commands without waiting for their echo */
    uint32_t last_serial;
} inject_t;

/* Seconds on the monotonic clock. */
static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Sleep s seconds. */
static void sleep_s(double s)
{
    struct timespec ts = { (time_t)s, (long)((s - (time_t)s) * 1e9) };
    nanosleep(&ts, NULL);
}

/* Report a script error with file:line. */
static void script_error(inject_t *in, const char *what, const char *word)
{
    fprintf(stderr, "%s:%d: %s '%s'\n", in->file, in->line, what, word);
    in->failed = 1;
}

/* Command code from a name ("SET_LINE") or any number ("99", "-3"); 0 or -1. */
static int command_code(const char *word, int *code)
{
    char *end;
    long n = strtol(word, &end, 10);

    if (end != word && *end == '\0') {
        *code = (int)n;
        return 0;
    }
    for (int c = EMCMOT_FIRST_COMMAND; c <= EMCMOT_LAST_COMMAND; c++) {
        if (strcmp(emcmot_command_name(c), word) == 0) {
            *code = c;
            return 0;
        }
    }
    return -1;
}

/* Build a command from words: NAME field=value ...; 0 or -1. */
static int build_command(inject_t *in, char **w, int n, emcmot_command_t *cmd)
{
    int code;

    if (command_code(w[0], &code) < 0) {
        script_error(in, "unknown command", w[0]);
        return -1;
    }
    emcmot_command_init(cmd, (emcmot_command_code_t)code);
    cmd->command = code;
    for (int i = 1; i < n; i++) {
        char *eq = strchr(w[i], '=');
        motion_field_t f;
        if (!eq) {
            script_error(in, "expected field=value, got", w[i]);
            return -1;
        }
        *eq = '\0';
        if (motion_command_field(w[i], &f) < 0 || motion_field_set(cmd, &f, eq + 1) < 0) {
            script_error(in, "bad command field or value", w[i]);
            return -1;
        }
    }
    return 0;
}

/* Push, retrying while the ring is full; the serial or 0 after an error. */
static uint32_t push(inject_t *in, emcmot_command_t *cmd)
{
    double deadline = now_s() + in->timeout_s;
    long serial;

    while ((serial = emcmot_push(in->client, cmd)) == -EAGAIN && now_s() < deadline)
        sleep_s(0.0002);
    if (serial < 0) {
        fprintf(stderr, "%s:%d: push failed: %s\n", in->file, in->line, strerror((int)-serial));
        in->failed = 1;
        return 0;
    }
    in->last_serial = (uint32_t)serial;
    return (uint32_t)serial;
}

/* Print text with newlines shown as \n, then end the line. */
static void print_escaped(const char *text)
{
    for (const char *p = text; *p; p++) {
        if (*p == '\n')
            fputs("\\n", stdout);
        else
            putchar(*p);
    }
    putchar('\n');
}

/* Wait for a serial's echo and print a rejection. */
static void wait_echo(inject_t *in, uint32_t serial, const char *name)
{
    char reason[EMCMOT_REASON_LEN];
    int result = 0;
    int rc = emcmot_wait_serial(in->client, serial, in->timeout_s, &result, reason, sizeof reason);

    if (rc < 0) {
        fprintf(stderr, "%s:%d: no echo for %s: %s\n", in->file, in->line, name, strerror(-rc));
        in->failed = 1;
        return;
    }
    if (result != EMCMOT_COMMAND_OK) {
        printf("%s: %s: ", name, emcmot_result_name(result));
        print_escaped(reason);
    }
}

/* Copy words with "%i" in a value replaced by index (fill numbers its commands). */
static int numbered_words(char **w, int n, long index, char buf[][128], char **out)
{
    for (int i = 0; i < n && i < MAX_WORDS; i++) {
        char *mark = strstr(w[i], "%i");
        if (mark)
            snprintf(buf[i], 128, "%.*s%ld%s", (int)(mark - w[i]), w[i], index, mark + 2);
        else
            snprintf(buf[i], 128, "%s", w[i]);
        out[i] = buf[i];
    }
    return n;
}

/* "fill N NAME fields": push N commands without waiting ("%i" in a value becomes 0..N-1),
 * stop when the ring is full. */
static void do_fill(inject_t *in, char **w, int n)
{
    static char buf[MAX_WORDS][128];
    char *words[MAX_WORDS];
    emcmot_command_t cmd;
    long count = n > 1 ? strtol(w[1], NULL, 10) : 0, queued = 0;

    if (n < 3)
        return;
    for (; queued < count; queued++) {
        numbered_words(w + 2, n - 2, queued, buf, words);
        if (build_command(in, words, n - 2, &cmd) < 0)
            return;
        long serial = emcmot_push(in->client, &cmd);
        if (serial < 0)
            break;
        in->last_serial = (uint32_t)serial;
    }
    printf("fill: %ld of %ld queued%s\n", queued, count, queued < count ? ", ring full" : "");
}

/* Current status, or exit when it cannot be read. */
static const emcmot_status_t *status(inject_t *in)
{
    static emcmot_status_t st;
    int rc = emcmot_read_status(in->client, &st);

    if (rc < 0) {
        fprintf(stderr, "%s:%d: status: %s\n", in->file, in->line, strerror(-rc));
        exit(1);
    }
    return &st;
}

/* Print one status field. */
static void print_field(inject_t *in, const emcmot_status_t *st, const char *name)
{
    motion_field_t f;

    if (motion_status_field(name, &f) < 0) {
        script_error(in, "unknown status field", name);
        return;
    }
    double v = motion_field_get(st, &f);
    if (f.type == MF_DOUBLE)
        printf("%s=%.6f\n", name, fabs(v) < 5e-7 ? 0.0 : v);
    else
        printf("%s=%.0f\n", name, v);
}

/* Compare a value with op. */
static int compare(double v, const char *op, double want)
{
    if (!strcmp(op, "=="))
        return fabs(v - want) <= 1e-9 * fmax(1.0, fabs(want));
    if (!strcmp(op, "!="))
        return fabs(v - want) > 1e-9 * fmax(1.0, fabs(want));
    if (!strcmp(op, "<"))
        return v < want;
    if (!strcmp(op, ">"))
        return v > want;
    if (!strcmp(op, "<="))
        return v <= want;
    return !strcmp(op, ">=") && v >= want;
}

/* "wait FIELD OP VALUE [TIMEOUT]": poll until it holds. */
static void do_wait(inject_t *in, char **w, int n)
{
    motion_field_t f;
    double timeout = n > 4 ? atof(w[4]) : in->timeout_s, deadline = now_s() + timeout, v = 0;

    if (n < 4 || motion_status_field(w[1], &f) < 0) {
        script_error(in, "usage: wait FIELD OP VALUE [TIMEOUT], field", n > 1 ? w[1] : "");
        return;
    }
    while (now_s() < deadline) {
        v = motion_field_get(status(in), &f);
        if (compare(v, w[2], atof(w[3])))
            return;
        sleep_s(0.0005);
    }
    printf("timeout: %s=%.6g, wanted %s %s\n", w[1], v, w[2], w[3]);
    in->failed = 1;
}

/* "cycles N": wait for N servo cycles. */
static void do_cycles(inject_t *in, long count)
{
    uint32_t start = status(in)->heartbeat;
    double deadline = now_s() + in->timeout_s + count * 0.01;

    while ((uint32_t)(status(in)->heartbeat - start) < (uint32_t)count && now_s() < deadline)
        sleep_s(0.0005);
}

/* "messages": print every queued operator message (newlines shown as \n). */
static void do_messages(inject_t *in)
{
    char text[EMCMOT_ERROR_LEN];
    int kind;

    while (emcmot_pop_error(in->client, text, sizeof text, &kind) == 1) {
        printf("message: ");
        print_escaped(text);
    }
}

/* "sh WORDS...": run a shell command (halcmd setp ...); its output goes to ours. */
static void do_shell(inject_t *in, char **w, int n)
{
    char cmd[4096] = "";

    for (int i = 1; i < n; i++) {
        strncat(cmd, w[i], sizeof cmd - strlen(cmd) - 2);
        strcat(cmd, " ");
    }
    fflush(stdout);
    if (system(cmd) != 0) {
        fprintf(stderr, "%s:%d: command failed: %s\n", in->file, in->line, cmd);
        in->failed = 1;
    }
}

/* One script line. */
static void run_line(inject_t *in, char **w, int n)
{
    emcmot_command_t cmd;

    if (!strcmp(w[0], "status")) {
        const emcmot_status_t *st = status(in);
        for (int i = 1; i < n; i++)
            print_field(in, st, w[i]);
    } else if (!strcmp(w[0], "wait")) {
        do_wait(in, w, n);
    } else if (!strcmp(w[0], "cycles")) {
        do_cycles(in, n > 1 ? strtol(w[1], NULL, 10) : 1);
    } else if (!strcmp(w[0], "sleep")) {
        sleep_s(n > 1 ? atof(w[1]) : 0.1);
    } else if (!strcmp(w[0], "messages")) {
        do_messages(in);
    } else if (!strcmp(w[0], "echo")) {
        for (int i = 1; i < n; i++)
            printf("%s%s", w[i], i + 1 < n ? " " : "\n");
    } else if (!strcmp(w[0], "sh")) {
        do_shell(in, w, n);
    } else if (!strcmp(w[0], "fill")) {
        do_fill(in, w, n);
    } else if (!strcmp(w[0], "sync")) {
        if (in->last_serial)
            wait_echo(in, in->last_serial, "sync");
    } else if (!strcmp(w[0], "push")) {
        if (n > 1 && build_command(in, w + 1, n - 1, &cmd) == 0)
            push(in, &cmd);
    } else if (build_command(in, w, n, &cmd) == 0) {
        uint32_t serial = push(in, &cmd);
        if (serial && !in->no_wait)
            wait_echo(in, serial, w[0]);
    }
    fflush(stdout);
}

/* Split a line into words; comments start with '#'. */
static int split(char *line, char **w)
{
    int n = 0;
    char *hash = strchr(line, '#');

    if (hash)
        *hash = '\0';
    for (char *t = strtok(line, " \t\r\n"); t && n < MAX_WORDS; t = strtok(NULL, " \t\r\n"))
        w[n++] = t;
    return n;
}

/* Attach as the producer, waiting up to the timeout for motion to appear. */
static int attach(inject_t *in, int key)
{
    char why[256];
    double deadline = now_s() + in->timeout_s;
    int rc;

    while ((rc = emcmot_attach(key, EMCMOT_ATTACH_PRODUCER, &in->client, why, sizeof why)) < 0 &&
           rc != -EBUSY && now_s() < deadline)
        sleep_s(0.05);
    if (rc < 0)
        fprintf(stderr, "motion-inject: %s\n", why);
    return rc;
}

/* Run every line of one script ("-" = standard input). */
static void run_file(inject_t *in, const char *path)
{
    char line[4096], *w[MAX_WORDS];
    FILE *f = stdin;

    in->file = path;
    in->line = 0;
    if (strcmp(path, "-") != 0 && !(f = fopen(path, "r"))) {
        fprintf(stderr, "motion-inject: %s: %s\n", path, strerror(errno));
        in->failed = 1;
        return;
    }
    while (fgets(line, sizeof line, f)) {
        int n;
        in->line++;
        n = split(line, w);
        if (n > 0)
            run_line(in, w, n);
    }
    if (f != stdin)
        fclose(f);
}

int main(int argc, char **argv)
{
    inject_t in = { NULL, 5.0, "-", 0, 0, 0, 0 };
    int key = EMCMOT_SHM_DEFAULT_KEY, opt;

    if (argc == 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        printf("%s\n", "Usage: motion-inject [-n] [-k SHMEM_KEY] [-t TIMEOUT_S] [SCRIPT...]");
        return 0;
    }
    while ((opt = getopt(argc, argv, "nk:t:")) != -1) {
        if (opt == 'n')
            in.no_wait = 1;
        else if (opt == 'k')
            key = atoi(optarg);
        else if (opt == 't')
            in.timeout_s = atof(optarg);
        else {
            fprintf(stderr, "usage: motion-inject [-n] [-k SHMEM_KEY] [-t TIMEOUT_S] [SCRIPT...]\n");
            return 2;
        }
    }
    if (attach(&in, key) < 0)
        return 1;
    if (optind == argc)
        run_file(&in, "-");
    for (int i = optind; i < argc; i++)
        run_file(&in, argv[i]);
    emcmot_detach(in.client);
    return in.failed ? 1 : 0;
}
