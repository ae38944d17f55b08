/* halsampler.c: user program that prints the records of a sampler stream, one line each. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "rtapi.h"
#include "hal.h"
#include "sampling_cli.h"

/* Prints one field in halsampler's format, followed by one space. */
static void print_field(FILE *out, hal_type_t type, const union hal_stream_data *d)
{
    switch (type) {
    case HAL_FLOAT: fprintf(out, "%f ", (double)d->f); break;
    case HAL_BIT: fprintf(out, "%d ", d->b ? 1 : 0); break;
    case HAL_S32: fprintf(out, "%ld ", (long)d->s); break;
    case HAL_U32: fprintf(out, "%lu ", (unsigned long)d->u); break;
    case HAL_S64: fprintf(out, "%lld ", (long long)d->l); break;
    case HAL_U64: fprintf(out, "%llu ", (unsigned long long)d->k); break;
    default: fprintf(out, "? "); break;
    }
}

/* Prints one record line, with `overrun` first when sample numbers skipped. */
static void print_record(FILE *out, hal_stream_t *stream, const union hal_stream_data *rec,
                         unsigned sampleno, int tag)
{
    static int have_last;
    static unsigned last;
    int n, count = hal_stream_element_count(stream);

    if (have_last && sampleno != last + 1) {
        fprintf(out, "overrun\n");
    }
    have_last = 1;
    last = sampleno;
    if (tag) {
        fprintf(out, "%u ", sampleno - 1);  /* the HAL library numbers records from 1, tags start at 0 */
    }
    for (n = 0; n < count; n++) {
        print_field(out, hal_stream_element_type(stream, n), &rec[n]);
    }
    fprintf(out, "\n");
}

/* Reads records until the count is reached or a signal arrives. */
static void sample_loop(FILE *out, hal_stream_t *stream, long count, int tag)
{
    union hal_stream_data rec[SAMPLING_MAX_FIELDS];
    unsigned sampleno;

    while (count != 0 && !sampling_stop) {
        if (hal_stream_read(stream, rec, &sampleno) < 0) {
            sampling_poll_sleep();
            continue;
        }
        print_record(out, stream, rec, sampleno, tag);
        if (count > 0) {
            count--;
        }
    }
}

static const char usage_text[] =
    "Usage: halsampler [-c CHAN] [-n COUNT] [-t] [-N NAME] [FILE]\n"
    "Prints the samples recorded by the realtime 'sampler' channel CHAN (default 0), one line\n"
    "per sample, to FILE or standard output.\n"
    "  -c CHAN   sampler channel 0..7\n"
    "  -n COUNT  stop after COUNT samples (default: until interrupted)\n"
    "  -t        start each line with the sample number\n"
    "  -N NAME   HAL component name (default halsamplerCHAN)\n"
    "  --help    this text\n";

/* Entry point: parse options, attach, open the output, print records, clean up. */
int main(int argc, char **argv)
{
    sampling_opts_t opts;
    hal_stream_t stream;
    FILE *out = stdout;
    int comp_id;

    int rc = sampling_parse_args(argc, argv, "cntN", usage_text, &opts);
    if (rc != 0) {
        return rc < 0 ? 1 : 0;
    }
    sampling_install_signals();
    comp_id = sampling_attach(&opts, "halsampler", SAMPLER_KEY_BASE, &stream);
    if (comp_id < 0) {
        return 1;
    }
    if (opts.filename != NULL) {
        out = fopen(opts.filename, "w");
        if (out == NULL) {
            fprintf(stderr, "ERROR: could not open '%s': %s\n", opts.filename, strerror(errno));
            hal_stream_detach(&stream);
            hal_exit(comp_id);
            return 1;
        }
    }
    sample_loop(out, &stream, opts.count, opts.tag);
    fflush(out);
    if (out != stdout) fclose(out);
    hal_stream_detach(&stream);
    hal_exit(comp_id);
    return 0;
}
