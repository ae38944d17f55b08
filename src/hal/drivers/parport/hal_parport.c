/* hal_parport.c: HAL driver for PC parallel ports (LinuxCNC's cfg=, pins, params and functs). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_errno.h"
#include "rtapi_string.h"
#include "hal.h"
#include "parport_bits.h"
#include "parport_cfg.h"
#include "parport_io.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Parallel port driver: cfg=\"<addr|N|parportN|/dev/...> [in|out|epp|x] ...\"");

#define PP_LAST_PIN 17

static char *cfg = "0x0278";
RTAPI_MP_STRING(cfg, "ports: address (hex) or Linux port number or ppdev device, each with an optional type");

/* HAL state of one port (in HAL memory). */
typedef struct {
    hal_bit_t *out[PP_LAST_PIN + 1];
    hal_bit_t out_invert[PP_LAST_PIN + 1];
    hal_bit_t out_reset[PP_LAST_PIN + 1];
    hal_bit_t *in[PP_LAST_PIN + 1];
    hal_bit_t *in_not[PP_LAST_PIN + 1];
    hal_u32_t reset_time;        /* ns after write before reset; param only when the data port is output */
    hal_u32_t debug1, debug2;
    pp_mode_t mode;
    pp_layout_t layout;
    pp_io_t io;
    uint32_t levels;             /* logical output levels last written */
    uint8_t data_written, control_written;
    int data_valid, control_valid;
    long long data_time_ns, control_time_ns;
} pp_port_t;

static int comp_id = -1;
static int port_count;
static pp_port_t *ports;

/* True when the mode drives the data lines (reset-time exists). */
static int data_is_output(const pp_port_t *p)
{
    return (p->layout.outputs & PP_DATA_PINS) != 0;
}

/* funct parport.N.read: input lines to the -in and -in-not pins. */
static void pp_read(void *arg, long period)
{
    pp_port_t *p = arg;
    uint8_t data = 0, status, control = 0;
    uint32_t pins;
    (void)period;
    if (pp_io_begin(&p->io) != 0)
        return;
    status = pp_io_read_status(&p->io);
    if (p->mode == PP_MODE_IN)
        data = pp_io_read_data(&p->io);
    if (p->mode == PP_MODE_X)
        control = pp_io_read_control(&p->io);
    pins = pp_pins_from_registers(p->mode, data, status, control);
    for (int n = 1; n <= PP_LAST_PIN; n++) {
        if (!(p->layout.inputs & PP_PIN(n)))
            continue;
        *p->in[n] = (pins >> n) & 1;
        *p->in_not[n] = !*p->in[n];
    }
}

/* Write the data and control registers for levels, each only when it changed. */
static void pp_output(pp_port_t *p, uint32_t levels)
{
    long long now = rtapi_get_time();
    if (data_is_output(p)) {
        uint8_t data = pp_data_from_pins(levels);
        if (!p->data_valid || data != p->data_written) {
            pp_io_write_data(&p->io, data);
            p->data_written = data;
            p->data_valid = 1;
            p->data_time_ns = now;
        }
    }
    uint8_t control = pp_control_from_pins(p->mode, levels);
    if (!p->control_valid || control != p->control_written) {
        pp_io_write_control(&p->io, control);
        p->control_written = control;
        p->control_valid = 1;
        p->control_time_ns = now;
    }
    p->levels = levels;
}

/* funct parport.N.write: -out pins (xor -out-invert) to the output lines. */
static void pp_write(void *arg, long period)
{
    pp_port_t *p = arg;
    uint32_t levels = 0;
    (void)period;
    if (pp_io_begin(&p->io) != 0)
        return;
    for (int n = 1; n <= PP_LAST_PIN; n++)
        if ((p->layout.outputs & PP_PIN(n)) && (*p->out[n] ^ p->out_invert[n]))
            levels |= PP_PIN(n);
    pp_output(p, levels);
}

/* Busy-wait until deadline_ns (at most a quarter period, see pp_reset). */
static void wait_until(long long deadline_ns)
{
    while (rtapi_get_time() < deadline_ns)
        ;
}

/* funct parport.N.reset: reset-time after write, put -out-reset pins back to their inactive level. */
static void pp_reset(void *arg, long period)
{
    pp_port_t *p = arg;
    uint32_t reset_mask = 0, invert_mask = 0, levels;
    if (pp_io_begin(&p->io) != 0)
        return;
    if (p->reset_time > (hal_u32_t)(period / 4))
        p->reset_time = (hal_u32_t)(period / 4);
    for (int n = 1; n <= PP_LAST_PIN; n++) {
        if (!(p->layout.outputs & PP_PIN(n)))
            continue;
        if (p->out_reset[n])
            reset_mask |= PP_PIN(n);
        if (p->out_invert[n])
            invert_mask |= PP_PIN(n);
    }
    levels = pp_reset_levels(p->levels, reset_mask, invert_mask);
    if (data_is_output(p) && p->data_valid && pp_data_from_pins(levels) != p->data_written)
        wait_until(p->data_time_ns + p->reset_time);
    if (p->control_valid && pp_control_from_pins(p->mode, levels) != p->control_written)
        wait_until(p->control_time_ns + p->reset_time);
    pp_output(p, levels);
}

/* funct parport.read-all. */
static void pp_read_all(void *arg, long period)
{
    (void)arg;
    for (int i = 0; i < port_count; i++)
        pp_read(&ports[i], period);
}

/* funct parport.write-all. */
static void pp_write_all(void *arg, long period)
{
    (void)arg;
    for (int i = 0; i < port_count; i++)
        pp_write(&ports[i], period);
}

/* Create the pins and params of one output line. */
static int export_output(pp_port_t *p, int index, int n)
{
    int r = hal_pin_bit_newf(HAL_IN, &p->out[n], comp_id, "parport.%d.pin-%02d-out", index, n);
    if (r == 0)
        r = hal_param_bit_newf(HAL_RW, &p->out_invert[n], comp_id, "parport.%d.pin-%02d-out-invert", index, n);
    if (r == 0)
        r = hal_param_bit_newf(HAL_RW, &p->out_reset[n], comp_id, "parport.%d.pin-%02d-out-reset", index, n);
    return r;
}

/* Create the pins of one input line. */
static int export_input(pp_port_t *p, int index, int n)
{
    int r = hal_pin_bit_newf(HAL_OUT, &p->in[n], comp_id, "parport.%d.pin-%02d-in", index, n);
    if (r == 0)
        r = hal_pin_bit_newf(HAL_OUT, &p->in_not[n], comp_id, "parport.%d.pin-%02d-in-not", index, n);
    if (r == 0)
        *p->in[n] = *p->in_not[n] = 0;
    return r;
}

/* Create every HAL object of port index. */
static int export_port(pp_port_t *p, int index)
{
    char name[HAL_NAME_LEN + 1];
    int r = 0;
    for (int n = 1; n <= PP_LAST_PIN && r == 0; n++) {
        if (p->layout.outputs & PP_PIN(n))
            r = export_output(p, index, n);
        else if (p->layout.inputs & PP_PIN(n))
            r = export_input(p, index, n);
    }
    if (r == 0 && data_is_output(p)) {
        r = hal_param_u32_newf(HAL_RW, &p->reset_time, comp_id, "parport.%d.reset-time", index);
        if (r == 0) r = hal_param_u32_newf(HAL_RW, &p->debug1, comp_id, "parport.%d.debug1", index);
        if (r == 0) r = hal_param_u32_newf(HAL_RW, &p->debug2, comp_id, "parport.%d.debug2", index);
    }
    rtapi_snprintf(name, sizeof(name), "parport.%d.read", index);
    if (r == 0) r = hal_export_funct(name, pp_read, p, 0, 0, comp_id);
    rtapi_snprintf(name, sizeof(name), "parport.%d.write", index);
    if (r == 0) r = hal_export_funct(name, pp_write, p, 0, 0, comp_id);
    rtapi_snprintf(name, sizeof(name), "parport.%d.reset", index);
    if (r == 0) r = hal_export_funct(name, pp_reset, p, 0, 0, comp_id);
    return r;
}

/* Close every port opened so far. */
static void close_ports(void)
{
    for (int i = 0; ports && i < port_count; i++)
        pp_io_close(&ports[i].io);
}

/* Open and export every configured port. */
static int setup_ports(const pp_port_cfg_t *cfgs)
{
    int r = 0;
    ports = hal_malloc(sizeof(*ports) * port_count);
    if (!ports) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: out of HAL memory\n");
        return -ENOMEM;
    }
    memset(ports, 0, sizeof(*ports) * port_count);
    for (int i = 0; i < port_count; i++)
        ports[i].io.fd = -1;
    for (int i = 0; i < port_count && r == 0; i++) {
        ports[i].mode = cfgs[i].mode;
        ports[i].layout = pp_layout(cfgs[i].mode);
        r = pp_io_open(&ports[i].io, &cfgs[i]);
        if (r == 0)
            r = export_port(&ports[i], i);
    }
    if (r == 0) r = hal_export_funct("parport.read-all", pp_read_all, NULL, 0, 0, comp_id);
    if (r == 0) r = hal_export_funct("parport.write-all", pp_write_all, NULL, 0, 0, comp_id);
    return r;
}

/* Parse cfg, claim the ports and create the HAL objects. */
int rtapi_app_main(void)
{
    pp_port_cfg_t cfgs[PP_MAX_PORTS];
    char err[PP_ERROR_LEN];
    int r;
    rtapi_print("config string '%s'\n", cfg ? cfg : "");
    port_count = pp_cfg_parse(cfg, cfgs, err);
    if (port_count < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s\n", err);
        port_count = 0;
        return -EINVAL;
    }
    if (port_count == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "PARPORT: ERROR: no ports configured\n");
        return -1;
    }
    comp_id = hal_init("hal_parport");
    if (comp_id < 0)
        return comp_id;
    r = setup_ports(cfgs);
    if (r != 0) {
        close_ports();
        hal_exit(comp_id);
        return r;
    }
    hal_ready(comp_id);
    return 0;
}

/* Release the ports and remove the component. */
void rtapi_app_exit(void)
{
    close_ports();
    hal_exit(comp_id);
}
