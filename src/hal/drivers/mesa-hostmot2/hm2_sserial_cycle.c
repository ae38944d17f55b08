/* hm2_sserial_cycle.c: the Smart Serial part of the read and write functs: one do-it per servo
   cycle per port, error counting (fault-inc/dec/lim), stopping a failing port safely, the
   restart on a run FALSE->TRUE edge and writing changed globals while a port is stopped. */
#include <string.h>
#include "hm2.h"

#define DOIT_WARN_AFTER 4

/* The first failed transfer of a remote, reported once (until the port restarts). */
static void report_channel_error(hm2_board_t *hm2, hm2_sserial_port_t *p, int c, uint32_t link)
{
    hm2_sserial_channel_t *ch = &p->chan[c];
    if (ch->error_reported)
        return;
    ch->error_reported = true;
    HM2_ERR(hm2, "Smart Serial Error: port %i channel %i. You may see this error if the FPGA card "
            "read thread is not running. This error message will not repeat.\n", p->index, c);
    if (link == SSLBP_LINK_CRC)
        HM2_ERR(hm2, "Smart serial card %s error = (%i) %s\n", ch->name, 0, "CRC error");
    else
        HM2_ERR(hm2, "Smart serial card %s error = (%i) %s\n", ch->name, 3, "Timeout");
}

/* Fault pins and comm-state of the remotes after a transfer (failed = channel mask). */
static void update_remote_status(hm2_board_t *hm2, hm2_sserial_port_t *p, uint32_t failed, bool unpack)
{
    for (int c = 0; c < p->num_channels; c++) {
        hm2_sserial_channel_t *ch = &p->chan[c];
        if (!ch->present)
            continue;
        uint32_t cs = *ch->cs_read;
        bool bad = (failed & (1u << c)) != 0;
        *ch->hal->comm_state = bad ? (SSLBP_CS_LINK(cs) ? SSLBP_CS_LINK(cs) : SSLBP_LINK_TIMEOUT) << 8
                                   : SSLBP_CS_STATUS(cs);
        *ch->hal->fault = bad || SSLBP_CS_STATUS(cs) != 0;
        if (bad)
            report_channel_error(hm2, p, c, SSLBP_CS_LINK(cs));
        if (!bad && unpack)
            hm2_sserial_unpack_inputs(ch);
    }
}

/* Stop a port that failed too often: report once, naming board, port and channels; bite the
   board's watchdog so its outputs go safe too (the remotes' own watchdogs drop theirs). */
static void stop_on_errors(hm2_board_t *hm2, hm2_sserial_port_t *p, uint32_t failed)
{
    p->state = HM2_SSERIAL_STOPPED_ON_ERRORS;
    p->send_stop = true;
    p->over_limit_times++;
    if (hm2->watchdog.num_instances) {
        uint32_t expire_now = 0;   /* the timeout param stays; recovery rewrites the timer */
        hm2_queue_write(hm2, hm2->watchdog.timer_addr, &expire_now, 4);
    }
    if (p->stop_reported)
        return;
    p->stop_reported = true;
    HM2_ERR(hm2, "Smart Serial Comms Error: There have been more than %i errors in %i thread "
            "executions at least %i times. See other error messages for details.\n",
            (int)p->hal->fault_dec, (int)p->hal->fault_inc, (int)p->hal->fault_lim);
    HM2_ERR(hm2, "***Smart Serial Port %i will be stopped***\n", p->index);
    for (int c = 0; c < p->num_channels; c++)
        if (failed & (1u << c))
            HM2_ERR(hm2, "Smart Serial port %d channel %d (%s) is not answering: outputs of the "
                    "board disabled (watchdog bitten); set %s.sserial.port-%d.run FALSE then TRUE "
                    "to restart\n", p->index, c, p->chan[c].name, hm2->llio->name, p->index);
}

/* Count one cycle's outcome; past fault-lim the port stops. */
static void account(hm2_board_t *hm2, hm2_sserial_port_t *p, bool bad, uint32_t failed)
{
    hm2_sserial_port_hal_t *h = p->hal;
    p->cycles_since_reset++;
    if (bad)
        p->fault_count += h->fault_inc;
    else
        p->fault_count = p->fault_count > h->fault_dec ? p->fault_count - h->fault_dec : 0;
    *h->fault_count = p->fault_count;
    if (p->fault_count > h->fault_lim)
        stop_on_errors(hm2, p, failed ? failed : p->active_mask);
}

/* Result of the previous cycle's do-it. */
static void check_doit(hm2_board_t *hm2, hm2_sserial_port_t *p)
{
    uint32_t cmd = *p->command_read, failed = *p->data_read & p->active_mask & SSLBP_DATA_FAIL_MASK;
    p->doit_sent = false;
    if (cmd != 0) {
        if (++p->doit_late == DOIT_WARN_AFTER)
            HM2_ERR(hm2, "Smart Serial port %i: DoIt not cleared from previous servo thread. Servo "
                    "thread rate probably too fast. This message will not be repeated, but the "
                    "%s.sserial.%1d.fault-count pin will indicate if this is happening frequently.\n",
                    p->index, hm2->llio->name, p->index);
        account(hm2, p, true, 0);
        return;
    }
    update_remote_status(hm2, p, failed, true);
    account(hm2, p, failed != 0, failed);
    if (failed)
        p->last_failed = failed;
}

/* Result of a restart (START_NORMAL) sent by the previous write. */
static void check_start(hm2_board_t *hm2, hm2_sserial_port_t *p)
{
    uint32_t failed = *p->data_read & p->active_mask & SSLBP_DATA_FAIL_MASK;
    if (*p->command_read != 0 || failed) {
        update_remote_status(hm2, p, failed ? failed : p->active_mask, false);
        p->state = HM2_SSERIAL_STOPPED_ON_ERRORS;
        if (!p->restart_reported)
            HM2_ERR(hm2, "Smart Serial port %d: restart failed (channels 0x%02X not answering); "
                    "toggle run again to retry\n", p->index, failed ? failed : p->active_mask);
        p->restart_reported = true;
        return;
    }
    p->state = HM2_SSERIAL_RUNNING;
    p->fault_count = 0;
    p->cycles_since_reset = 0;
    p->stop_reported = false;
    p->restart_reported = false;
    for (int c = 0; c < p->num_channels; c++)
        p->chan[c].error_reported = false;
    *p->hal->fault_count = 0;
    update_remote_status(hm2, p, 0, false);
    HM2_PRINT(hm2, "Smart Serial port %d restarted\n", p->index);
}

/* read funct: results of what the previous write sent. */
void hm2_sserial_process_tram_read(hm2_board_t *hm2)
{
    for (int i = 0; i < hm2->sserial.num_instances; i++) {
        hm2_sserial_port_t *p = &hm2->sserial.port[i];
        if (!p->hal || !p->active_mask)
            continue;
        if (p->state == HM2_SSERIAL_RUNNING && p->doit_sent)
            check_doit(hm2, p);
        else if (p->state == HM2_SSERIAL_STARTING && p->doit_sent) {
            p->doit_sent = false;
            check_start(hm2, p);
        }
        *p->hal->port_state = (hal_u32_t)p->state;
        *p->hal->port_state2 = p->last_failed;
        *p->hal->port_state3 = p->active_mask;
    }
}

/* write funct, TRAM part: outputs and the do-it, or an ignored command when not running. */
void hm2_sserial_prepare_tram_write(hm2_board_t *hm2)
{
    for (int i = 0; i < hm2->sserial.num_instances; i++) {
        hm2_sserial_port_t *p = &hm2->sserial.port[i];
        if (!p->hal || !p->active_mask)
            continue;
        bool run = *p->hal->run;
        uint32_t cmd = SSLBP_CMD_IGNORED;
        if (p->send_stop) {
            p->send_stop = false;
            cmd = SSLBP_CMD_STOP_ALL;
        } else if (p->state == HM2_SSERIAL_RUNNING && !run) {
            p->state = HM2_SSERIAL_STOPPED;
            p->doit_sent = false;
            cmd = SSLBP_CMD_STOP_ALL;
        } else if (p->state == HM2_SSERIAL_RUNNING) {
            for (int c = 0; c < p->num_channels; c++)
                if (p->chan[c].present)
                    hm2_sserial_pack_outputs(&p->chan[c]);
            cmd = SSLBP_CMD_DOIT | p->active_mask;
            p->doit_sent = true;
        } else if (run && !p->prev_run) {
            p->state = HM2_SSERIAL_STARTING;   /* the start itself is queued after the TRAM */
            p->doit_sent = false;
        }
        p->prev_run = run;
        *p->command_write = cmd;
        *p->hal->debug = (hal_s32_t)cmd;
    }
}

/* Queue a write of a channel register. */
static void queue_reg(hm2_board_t *hm2, uint32_t addr, uint32_t v)
{
    hm2_queue_write(hm2, addr, &v, 4);
}

/* Value a global's param asks for, in the remote's bits. */
static uint32_t global_value(const hm2_sserial_rec_t *rec)
{
    const hm2_sserial_rec_hal_t *h = rec->hal;
    uint32_t v;
    if (rec->data_type == SSLBP_TYPE_FLOAT) {
        float f = (float)h->param_float;
        memcpy(&v, &f, sizeof(v));
        return v;
    }
    v = (rec->data_type == SSLBP_TYPE_SIGNED || rec->data_type == SSLBP_TYPE_NONVOL_SIGNED)
            ? (uint32_t)h->param_s32 : h->param_u32;
    return rec->bits < 32 ? v & ((1u << rec->bits) - 1) : v;
}

/* While stopped: write at most one changed writable global per cycle to its remote. */
static void write_one_global(hm2_board_t *hm2, hm2_sserial_port_t *p)
{
    for (int c = 0; c < p->num_channels; c++) {
        hm2_sserial_channel_t *ch = &p->chan[c];
        for (int i = ch->num_pd; ch->present && i < ch->num_pd + ch->num_globals; i++) {
            hm2_sserial_rec_t *rec = &ch->rec[i];
            uint32_t v = global_value(rec);
            if (rec->dir == SSLBP_DIR_IN || v == rec->written_global)
                continue;
            queue_reg(hm2, ch->cs_addr, SSLBP_CS_REMOTE_WRITE | rec->parm_addr);
            queue_reg(hm2, ch->iface_addr[0], v);
            queue_reg(hm2, p->command_addr, SSLBP_CMD_DOIT | 1u << c);
            rec->written_global = v;
            return;
        }
    }
}

/* write funct, queued part: a pending restart (modes, then START_NORMAL) or a global write. */
void hm2_sserial_write(hm2_board_t *hm2)
{
    for (int i = 0; i < hm2->sserial.num_instances; i++) {
        hm2_sserial_port_t *p = &hm2->sserial.port[i];
        if (!p->hal || !p->active_mask)
            continue;
        if (p->state == HM2_SSERIAL_STARTING && !p->doit_sent) {
            for (int c = 0; c < p->num_channels; c++)
                if (p->chan[c].present)
                    queue_reg(hm2, p->chan[c].cs_addr, (uint32_t)p->chan[c].mode << SSLBP_CS_MODE_SHIFT);
            queue_reg(hm2, p->command_addr, SSLBP_CMD_START_NORMAL | p->active_mask);
            p->doit_sent = true;
        } else if (p->state == HM2_SSERIAL_STOPPED && !*p->hal->run) {
            write_one_global(hm2, p);
        }
    }
}

/* debug_modules: the ports and their remotes. */
void hm2_sserial_print_module(hm2_board_t *hm2)
{
    for (int i = 0; i < hm2->sserial.num_instances; i++) {
        hm2_sserial_port_t *p = &hm2->sserial.port[i];
        HM2_PRINT(hm2, "Smart Serial port %d: %d channels, active 0x%02X, state %d\n", i,
                  p->num_channels, p->active_mask, p->state);
        for (int c = 0; c < p->num_channels; c++)
            if (p->chan[c].present)
                HM2_PRINT(hm2, "    channel %d: %s mode %d, %d records, %d globals\n", c,
                          p->chan[c].name, p->chan[c].mode, p->chan[c].num_pd, p->chan[c].num_globals);
    }
}
