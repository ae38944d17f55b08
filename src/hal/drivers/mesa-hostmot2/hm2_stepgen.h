/* hm2_stepgen.h: stepgen register bits and the helpers shared by its set-up and cycle files. */
#ifndef HM2_STEPGEN_H
#define HM2_STEPGEN_H

#define HM2_STEPGEN_MODE_TYPE_MASK 0x3u
#define HM2_STEPGEN_MODE_TABLE 0x3u
#define HM2_STEPGEN_MODE_SWAP (1u << 2)
#define HM2_STEPGEN_MODE_LATCH_ON_INDEX (1u << 4)
#define HM2_STEPGEN_MODE_INDEX_POLARITY (1u << 5)
#define HM2_STEPGEN_MODE_LATCH_ON_PROBE (1u << 6)
#define HM2_STEPGEN_MODE_PROBE_POLARITY (1u << 7)
#define HM2_STEPGEN_TIMING_MAX 0x3FFFu
#define HM2_STEPGEN_TABLE_MAX 16
#define HM2_STEPGEN_MASTER_DDS 0xFFFFFFFFu

struct hm2_board;
/* Export the HAL objects of stepgen instance i (hm2_stepgen_hal.c). */
int hm2_stepgen_export_instance(struct hm2_board *hm2, int i);

#endif
