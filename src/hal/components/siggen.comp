component siggen "Signal generator: square, triangle, sawtooth, sine and cosine waves";
pin out float square "Square wave";
pin out float sawtooth "Sawtooth wave";
pin out float triangle "Triangle wave";
pin out float sine "Sine wave";
pin out float cosine "Cosine wave";
pin out bit clock "TRUE during the second half of each cycle";
pin in float frequency = 1.0 "Frequency in Hz (rewritten to 0.5/period when higher)";
pin in float amplitude = 1.0 "Peak amplitude of every output";
pin in float offset = 0.0 "Offset added to every output";
pin in bit reset "While TRUE, the phase is held at one half";
variable double phase;
function update "Advance the phase and compute the waveforms";
option rtapi_app no;
include "comp_args.h";
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description "Load with num_chan=N (at most 16, default 1) or names=a,b,... Instances are siggen.N or the given names.";
;;
#define SIGGEN_MAX_CHAN 16
static int num_chan = 0;
RTAPI_MP_INT(num_chan, "number of channels");
static char *names[SIGGEN_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(names, SIGGEN_MAX_CHAN, "names of channels");

/* Advance the phase and compute every waveform. */
FUNCTION(update) {
    double p = phase, ps = fperiod, sq, saw, tri, amp = amplitude, off = offset;
    if (reset) {
        p = 0.5;
    } else {
        double inc = frequency * ps;
        if (inc != inc || inc == -INFINITY)  /* NaN or -inf: hold the phase */
            inc = 0.0;
        if (inc > 0.5) {
            *frequency_ptr = 0.5 / ps;
            inc = 0.5;
        }
        p += inc;
    }
    p -= floor(p);  /* wrap into [0,1) in one step, whatever the size */
    if (p >= 1.0) p = 0.0;  /* a tiny negative phase rounds up to 1 */
    phase = p;
    sq = p > 0.5 ? 1.0 : -1.0;
    clock = p > 0.5;
    saw = 2.0 * p - 1.0;
    tri = 2.0 * saw * sq - 1.0;
    square = sq * amp + off;
    sawtooth = saw * amp + off;
    triangle = tri * amp + off;
    sine = sin(p * 2.0 * 3.1415927) * amp + off;
    cosine = cos(p * 2.0 * 3.1415927) * amp + off;
}

/* Create num_chan (or one per name) siggen channels. */
int rtapi_app_main(void) {
    static const comp_chan_spec_t spec = { "SIGGEN", "siggen", SIGGEN_MAX_CHAN, 1 };
    int i, r = 0, n = comp_chan_count(&spec, num_chan, names);
    char buf[HAL_NAME_LEN + 1];
    if (n < 0)
        return n;
    comp_id = hal_init("siggen");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < n && r == 0; i++) {
        comp_chan_name(&spec, names, i, buf, sizeof(buf));
        r = export(buf, i);
    }
    if (r) {
        hal_exit(comp_id);
        return r;
    }
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void) {
    hal_exit(comp_id);
}
