/* halstreamer.c: user program that feeds text lines into a streamer stream as records. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rtapi.h"
#include "hal.h"
#include "sampling_cli.h"

/* Parses an integer field of `type` at cp into d; returns end pointer (cp on failure). */
static const char *parse_integer(const char *cp, hal_type_t type, union hal_stream_data *d)
{
    char *end;
    switch (type) {
    case HAL_S32: d->s = (int32_t)strtol(cp, &end, 10); break;
    case HAL_U32: d->u = (uint32_t)strtoul(cp, &end, 10); break;
    case HAL_S64: d->l = (int64_t)strtoll(cp, &end, 10); break;
    default: d->k = (uint64_t)strtoull(cp, &end, 10); break;
    }
    return end;
}

/* Parses one field at *cpp; NULL on success or the error text. */
static const char *parse_field(const char **cpp, hal_type_t type, union hal_stream_data *d)
{
    const char *cp = *cpp, *end;
    char *fend;

    while (*cp == ' ' || *cp == '\t') {
        cp++;
    }
    if (*cp == '\0' || *cp == '\n') {
        return "premature end of line";
    }
    if (type == HAL_BIT) {
        if (*cp != '0' && *cp != '1') {
            return "bit value not 0 or 1";
        }
        d->b = *cp == '1';
        end = cp + 1;
    } else if (type == HAL_FLOAT) {
        d->f = strtod(cp, &fend);
        end = fend;
    } else {
        end = parse_integer(cp, type, d);
    }
    if (end == cp || !isspace((unsigned char)*end)) {
        return "bad character";
    }
    *cpp = end;
    return NULL;
}

/* Parses a whole line into rec; prints the error and returns -1 when bad. */
static int parse_line(const char *line, long lineno, hal_stream_t *stream,
                      union hal_stream_data *rec)
{
    int n, count = hal_stream_element_count(stream);
    const char *cp = line, *err;

    for (n = 0; n < count; n++) {
        err = parse_field(&cp, hal_stream_element_type(stream, n), &rec[n]);
        if (err != NULL) {
            fprintf(stderr, "line %ld, field %d: %s, skipping the line\n", lineno, n, err);
            return -1;
        }
    }
    return 0;
}

/* Writes a record, waiting while the FIFO is full; -1 if interrupted. */
static int write_record(hal_stream_t *stream, union hal_stream_data *rec)
{
    while (!hal_stream_writable(stream)) {
        if (sampling_stop) {
            return -1;
        }
        sampling_poll_sleep();
    }
    return hal_stream_write(stream, rec) < 0 ? -1 : 0;
}

/* Reads every line of in and streams the good ones. */
static void stream_loop(FILE *in, hal_stream_t *stream)
{
    union hal_stream_data rec[SAMPLING_MAX_FIELDS];
    char *line = NULL;
    size_t cap = 0;
    long lineno;

    for (lineno = 0; !sampling_stop && getline(&line, &cap, in) >= 0; lineno++) {
        if (line[0] == '#') {
            continue;
        }
        if (parse_line(line, lineno, stream, rec) < 0) {
            continue;
        }
        if (write_record(stream, rec) < 0) {
            break;
        }
    }
    free(line);
}

static const char usage_text[] =
    "Usage: halstreamer [-c CHAN] [-N NAME] [FILE]\n"
    "Feeds lines of numbers from FILE or standard input to the realtime 'streamer' channel\n"
    "CHAN (default 0), one line per sample.\n"
    "  -c CHAN   streamer channel 0..7\n"
    "  -N NAME   HAL component name (default halstreamerCHAN)\n"
    "  --help    this text\n";

/* Entry point: parse options, attach, stream the input, clean up. */
int main(int argc, char **argv)
{
    sampling_opts_t opts;
    hal_stream_t stream;
    FILE *in = stdin;
    int comp_id;

    int rc = sampling_parse_args(argc, argv, "cN", usage_text, &opts);
    if (rc != 0) {
        return rc < 0 ? 1 : 0;
    }
    if (opts.filename != NULL) {
        in = fopen(opts.filename, "r");
        if (in == NULL) {
            fprintf(stderr, "ERROR: could not open '%s': %s\n", opts.filename, strerror(errno));
            return 1;
        }
    }
    sampling_install_signals();
    comp_id = sampling_attach(&opts, "halstreamer", STREAMER_KEY_BASE, &stream);
    if (comp_id < 0) {
        if (in != stdin) fclose(in);
        return 1;
    }
    stream_loop(in, &stream);
    if (in != stdin) fclose(in);
    hal_stream_detach(&stream);
    hal_exit(comp_id);
    return 0;
}
