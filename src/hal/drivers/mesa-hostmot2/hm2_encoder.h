/* hm2_encoder.h: encoder control bits and the encoder's pure helpers (register values, velocity). */
#ifndef HM2_ENCODER_H
#define HM2_ENCODER_H

#include <stdbool.h>
#include <stdint.h>

/* Control/status register (reg 1) low half. */
#define HM2_ENCODER_QUADRATURE_ERROR    (1u << 15)
#define HM2_ENCODER_AB_MASK_POLARITY    (1u << 14)
#define HM2_ENCODER_LATCH_ON_PROBE      (1u << 13)
#define HM2_ENCODER_PROBE_POLARITY      (1u << 12)
#define HM2_ENCODER_FILTER              (1u << 11)
#define HM2_ENCODER_COUNTER_MODE        (1u << 10)
#define HM2_ENCODER_INDEX_MASK          (1u << 9)
#define HM2_ENCODER_INDEX_MASK_POLARITY (1u << 8)
#define HM2_ENCODER_INDEX_JUSTONCE      (1u << 6)
#define HM2_ENCODER_CLEAR_ON_INDEX      (1u << 5)
#define HM2_ENCODER_LATCH_ON_INDEX      (1u << 4)
#define HM2_ENCODER_INDEX_POLARITY      (1u << 3)
#define HM2_ENCODER_INPUT_INDEX         (1u << 2)
#define HM2_ENCODER_INPUT_B             (1u << 1)
#define HM2_ENCODER_INPUT_A             (1u << 0)

enum { HM2_ENCODER_STOPPED = 0, HM2_ENCODER_MOVING = 1 };

/* Velocity estimator state of one encoder. */
typedef struct {
    int state;
    int64_t prev_event_count;
    int64_t prev_event_ticks;
    int prev_dir;
} hm2_encoder_vel_t;

/* TimestampDiv register: ~2 MHz timestamps, or ~10 MHz with hires. */
uint32_t hm2_encoder_timestamp_divider(uint32_t clock_hz, bool hires);
/* QFilterRate register for a sample frequency; *achieved gets the resulting frequency. */
uint32_t hm2_encoder_filter_rate(uint32_t clock_hz, uint32_t sample_hz, uint32_t *achieved);
/* Mux skew field (ns rounded to clock periods, max 15). */
uint32_t hm2_encoder_skew_bits(uint32_t clock_hz, uint32_t skew_ns);
/* Absolute ticks of an event timestamp ts seen with counter value tsc of epoch epoch. */
int64_t hm2_encoder_event_ticks(uint32_t epoch, uint16_t tsc, uint16_t ts);
/* One velocity update. new_counts: the count changed this cycle (event at event_ticks).
   Returns the velocity; *interp_offset gets position-interpolated minus position. */
double hm2_encoder_velocity(hm2_encoder_vel_t *v, double velocity, int64_t count64, bool new_counts,
                            int64_t event_ticks, int64_t now_ticks, double seconds_per_tick,
                            double scale, double vel_timeout, double *interp_offset);

struct hm2_board;
/* Export the HAL objects of encoder instance i (hm2_encoder_hal.c). */
int hm2_encoder_export_instance(struct hm2_board *hm2, int i);
/* True when the firmware has a module with this tag. */
bool hm2_md_has_gtag(struct hm2_board *hm2, int gtag);

#endif
