component limit_axis "Choose a pair of position limits from a table of ranges of a feedback value";
description """
personality is the number of ranges (2..10; other values are brought into that span).
Each enabled range NN maps feedback between \\fBmin-range-NN\\fR and \\fBmax-range-NN\\fR
(inclusive) to the limits \\fBmin-limit-NN\\fR and \\fBmax-limit-NN\\fR; the first matching
range wins, unless the current range is sticky and still matches.
""";
pin in float fb "Feedback value that selects the range";
pin in float min_range-##[10 : personality] "Lower end of range NN";
pin in float max_range-##[10 : personality] "Upper end of range NN";
pin in float min_limit-##[10 : personality] "Lower limit output while range NN is in use";
pin in float max_limit-##[10 : personality] "Upper limit output while range NN is in use";
pin in bit enable-##[10 : personality] "Range NN takes part";
pin in bit sticky-##[10 : personality] "Keep range NN while the feedback stays inside it";
pin out bit error_range-##[10 : personality] = 1 "Range NN has max-range below min-range";
pin out bit error_limit-##[10 : personality] = 1 "Range NN has max-limit below min-limit";
pin out bit error_no_range "No range contains the feedback";
pin out float min_output "Lower limit of the range in use";
pin out float max_output "Upper limit of the range in use";
pin out u32 current_range "Range in use";
option extra_setup yes;
function _;
license "GPL";
author "OpenEMC";
;;
#define LA_MIN_RANGES 2
#define LA_MAX_RANGES 10

/* Bring the number of ranges into 2..10. */
EXTRA_SETUP()
{
    (void)prefix;
    (void)extra_arg;
    if (personality > LA_MAX_RANGES) personality = LA_MAX_RANGES;
    if (personality < LA_MIN_RANGES) personality = LA_MIN_RANGES;
    return 0;
}

/* Range r is usable: report (once) a range or limit pair given the wrong way round. */
static int la_range_ok(struct __comp_state *__comp_inst, int r)
{
    if (max_range(r) < min_range(r)) {
        if (!error_range(r))
            rtapi_print_msg(RTAPI_MSG_ERR, "limit_axis: Error in range %d settings! Min: %f > Max: %f\n", r,
                            max_range(r), min_range(r));
        error_range(r) = 1;
        return 0;
    }
    error_range(r) = 0;
    if (max_limit(r) < min_limit(r)) {
        if (!error_limit(r))
            rtapi_print_msg(RTAPI_MSG_ERR, "limit_axis: Error in limit %d settings! Min: %f > Max: %f\n", r,
                            max_limit(r), min_limit(r));
        error_limit(r) = 1;
        return 0;
    }
    error_limit(r) = 0;
    return 1;
}

/* Range r contains the feedback. */
static int la_contains(struct __comp_state *__comp_inst, int r)
{
    return min_range(r) <= fb && fb <= max_range(r);
}

FUNCTION(_)
{
    int cur = current_range;
    (void)period;
    if (cur < personality && sticky(cur) && enable(cur) && la_contains(__comp_inst, cur)) {
        min_output = min_limit(cur);
        max_output = max_limit(cur);
        return;
    }
    for (int r = 0; r < personality; r++) {
        if (!enable(r) || !la_range_ok(__comp_inst, r) || !la_contains(__comp_inst, r))
            continue;
        min_output = min_limit(r);
        max_output = max_limit(r);
        error_no_range = 0;
        if ((int)current_range != r)
            rtapi_print_msg(RTAPI_MSG_INFO, "limit_axis: Switching to Range %d\n", r);
        current_range = r;
        return;
    }
    if (!error_no_range)
        rtapi_print_msg(RTAPI_MSG_ERR, "limit_axis: No Range found corresponding to feedback");
    error_no_range = 1;
}
