/* hm2_modules.h: state of each hostmot2 function module and the calls the core makes on it. */
#ifndef HM2_MODULES_H
#define HM2_MODULES_H

#include <stdbool.h>
#include <stdint.h>
#include "hal.h"
#include "hm2_encoder.h"
#include "hm2_stepgen_motion.h"

struct hm2_board;

/* ---- IOPort / GPIO (GTag 3) ---- */
typedef struct {
    hal_bit_t *in, *in_not, *out;
    hal_bit_t is_output, is_opendrain, invert_output;
} hm2_gpio_hal_t;

typedef struct {
    int num_instances;
    uint32_t clock_freq;
    uint32_t data_addr, ddr_addr, alt_source_addr, open_drain_addr, output_invert_addr;
    uint32_t *data_read, *data_write;                 /* TRAM */
    uint32_t *ddr, *alt_source, *open_drain, *output_invert;
    uint32_t *written_ddr, *written_open_drain, *written_output_invert;
} hm2_ioport_t;

/* ---- Watchdog (GTag 2) ---- */
typedef struct {
    hal_bit_t *has_bit;
    hal_u32_t timeout_ns;
} hm2_watchdog_hal_t;

typedef struct {
    int num_instances;
    uint32_t clock_freq;
    uint32_t timer_addr, status_addr, reset_addr;
    uint32_t *status_reg, *reset_reg;                 /* TRAM */
    hm2_watchdog_hal_t *hal;
    bool enable, written_enable;
    uint32_t written_timeout_ns;
} hm2_watchdog_t;

/* ---- Encoder / muxed encoder (GTag 4 / 12) ---- */
typedef struct {
    hal_s32_t *rawcounts, *rawlatch, *count, *count_latch;
    hal_float_t *position, *position_interpolated, *position_latch, *velocity, *velocity_rpm;
    hal_bit_t *reset, *index_enable, *no_clear_on_index, *probe_enable, *probe_invert;
    hal_bit_t *quad_error, *quad_error_enable, *input_a, *input_b, *input_idx;
    hal_float_t scale, vel_timeout;
    hal_bit_t index_invert, index_mask, index_mask_invert, counter_mode, filter;
} hm2_encoder_hal_t;

typedef struct {
    hm2_encoder_hal_t *hal;
    int64_t count64;           /* extended hardware count */
    uint16_t prev_hw_count;
    int64_t zero_offset;
    int64_t latch64;
    uint32_t written_control;
    bool control_written;
    bool prev_quad_error_enable, quad_error_reported;
    hm2_encoder_vel_t vel;     /* timestamp velocity estimator */
} hm2_encoder_instance_t;

typedef struct {
    hal_u32_t *sample_frequency, *muxed_skew;
    hal_bit_t *hires_timestamp;
    hal_s32_t *timer_number;
} hm2_encoder_global_hal_t;

typedef struct {
    int num_instances;
    bool muxed, has_probe;
    int version;
    uint32_t clock_freq;
    uint32_t counter_addr, latch_control_addr, timestamp_div_addr, timestamp_count_addr;
    uint32_t filter_rate_addr, dpll_timer_addr;
    uint32_t *counter_reg, *latch_control_reg, *timestamp_count_reg;  /* TRAM reads */
    hm2_encoder_global_hal_t *hal;
    hm2_encoder_instance_t *instance;
    uint32_t written_sample_frequency, written_skew;
    bool written_hires, globals_written, dpll_timer_usable;
    int32_t written_timer_number;
    uint32_t tsc_epoch;         /* rollovers of the 16-bit timestamp counter */
    uint16_t prev_tsc;
    double seconds_per_tick;
} hm2_encoder_t;

/* ---- StepGen (GTag 5) ---- */
typedef struct {
    hal_float_t *position_cmd, *velocity_cmd, *position_fb, *velocity_fb, *position_latch;
    hal_s32_t *counts, *dbg_step_rate;
    hal_bit_t *enable, *control_type, *position_reset, *index_enable, *probe_enable;
    hal_bit_t *index_invert, *probe_invert;
    hal_float_t *dbg_pos_minus_prev_cmd, *dbg_ff_vel, *dbg_s_to_match, *dbg_vel_error;
    hal_float_t *dbg_err_at_match;
    hal_float_t position_scale, maxvel, maxaccel;
    hal_u32_t steplen, stepspace, dirsetup, dirhold, step_type;
    hal_bit_t swap_step_dir;
    hal_u32_t table[4];
} hm2_stepgen_hal_t;

typedef struct {
    hm2_stepgen_hal_t *hal;
    uint32_t prev_accumulator;
    int64_t subcounts;
    double old_position_cmd;
    uint32_t written_steplen, written_stepspace, written_dirsetup, written_dirhold;
    uint32_t written_step_type, written_table[4], written_mode;
    bool written_swap, mode_written;
    int table_width;
} hm2_stepgen_instance_t;

typedef struct {
    int num_instances;
    int version;
    bool has_swap, has_index_probe;
    uint32_t clock_freq;
    uint32_t step_rate_addr, accumulator_addr, mode_addr, dir_setup_time_addr;
    uint32_t dir_hold_time_addr, pulse_width_addr, pulse_idle_width_addr;
    uint32_t table_sequence_data_addr, table_sequence_length_addr, master_dds_addr;
    uint32_t dpll_timer_addr;
    uint32_t *step_rate_reg, *accumulator_reg, *mode_reg;   /* TRAM */
    hal_s32_t *timer_number;
    int32_t written_timer_number;
    bool dpll_present;
    hm2_stepgen_instance_t *instance;
} hm2_stepgen_t;

/* ---- PWMGen (GTag 6) ---- */
typedef struct {
    hal_float_t *value;
    hal_bit_t *enable;
    hal_float_t scale;
    hal_s32_t output_type;
    hal_bit_t offset_mode, dither;
} hm2_pwmgen_hal_t;

typedef struct {
    hm2_pwmgen_hal_t *hal;
    int32_t written_output_type;
    bool written_offset_mode, written_dither, written_enable;
} hm2_pwmgen_instance_t;

typedef struct {
    hal_u32_t pwm_frequency, pdm_frequency;
} hm2_pwmgen_global_hal_t;

typedef struct {
    int num_instances;
    int version;
    uint32_t clock_freq;
    uint32_t pwm_value_addr, pwm_mode_addr, pwmgen_master_rate_dds_addr;
    uint32_t pdmgen_master_rate_dds_addr, enable_addr;
    uint32_t *pwm_value_reg;                                 /* TRAM */
    hm2_pwmgen_global_hal_t *hal;
    hm2_pwmgen_instance_t *instance;
    uint32_t pwm_bits, pwm_dds, pdm_dds;
    uint32_t written_pwm_frequency, written_pdm_frequency;
    bool config_written;
} hm2_pwmgen_t;

/* ---- LED (GTag 128) ---- */
typedef struct {
    hal_bit_t *led;
} hm2_led_hal_t;

typedef struct {
    int num_instances;       /* LEDs in use */
    uint32_t led_addr;
    hm2_led_hal_t *hal;
    uint32_t written;
    bool ever_written;
} hm2_led_t;

/* ---- DPLL (GTag 26) ---- */
typedef struct {
    hal_float_t *time_us[4], *base_freq, *phase_error;
    hal_u32_t *time_const, *plimit, *ddsize, *prescale;
} hm2_dpll_hal_t;

typedef struct {
    int num_instances;
    uint32_t clock_freq;
    uint32_t base_rate_addr, phase_err_addr, control_reg0_addr, control_reg1_addr;
    uint32_t timer_12_addr, timer_34_addr, hm2_dpll_sync_addr;
    uint32_t *control_reg1_read, *hm2_dpll_sync_reg;        /* TRAM reads */
    hm2_dpll_hal_t *hal;
    uint32_t written_base_rate, written_control0, written_control1, written_timer_12;
    uint32_t written_timer_34;
    unsigned writes_done;
    bool written_once;
} hm2_dpll_t;

/* ---- UART (GTag 9/10), PktUART (27/28), BSPI (14): the serial API's state ---- */
typedef struct {
    char name[HAL_NAME_LEN + 1];
    uint32_t clock_freq;
    uint32_t tx1_addr, tx2_addr, tx3_addr, tx4_addr, tx_fifo_count_addr, tx_bitrate_addr;
    uint32_t tx_mode_addr, rx1_addr, rx2_addr, rx3_addr, rx4_addr, rx_fifo_count_addr;
    uint32_t rx_bitrate_addr, rx_mode_addr;
    uint32_t bitrate;
    bool configured, warned_unconfigured;
} hm2_uart_instance_t;

typedef struct {
    int num_instances;
    hm2_uart_instance_t *instance;
} hm2_uart_t;

typedef struct {
    char name[HAL_NAME_LEN + 1];
    uint32_t clock_freq;
    int tx_version, rx_version;
    uint32_t tx_fifo_addr, tx_count_addr, tx_bitrate_addr, tx_mode_addr;
    uint32_t rx_fifo_addr, rx_count_addr, rx_bitrate_addr, rx_mode_addr;
    uint32_t *rx_status_reg, *tx_status_reg;                 /* TRAM reads */
    uint32_t tx_bitrate, rx_bitrate, tx_mode, rx_mode;
    bool tx_configured, rx_configured;
} hm2_pktuart_instance_t;

typedef struct {
    int num_instances;
    hm2_pktuart_instance_t *instance;
} hm2_pktuart_t;

#define HM2_BSPI_CHANNELS 16
#define HM2_BSPI_MAX_FRAMES 32

typedef struct {
    char name[HAL_NAME_LEN + 1];
    uint32_t clock_freq;
    uint32_t base_address, register_stride, instance_stride, count_addr, cd_addr[HM2_BSPI_CHANNELS];
    uint32_t addr[HM2_BSPI_CHANNELS];
    uint32_t cd[HM2_BSPI_CHANNELS];
    bool conf_flag[HM2_BSPI_CHANNELS];
    int num_frames;
    int (*read_function)(void *);
    int (*write_function)(void *);
    void *read_subdata, *write_subdata;
} hm2_bspi_instance_t;

typedef struct {
    int num_instances;
    hm2_bspi_instance_t *instance;
} hm2_bspi_t;

/* ---- raw register access (enable_raw) ---- */
typedef struct {
    hal_u32_t *read_address, *read_data, *write_address, *write_data;
    hal_bit_t *write_strobe, *dump_state;
} hm2_raw_hal_t;

typedef struct {
    hm2_raw_hal_t *hal;
    uint32_t read_word;
} hm2_raw_t;

/* ---- module entry points the core calls (each returns at once when unused) ---- */
int hm2_ioport_parse_md(struct hm2_board *hm2, int md_index);
int hm2_ioport_gpio_export_hal(struct hm2_board *hm2);
void hm2_ioport_gpio_process_tram_read(struct hm2_board *hm2);
void hm2_ioport_gpio_prepare_tram_write(struct hm2_board *hm2);
void hm2_ioport_write(struct hm2_board *hm2);
void hm2_ioport_force_write(struct hm2_board *hm2);
void hm2_ioport_gpio_read(struct hm2_board *hm2);
void hm2_ioport_gpio_write(struct hm2_board *hm2);
void hm2_ioport_cleanup(struct hm2_board *hm2);
void hm2_ioport_print_module(struct hm2_board *hm2);

int hm2_watchdog_parse_md(struct hm2_board *hm2, int md_index);
void hm2_watchdog_process_tram_read(struct hm2_board *hm2);
void hm2_watchdog_prepare_tram_write(struct hm2_board *hm2);
void hm2_watchdog_write(struct hm2_board *hm2, long period_ns);
void hm2_watchdog_force_write(struct hm2_board *hm2, bool clear_bite);
void hm2_watchdog_bite_now(struct hm2_board *hm2);
void hm2_watchdog_print_module(struct hm2_board *hm2);

int hm2_encoder_parse_md(struct hm2_board *hm2, int md_index);
void hm2_encoder_tram_init(struct hm2_board *hm2);
void hm2_encoder_process_tram_read(struct hm2_board *hm2, long period_ns);
void hm2_encoder_write(struct hm2_board *hm2);
void hm2_encoder_force_write(struct hm2_board *hm2);
void hm2_encoder_cleanup(struct hm2_board *hm2);
void hm2_encoder_print_module(struct hm2_board *hm2);

int hm2_stepgen_parse_md(struct hm2_board *hm2, int md_index);
void hm2_stepgen_tram_init(struct hm2_board *hm2);
void hm2_stepgen_process_tram_read(struct hm2_board *hm2, long period_ns);
void hm2_stepgen_prepare_tram_write(struct hm2_board *hm2, long period_ns);
void hm2_stepgen_write(struct hm2_board *hm2);
void hm2_stepgen_force_write(struct hm2_board *hm2);
void hm2_stepgen_allocate_pins(struct hm2_board *hm2);
void hm2_stepgen_cleanup(struct hm2_board *hm2);
void hm2_stepgen_print_module(struct hm2_board *hm2);

int hm2_pwmgen_parse_md(struct hm2_board *hm2, int md_index);
void hm2_pwmgen_prepare_tram_write(struct hm2_board *hm2);
void hm2_pwmgen_write(struct hm2_board *hm2);
void hm2_pwmgen_force_write(struct hm2_board *hm2);
void hm2_pwmgen_cleanup(struct hm2_board *hm2);
void hm2_pwmgen_print_module(struct hm2_board *hm2);

int hm2_led_parse_md(struct hm2_board *hm2, int md_index);
void hm2_led_write(struct hm2_board *hm2);

int hm2_dpll_parse_md(struct hm2_board *hm2, int md_index);
void hm2_dpll_process_tram_read(struct hm2_board *hm2, long period_ns);
void hm2_dpll_write(struct hm2_board *hm2, long period_ns);
void hm2_dpll_force_write(struct hm2_board *hm2);
void hm2_dpll_cleanup(struct hm2_board *hm2);

int hm2_uart_parse_md(struct hm2_board *hm2, int md_index);
void hm2_uart_cleanup(struct hm2_board *hm2);
int hm2_pktuart_parse_md(struct hm2_board *hm2, int md_index);
void hm2_pktuart_cleanup(struct hm2_board *hm2);
int hm2_bspi_parse_md(struct hm2_board *hm2, int md_index);
void hm2_bspi_process_tram_read(struct hm2_board *hm2);
void hm2_bspi_prepare_tram_write(struct hm2_board *hm2);
void hm2_bspi_cleanup(struct hm2_board *hm2);

int hm2_raw_setup(struct hm2_board *hm2);
void hm2_raw_queue_read(struct hm2_board *hm2);
void hm2_raw_process_read(struct hm2_board *hm2);
void hm2_raw_write(struct hm2_board *hm2);

#endif
