component histobinstream "Histogram of one input, pushed whole into a HAL stream on request";
description """
Load with \\fBkeys=\\fR one non-zero stream key per instance (at most 8).  Each instance
creates a stream (depth 203, one u32 per record).  Bins accumulate while \\fBreset\\fR is
FALSE (it starts TRUE); on a rising edge of \\fBstream\\fR the statistics pins are latched and
nbins + 2 records are written: the count below minvalue, each bin, the count above the top.
""";
pin in u32 pintype "0 input (float), 1 input-s32, 2 input-u32, 3 input-bit";
pin in float input;
pin in s32 input_s32;
pin in u32 input_u32;
pin in bit input_bit;
pin in u32 nbins = 20 "Number of bins (1..200)";
pin in float binsize = 1 "Width of each bin";
pin in float minvalue = 0 "Lower edge of bin 0";
pin in bit reset = 1 "Clear while TRUE";
pin in bit method "FALSE: Welford running variance; TRUE: sums of values and squares";
pin in bit stream "Rising edge: latch the statistics and write the histogram to the stream";
pin out bit stream_error "The stream had no room for the histogram";
pin out s64 stream_time "Nanoseconds spent writing the stream";
pin out bit input_error "nbins outside 1..200 or binsize not positive (cleared by reset)";
pin out float input_min;
pin out float input_max;
pin out u32 nsamples;
pin out float variance;
pin out float mean;
pin out s32 availablebins = 200 "Most bins available";
variable unsigned bin[200];
variable unsigned ntail;
variable unsigned ptail;
variable int started;
variable int last_stream;
variable unsigned last_nbins;
variable double last_binsize;
variable double last_minvalue;
variable double run_min;
variable double run_max;
variable double run_mean;
variable double run_var;
variable double m2;
variable double sum;
variable double sumsq;
variable unsigned n;
variable int stream_index;
option extra_setup yes;
option extra_cleanup yes;
function _;
license "GPL";
author "OpenEMC";
;;
#define HBS_MAX_INST 8
#define HBS_MAX_BINS 200
#define HBS_DEPTH (HBS_MAX_BINS + 2 + 1)
static int keys[HBS_MAX_INST];
RTAPI_MP_ARRAY_INT(keys, HBS_MAX_INST, "stream key of each instance (non-zero)");
static hal_stream_t streams[HBS_MAX_INST];
static int nstreams;

/* Each instance needs a non-zero key; creates its stream. */
EXTRA_SETUP()
{
    (void)prefix;
    if (extra_arg >= HBS_MAX_INST || keys[extra_arg] == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "histobinstream: instance %ld needs a non-zero stream key "
                        "(keys=K1,K2,... with at most %d keys)\n", extra_arg, HBS_MAX_INST);
        return -EINVAL;
    }
    int r = hal_stream_create(&streams[extra_arg], comp_id, keys[extra_arg], HBS_DEPTH, "u");
    if (r < 0)
        return r;
    stream_index = extra_arg;
    nstreams = extra_arg + 1;
    return 0;
}

/* Destroy the streams made so far. */
EXTRA_CLEANUP()
{
    for (int i = 0; i < nstreams; i++)
        hal_stream_destroy(&streams[i]);
    nstreams = 0;
}

/* Clear the bins and the running statistics. */
static void hbs_clear(struct __comp_state *__comp_inst)
{
    for (int i = 0; i < HBS_MAX_BINS; i++)
        bin[i] = 0;
    ntail = ptail = n = 0;
    run_min = 1e99;
    run_max = -1e99;
    run_mean = run_var = m2 = sum = sumsq = 0;
    started = 1;
    last_nbins = nbins;
    last_binsize = binsize;
    last_minvalue = minvalue;
}

/* Bin one sample and update min, max, mean and variance (the first sample counts here). */
static void hbs_add(struct __comp_state *__comp_inst, double v)
{
    if (v < minvalue) {
        ntail++;
    } else {
        double idx = (v - minvalue) / binsize;
        if (idx >= nbins) ptail++;
        else bin[(int)idx]++;
    }
    if (v < run_min) run_min = v;
    if (v > run_max) run_max = v;
    n++;
    if (n == 1) {
        run_mean = sum = v;
        sumsq = v * v;
    } else if (!method) {
        double d = v - run_mean;
        run_mean += d / n;
        m2 += d * (v - run_mean);
        run_var = m2 / (n - 1);
    } else {
        sum += v;
        sumsq += v * v;
        run_var = (sumsq - sum * sum / n) / (n - 1);
        run_mean = sum / n;
    }
}

/* Latch the statistics and write ntail, the bins and ptail, if the stream has room. */
static void hbs_push(struct __comp_state *__comp_inst)
{
    hal_stream_t *s = &streams[stream_index];
    union hal_stream_data rec;
    nsamples = n;
    mean = run_mean;
    variance = run_var;
    input_min = n ? run_min : 0;
    input_max = n ? run_max : 0;
    if (hal_stream_maxdepth(s) - 1 - hal_stream_depth(s) < (int)nbins + 2) {
        stream_error = 1;
        return;
    }
    long long t0 = rtapi_get_time();
    rec.u = ntail;
    hal_stream_write(s, &rec);
    for (unsigned i = 0; i < nbins; i++) {
        rec.u = bin[i];
        hal_stream_write(s, &rec);
    }
    rec.u = ptail;
    hal_stream_write(s, &rec);
    stream_error = 0;
    stream_time = rtapi_get_time() - t0;
}

FUNCTION(_)
{
    double v = pintype == 1 ? input_s32 : pintype == 2 ? input_u32 : pintype == 3 ? (input_bit ? 1.0 : 0.0) : input;
    (void)period;
    if (nbins < 1 || nbins > HBS_MAX_BINS || !(binsize > 0)) {
        input_error = 1;
        last_stream = stream;
        return;
    }
    if (reset)
        input_error = 0;
    if (reset || !started || nbins != last_nbins || binsize != last_binsize || minvalue != last_minvalue)
        hbs_clear(__comp_inst);
    else
        hbs_add(__comp_inst, v);
    if (stream && !last_stream)
        hbs_push(__comp_inst);
    last_stream = stream;
}
