/* hm2_firmware.h: find a Xilinx bitfile, check its FPGA part and hand its bits to the board driver. */
#ifndef HM2_FIRMWARE_H
#define HM2_FIRMWARE_H

#include <stddef.h>
#include <stdint.h>

/* The parts of a .bit file hostmot2 uses. */
typedef struct {
    char design[128];
    char part[64];
    const uint8_t *bits;
    size_t size;
} hm2_bitfile_t;

/* Parse a Xilinx bitfile held in data (size bytes); 0 or -EINVAL. */
int hm2_bitfile_parse(const uint8_t *data, size_t size, hm2_bitfile_t *bf);
/* True when a bitfile part ("6slx9tqg144") names the board's FPGA ("XC6SLX9"...). */
int hm2_fpga_part_matches(const char *board_part, const char *bitfile_part);

struct hm2_board;
/* Load config firmware= into the board when its driver can program it; 0 or -errno. */
int hm2_load_firmware(struct hm2_board *hm2);

#endif
