// halui_mdi.cc: [HALUI]MDI_COMMAND pins: switch to MDI, run the command, then return to the mode the operator was in.
#include <cstdio>

#include "halui.hh"

namespace {

// Ask task for a mode.
void set_mode(Halui &h, int mode)
{
    EMC_TASK_SET_MODE m;
    m.mode = mode;
    halui_send(h, m);
}

// Send command i, switching to MDI mode first when needed.
void run_command(Halui &h, size_t i)
{
    if (!halui_machine_ready(h)) return;
    const EMC_STAT &s = h.client.status();
    if (s.task.state != EMC_TASK_STATE_ON) {
        fprintf(stderr, "halui: mdi-command-%02zu not run: the machine is not on\n", i);
        return;
    }
    int mode = s.task.mode;
    if (mode != EMC_TASK_MODE_MDI) {
        set_mode(h, EMC_TASK_MODE_MDI);
        h.client.poll();
        if (h.client.status().task.mode != EMC_TASK_MODE_MDI) {
            fprintf(stderr, "halui: mdi-command-%02zu not run: task did not switch to MDI mode\n", i);
            return;
        }
    }
    if (!h.mdi_running) h.mdi_saved_mode = mode;
    EMC_TASK_PLAN_EXECUTE m;
    if (!emc_set_text(m.command, h.cfg.mdi_commands[i].c_str()))
        fprintf(stderr, "halui: mdi-command-%02zu is longer than %d characters; truncated\n", i, LINELEN - 1);
    if (halui_send(h, m)) {
        h.mdi_running = true;
        h.mdi_serial = h.client.last_serial();
    }
}

// The commands halui sent are finished: task has read the last one, nothing is queued or
// running, and the interpreter is idle.
bool finished(const Halui &h)
{
    const EMC_STAT &s = h.client.status();
    int32_t diff = ui_serial_diff(s.echo_serial_number, h.mdi_serial);
    if (diff < 0 || (diff == 0 && s.status == RCS_EXEC)) return false;
    return s.task.interpState == EMC_TASK_INTERP_IDLE && s.task.queuedMDIcommands == 0;
}

} // namespace

// Serve the MDI command pins and finish a run.
void halui_mdi(Halui &h)
{
    for (size_t i = 0; i < h.pins.mdi_command.size(); i++)
        if (h.pins.mdi_command[i].rose()) run_command(h, i);
    if (h.mdi_running && halui_machine_ready(h) && finished(h)) {
        h.mdi_running = false;
        int back = h.mdi_saved_mode;
        h.mdi_saved_mode = 0;
        if (back && back != EMC_TASK_MODE_MDI && h.client.status().task.mode == EMC_TASK_MODE_MDI)
            set_mode(h, back);
    }
    if (h.pins.mdi_is_running) **h.pins.mdi_is_running = h.mdi_running;
}
