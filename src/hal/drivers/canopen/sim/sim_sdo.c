/* sim_sdo.c: the simulated drive's SDO server: expedited uploads and downloads, with the checks a
   real drive makes (access, length, PDO mapping rules, supported modes). */
#include <string.h>
#include "sim_drive.h"

#define MAP_BITS_MAX 64

/* Send an SDO answer: cmd byte, the request's index and sub, 4 data bytes. */
static void answer(sim_drive_t *d, uint8_t cmd, uint16_t index, uint8_t sub, uint32_t value)
{
    co_frame_t f = { .id = (uint16_t)(CO_SDO_TX + d->node_id), .len = 8 };
    if (d->bad_sdo_next) {
        d->bad_sdo_next = 0;
        f.len = 3;
    }
    f.data[0] = cmd;
    co_put16(&f.data[1], index);
    f.data[3] = sub;
    co_put32(&f.data[4], value);
    d->send(d->ctx, &f);
}

/* TRUE for RPDO and TPDO mapping objects (0x1600-0x17FF, 0x1A00-0x1BFF). */
static int is_mapping(uint16_t index)
{
    return (index >= 0x1600 && index <= 0x17FF) || (index >= 0x1A00 && index <= 0x1BFF);
}

/* TRUE for RPDO and TPDO communication objects (0x1400-0x15FF, 0x1800-0x19FF). */
static int is_communication(uint16_t index)
{
    return (index >= 0x1400 && index <= 0x15FF) || (index >= 0x1800 && index <= 0x19FF);
}

/* The mapping object's PDO communication object (0x16xx -> 0x14xx, 0x1Axx -> 0x18xx). */
static uint16_t comm_of(uint16_t map_index)
{
    return (uint16_t)(map_index - 0x200);
}

/* Checks on a write to a PDO mapping object; 0 or an abort code. */
static uint32_t check_mapping(sim_drive_t *d, uint16_t index, uint8_t sub, uint32_t value)
{
    int bits = 0;
    if (!(sim_od_get(&d->od, comm_of(index), 1) & CO_PDO_INVALID))
        return CO_ABORT_DEVICE_STATE;
    if (sub > 0) {
        sim_entry_t *target = sim_od_find(&d->od, (uint16_t)(value >> 16), (uint8_t)(value >> 8));
        if (sim_od_get(&d->od, index, 0) != 0)
            return CO_ABORT_UNSUPPORTED_ACCESS;
        if (!target || !target->mappable || target->size * 8 != (int)(value & 0xFF))
            return CO_ABORT_NOT_MAPPABLE;
        return 0;
    }
    if (value > SIM_MAP_ENTRIES)
        return CO_ABORT_VALUE_RANGE;
    for (uint32_t i = 1; i <= value; i++)
        bits += (int)(sim_od_get(&d->od, index, (uint8_t)i) & 0xFF);
    return bits > MAP_BITS_MAX ? CO_ABORT_PDO_TOO_LONG : 0;
}

/* Checks on a write to a PDO COB-ID: a valid PDO keeps its COB-ID. */
static uint32_t check_cob_id(sim_drive_t *d, sim_entry_t *e, uint32_t value)
{
    if (!(e->value & CO_PDO_INVALID) && !(value & CO_PDO_INVALID) && value != e->value)
        return CO_ABORT_VALUE_RANGE;
    (void)d;
    return 0;
}

/* Every check of a download; 0 or an abort code. */
static uint32_t check_write(sim_drive_t *d, sim_entry_t *e, int size, uint32_t value)
{
    int8_t mode = (int8_t)value;
    if (!(e->access & SIM_WO))
        return CO_ABORT_READ_ONLY;
    if (size && size != e->size)
        return CO_ABORT_LENGTH;
    if (is_mapping(e->index))
        return check_mapping(d, e->index, e->sub, value);
    if (is_communication(e->index) && e->sub == 1)
        return check_cob_id(d, e, value);
    if (e->index == CIA402_MODE && mode != 0 && mode != 1 && mode != CIA402_MODE_CSP)
        return CO_ABORT_VALUE_RANGE;
    return 0;
}

/* The entry a request names, or 0 with the abort code in *abort_code. */
static sim_entry_t *entry_for(sim_drive_t *d, uint16_t index, uint8_t sub, uint32_t *abort_code)
{
    sim_entry_t *e = sim_od_find(&d->od, index, sub);
    if (!e)
        *abort_code = sim_od_has_index(&d->od, index) ? CO_ABORT_NO_SUBINDEX : CO_ABORT_NO_OBJECT;
    return e;
}

/* Initiate download, expedited only. */
static void download(sim_drive_t *d, const co_frame_t *f, uint16_t index, uint8_t sub)
{
    uint8_t cmd = f->data[0];
    int size = (cmd & CO_SDO_SIZE_SET) ? 4 - ((cmd >> 2) & 3) : 0;
    uint32_t value = co_get32(&f->data[4]), abort_code = 0;
    sim_entry_t *e;
    if (!(cmd & CO_SDO_EXPEDITED)) {
        answer(d, CO_SDO_ABORT, index, sub, CO_ABORT_COMMAND);
        return;
    }
    if (size)
        value &= size == 4 ? 0xFFFFFFFFu : (1u << (8 * size)) - 1;
    e = entry_for(d, index, sub, &abort_code);
    if (e)
        abort_code = check_write(d, e, size, value);
    if (abort_code) {
        sim_logf(d, "node %d: sdo write %04X:%02X = %u refused (0x%08X)", d->node_id, index, sub, value,
                 abort_code);
        answer(d, CO_SDO_ABORT, index, sub, abort_code);
        return;
    }
    e->value = value;
    sim_logf(d, "node %d: sdo write %04X:%02X = %u (0x%X)", d->node_id, index, sub, value, value);
    answer(d, CO_SDO_SCS_DOWNLOAD, index, sub, 0);
}

/* Initiate upload, answered expedited. */
static void upload(sim_drive_t *d, uint16_t index, uint8_t sub)
{
    uint32_t abort_code = 0;
    sim_entry_t *e = entry_for(d, index, sub, &abort_code);
    if (e && !(e->access & SIM_RO))
        abort_code = CO_ABORT_WRITE_ONLY;
    if (abort_code) {
        answer(d, CO_SDO_ABORT, index, sub, abort_code);
        return;
    }
    answer(d, (uint8_t)(CO_SDO_SCS_UPLOAD | CO_SDO_EXPEDITED | CO_SDO_SIZE_SET | ((4 - e->size) << 2)), index,
           sub, e->value);
}

/* The SDO server: answer one request frame (not while stopped). */
void sim_sdo_request(sim_drive_t *d, const co_frame_t *f)
{
    uint16_t index;
    uint8_t sub;
    if (d->nmt == CO_STATE_STOPPED || f->len != 8)
        return;
    index = co_get16(&f->data[1]);
    sub = f->data[3];
    switch (f->data[0] & 0xE0) {
    case CO_SDO_CCS_DOWNLOAD: download(d, f, index, sub); break;
    case CO_SDO_CCS_UPLOAD: upload(d, index, sub); break;
    case CO_SDO_ABORT: break;
    default: answer(d, CO_SDO_ABORT, index, sub, CO_ABORT_COMMAND); break;
    }
}
