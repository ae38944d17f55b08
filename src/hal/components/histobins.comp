component histobins "Histogram bins of one input, read back one bin at a time (for hal-histogram)";
description """
Each call bins one sample: below \\fBminvalue\\fR counts in \\fBnextra\\fR, above
minvalue + nbins x binsize in \\fBpextra\\fR (a sample exactly at the top also goes there),
else in bin floor((v - minvalue)/binsize).  Set \\fBindex\\fR to read a bin in
\\fBbinvalue\\fR; \\fBcheck\\fR echoes the index.  \\fBreset\\fR (held) or a change of the
geometry clears everything; the sample of a clearing call is not binned.
""";
pin in u32 pintype "0 input (float), 1 input-s32, 2 input-u32, 3 input-bit";
pin in float input;
pin in s32 input_s32;
pin in u32 input_u32;
pin in bit input_bit;
pin in u32 nbins = 20 "Number of bins (1..200)";
pin in float binsize = 1 "Width of each bin";
pin in float minvalue = 0 "Lower edge of bin 0";
pin in s32 index "Bin to read";
pin in bit reset "Clear while TRUE";
pin in bit method "FALSE: Welford running variance; TRUE: sums of values and squares";
pin out s32 check "Echo of index";
pin out bit input_error "nbins is outside 1..200";
pin out float binvalue "Count of the bin at index (-1 when index is outside)";
pin out float pextra "Samples above the top bin";
pin out float nextra "Samples below bin 0";
pin out float input_min;
pin out float input_max;
pin out u32 nsamples;
pin out float variance;
pin out float mean;
pin out s32 availablebins = 200 "Most bins available";
variable double bin[200];
variable int started;
variable unsigned last_nbins;
variable double last_binsize;
variable double last_minvalue;
variable double m2;
variable double sum;
variable double sumsq;
function _;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
#define HB_MAX_BINS 200
double v = pintype == 1 ? input_s32 : pintype == 2 ? input_u32 : pintype == 3 ? (input_bit ? 1.0 : 0.0) : input;
check = index;
if (nbins > HB_MAX_BINS || nbins < 1) {
    input_error = 1;
    return;
}
input_error = 0;
if (reset || !started || nbins != last_nbins || binsize != last_binsize || minvalue != last_minvalue) {
    for (int i = 0; i < HB_MAX_BINS; i++)
        bin[i] = 0;
    pextra = nextra = 0;
    nsamples = 0;
    mean = variance = 0;
    m2 = sum = sumsq = 0;
    input_min = 1e99;
    input_max = -1e99;
    started = 1;
    last_nbins = nbins;
    last_binsize = binsize;
    last_minvalue = minvalue;
} else {
    double top = minvalue + nbins * binsize;
    if (v < minvalue)
        nextra++;
    else if (v >= top || !(binsize > 0))
        pextra++;  /* LinuxCNC writes one past the last bin when v is exactly the top */
    else
        bin[(int)fmin((v - minvalue) / binsize, nbins - 1)]++;
}
binvalue = index >= 0 && index < (int)nbins ? bin[index] : -1;
if (v < input_min) input_min = v;
if (v > input_max) input_max = v;
nsamples++;
if (nsamples >= 2) {
    double n = nsamples;
    if (!method) {
        double d = v - mean;
        mean += d / n;
        m2 += d * (v - mean);
        variance = m2 / (n - 1);
    } else {
        sum += v;
        sumsq += v * v;
        variance = (sumsq - sum * sum / n) / (n - 1);
        mean = sum / n;
    }
}
