component latencybins "Histogram of thread start latency (for latency-histogram)";
description """
Each call measures how late it started compared with the previous call plus the period, and
counts it in a bin of \\fBnsbinsize\\fR ns (positive and negative sides, up to
\\fBmaxbinnumber\\fR bins each, beyond that in pextra/nextra).  Set \\fBindex\\fR to read a bin
pair; \\fBcheck\\fR echoes the index.  With nsbinsize 0 (the default) or \\fBreset\\fR everything
stays cleared.
""";
pin in s32 maxbinnumber = 1000 "Highest bin number used on each side (at most 1000)";
pin in s32 index "Bin to read";
pin in bit reset "Clear while TRUE";
pin in s32 nsbinsize "Bin width in ns (0 keeps everything cleared)";
pin out s32 check "Echo of index";
pin out s32 latency "Latency of this call, ns";
pin out s32 latency_max;
pin out s32 latency_min;
pin out s32 pbinvalue "Count of positive bin index (-1 when outside)";
pin out s32 nbinvalue "Count of negative bin index (-1 when outside)";
pin out s32 pextra "Latencies beyond the last positive bin";
pin out s32 nextra "Latencies beyond the last negative bin";
pin out s32 variance "Variance of the latencies, ns squared";
pin out s32 availablebins = 1000 "Most bins on each side";
variable int pbins[1001];
variable int nbins[1001];
variable long long last_ns;
variable int started;
variable unsigned long long n;
variable long long sum;
variable unsigned long long sumsq;
function _;
license "GPL";
author "OpenEMC";
;;
#define LB_MAX_BIN 1000
long long now = rtapi_get_time();
int lat = (int)(hal_u32_t)(now - last_ns - period);
int binmax = maxbinnumber < LB_MAX_BIN ? maxbinnumber : LB_MAX_BIN;
last_ns = now;
if (reset || !started || nsbinsize == 0) {
    latency = 0;
    latency_min = 2147483647;
    latency_max = -2147483647 - 1;
    pextra = nextra = 0;
    for (int i = 0; i <= LB_MAX_BIN; i++)
        pbins[i] = nbins[i] = 0;
    n = 0;
    sum = 0;
    sumsq = 0;
    started = 1;
} else {
    int i = lat / nsbinsize;
    latency = lat;
    if (lat > latency_max) latency_max = lat;
    if (lat < latency_min) latency_min = lat;
    if (i >= 0) {
        if (i > binmax) pextra++;
        else pbins[i]++;
    } else {
        if (-(long long)i > binmax) nextra++;
        else nbins[-i]++;
    }
    n++;
    sum += lat;
    sumsq += (unsigned long long)((long long)lat * lat);
    if (n > 1)
        variance = (hal_s32_t)((sumsq - ((unsigned long long)sum * (unsigned long long)sum) / n) / (n - 1));
}
check = index;
if (index >= 0 && index <= binmax) {
    pbinvalue = pbins[index];
    nbinvalue = nbins[index];
} else {
    pbinvalue = nbinvalue = -1;
}
