/* axis_tester.h: the back-and-forth run of steptest and axistest (a pause at each end), shared by
 * both .comp files; each supplies its own idle jog. Included after the pin macros. */

/* Start of a run: remember where it starts and pick the two ends by dir (1 only up, 2 only down). */
static void axis_test_start(struct __comp_state *__comp_inst)
{
    running = 1;
    run_start = position_fb;
    run_high = dir == 2 ? run_start : run_start + amplitude;
    run_low = dir == 1 ? run_start : run_start - amplitude;
    position_cmd = run_low;
}

/* While running: at an end (within epsilon) wait pause seconds, then head for the other end. */
static void axis_test_run(struct __comp_state *__comp_inst)
{
    if (!running)
        axis_test_start(__comp_inst);
    if (fabs(position_fb - position_cmd) >= epsilon || (position_cmd != run_low && position_cmd != run_high))
        return;
    if (!timer_running) {
        timer_running = 1;
        timer = 0;
    } else if (timer >= pause) {
        timer_running = 0;
        position_cmd = position_cmd == run_low ? run_high : run_low;
    }
}

/* One call: advance the timer, run, return to the start after a run, or jog (returns 1 when idle). */
static int axis_test_step(struct __comp_state *__comp_inst, double period_s)
{
    if (timer_running)
        timer += period_s;
    elapsed = timer;
    if (run) {
        axis_test_run(__comp_inst);
        return 0;
    }
    if (running) {
        position_cmd = run_start;
        if (fabs(position_fb - run_start) < epsilon) {
            running = 0;
            timer_running = 0;
        }
        return 0;
    }
    return 1;
}
