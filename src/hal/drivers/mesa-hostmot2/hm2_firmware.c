/* hm2_firmware.c: firmware= handling: bitfile lookup (OPENEMC_FIRMWARE_DIR or /lib/firmware), part check, programming. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rtapi_errno.h"
#include "hm2.h"
#include "hm2_firmware.h"

#define FIRMWARE_MAX_BYTES (16 * 1024 * 1024)

/* Read the whole firmware file into memory; NULL when missing or unreadable. */
static uint8_t *read_firmware(const char *name, char *path, size_t pathlen, size_t *size)
{
    const char *dir = getenv("OPENEMC_FIRMWARE_DIR");
    snprintf(path, pathlen, "%s/%s", dir && *dir ? dir : "/lib/firmware", name);
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    uint8_t *data = malloc(FIRMWARE_MAX_BYTES);
    *size = data ? fread(data, 1, FIRMWARE_MAX_BYTES, f) : 0;
    fclose(f);
    return data;
}

/* Load, check and program the requested firmware. */
int hm2_load_firmware(hm2_board_t *hm2)
{
    char path[512];
    size_t size = 0;
    hm2_bitfile_t bf;
    if (strlen(hm2->config.firmware) > HM2_FIRMWARE_NAME_MAX) {
        HM2_ERR(hm2, "requested firmware name '%s' is too long (max length is %d)\n",
                hm2->config.firmware, HM2_FIRMWARE_NAME_MAX);
        return -EINVAL;
    }
    uint8_t *data = read_firmware(hm2->config.firmware, path, sizeof(path), &size);
    int r = 0;
    if (!data) {
        HM2_ERR(hm2, "firmware %s not found\n", hm2->config.firmware);
        HM2_ERR(hm2, "install the package containing the firmware.\n");
        return -ENOENT;
    }
    if (hm2_bitfile_parse(data, size, &bf) < 0) {
        HM2_ERR(hm2, "firmware %s is not a valid Xilinx bitfile\n", path);
        r = -EINVAL;
    } else if (!hm2_fpga_part_matches(hm2->llio->fpga_part_number, bf.part)) {
        HM2_ERR(hm2, "board has FPGA '%s', but the firmware in %s is for FPGA '%s'\n",
                hm2->llio->fpga_part_number, path, bf.part);
        r = -EINVAL;
    } else {
        r = hm2->llio->ops->program_fpga(hm2->llio, bf.bits, bf.size);
        if (r < 0)
            HM2_ERR(hm2, "failed to program fpga, aborting hm2_register\n");
    }
    free(data);
    return r;
}
