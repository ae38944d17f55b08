component latencybinstream "Histogram of thread start latency, pushed whole into a HAL stream on request";
description """
Load with \\fBkeys=\\fR one non-zero stream key per instance (at most 8).  Each instance
creates a stream (depth 2004, one u32 per record).  Latencies accumulate while \\fBreset\\fR is
FALSE (it starts TRUE) and \\fBnsbinsize\\fR is not 0; on a rising edge of \\fBstream\\fR the
statistics are latched and 2 x binmax + 3 records are written: the count beyond the negative
bins, negative bins binmax..1, positive bins 0..binmax, the count beyond the positive bins.
""";
pin in s64 maxbinnumber = 1000 "Highest bin number used on each side (at most 1000)";
pin in bit reset = 1 "Clear while TRUE";
pin in s64 nsbinsize "Bin width in ns (0 keeps everything cleared)";
pin in bit stream "Rising edge: latch the statistics and write the histogram to the stream";
pin out bit stream_error "The stream had no room for the histogram";
pin out s64 stream_time "Nanoseconds spent writing the stream";
pin out s64 latency "Latency of this call, ns";
pin out s64 latency_min;
pin out s64 latency_max;
pin out s64 latency_avg;
pin out s64 variance "Variance of the latencies, ns squared";
pin out s64 availablebins = 1000 "Most bins on each side";
variable unsigned pbins[1001];
variable unsigned nbins[1001];
variable unsigned ptail;
variable unsigned ntail;
variable long long last_ns;
variable int started;
variable int last_stream;
variable long long run_min;
variable long long run_max;
variable unsigned long long n;
variable long long sum;
variable unsigned long long sumsq;
variable int stream_index;
option extra_setup yes;
option extra_cleanup yes;
function _;
license "GPL";
author "OpenEMC";
;;
#define LBS_MAX_INST 8
#define LBS_MAX_BIN 1000
#define LBS_DEPTH (2 * LBS_MAX_BIN + 1 + 2 + 1)
static int keys[LBS_MAX_INST];
RTAPI_MP_ARRAY_INT(keys, LBS_MAX_INST, "stream key of each instance (non-zero)");
static hal_stream_t streams[LBS_MAX_INST];
static int nstreams;

/* Each instance needs a non-zero key; creates its stream. */
EXTRA_SETUP()
{
    (void)prefix;
    if (extra_arg >= LBS_MAX_INST || keys[extra_arg] == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "latencybinstream: instance %ld needs a non-zero stream key "
                        "(keys=K1,K2,... with at most %d keys)\n", extra_arg, LBS_MAX_INST);
        return -EINVAL;
    }
    int r = hal_stream_create(&streams[extra_arg], comp_id, keys[extra_arg], LBS_DEPTH, "u");
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

/* Clear the bins and the statistics. */
static void lbs_clear(struct __comp_state *__comp_inst)
{
    for (int i = 0; i <= LBS_MAX_BIN; i++)
        pbins[i] = nbins[i] = 0;
    ptail = ntail = 0;
    run_min = 9223372036854775807LL;
    run_max = -9223372036854775807LL - 1;
    n = 0;
    sum = 0;
    sumsq = 0;
    latency = variance = latency_avg = latency_min = latency_max = 0;
    started = 1;
}

/* Count one latency. */
static void lbs_add(struct __comp_state *__comp_inst, long long lat, long long binmax)
{
    long long i = lat / nsbinsize;
    latency = lat;
    if (lat > run_max) run_max = lat;
    if (lat < run_min) run_min = lat;
    if (i >= 0) {
        if (i > binmax) ptail++;
        else pbins[i]++;
    } else {
        if (-i > binmax) ntail++;
        else nbins[-i]++;
    }
    n++;
    sum += lat;
    sumsq += (unsigned long long)lat * (unsigned long long)lat;
}

/* Write one record. */
static void lbs_put(hal_stream_t *s, unsigned v)
{
    union hal_stream_data rec;
    rec.u = v;
    hal_stream_write(s, &rec);
}

/* Latch the statistics and write the histogram if the stream has room for it. */
static void lbs_push(struct __comp_state *__comp_inst, long long binmax)
{
    hal_stream_t *s = &streams[stream_index];
    if (n > 1) {
        variance = (long long)((sumsq - ((unsigned long long)sum * (unsigned long long)sum) / n) / (n - 1));
        latency_avg = sum / (long long)n;
        latency_min = run_min;
        latency_max = run_max;
    }
    if (binmax < 0 || hal_stream_maxdepth(s) - 1 - hal_stream_depth(s) < 2 * binmax + 3) {
        stream_error = 1;
        return;
    }
    long long t0 = rtapi_get_time();
    lbs_put(s, ntail);
    for (long long i = binmax; i >= 1; i--)
        lbs_put(s, nbins[i]);
    for (long long i = 0; i <= binmax; i++)
        lbs_put(s, pbins[i]);
    lbs_put(s, ptail);
    stream_error = 0;
    stream_time = rtapi_get_time() - t0;
}

FUNCTION(_)
{
    long long now = rtapi_get_time();
    long long lat = now - last_ns - period;
    long long binmax = maxbinnumber < LBS_MAX_BIN ? maxbinnumber : LBS_MAX_BIN;
    last_ns = now;
    if (reset || !started || nsbinsize == 0)
        lbs_clear(__comp_inst);
    else
        lbs_add(__comp_inst, lat, binmax);
    if (stream && !last_stream)
        lbs_push(__comp_inst, binmax);
    last_stream = stream;
}
