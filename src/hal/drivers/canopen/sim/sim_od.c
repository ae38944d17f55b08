/* sim_od.c: the simulated drive's object dictionary: CiA 301 communication objects, the CiA 402
   process values, two vendor objects for tests, and PDO packing by mapping. */
#include <string.h>
#include "../canopen.h"
#include "sim_od.h"

#define DEVICE_TYPE_SERVO 0x00020192u   /* CiA 402, servo drive */
#define VENDOR_ID 0x4F454D43u           /* "OEMC" */
#define SUPPORTED_MODES 0x00000081u     /* profile position (bit 0) and CSP (bit 7) */
#define TYPE_ASYNC 255
#define VENDOR_PARAMS 0x2000u
#define VENDOR_READ_ONLY 0x2001u

/* Append one object. */
static void add(sim_od_t *od, uint16_t index, uint8_t sub, uint8_t size, uint8_t access, uint8_t mappable,
                uint32_t initial)
{
    sim_entry_t *e = &od->entries[od->count++];
    *e = (sim_entry_t){ index, sub, size, access, mappable, initial, initial };
}

/* RPDOn/TPDOn communication and mapping objects; mapping holds the power-on entries. */
static void add_pdo(sim_od_t *od, uint16_t comm, uint16_t map, uint32_t cob_id, const uint32_t *mapping, int n)
{
    add(od, comm, 0, 1, SIM_RO, 0, 2);
    add(od, comm, 1, 4, SIM_RW, 0, cob_id);
    add(od, comm, 2, 1, SIM_RW, 0, TYPE_ASYNC);
    add(od, map, 0, 1, SIM_RW, 0, (uint32_t)n);
    for (int i = 1; i <= SIM_MAP_ENTRIES; i++)
        add(od, map, (uint8_t)i, 4, SIM_RW, 0, i <= n ? mapping[i - 1] : 0);
}

/* Fill od with the drive's objects at their power-on values for node_id. */
void sim_od_init(sim_od_t *od, int node_id)
{
    static const uint32_t rpdo1[] = { CO_MAP(CIA402_CONTROLWORD, 0, 16) };
    static const uint32_t tpdo1[] = { CO_MAP(CIA402_STATUSWORD, 0, 16) };
    od->count = 0;
    add(od, 0x1000, 0, 4, SIM_RO, 0, DEVICE_TYPE_SERVO);
    add(od, CO_OBJ_ERROR_REGISTER, 0, 1, SIM_RO, 1, 0);
    add(od, CO_OBJ_SYNC_COB_ID, 0, 4, SIM_RW, 0, CO_SYNC);
    add(od, CO_OBJ_CYCLE_PERIOD, 0, 4, SIM_RW, 0, 0);
    add(od, CO_OBJ_HEARTBEAT_TIME, 0, 2, SIM_RW, 0, 0);
    add(od, 0x1018, 0, 1, SIM_RO, 0, 1);
    add(od, 0x1018, 1, 4, SIM_RO, 0, VENDOR_ID);
    add_pdo(od, CO_OBJ_RPDO_COMM, CO_OBJ_RPDO_MAP, CO_RPDO1 + node_id, rpdo1, 1);
    add_pdo(od, CO_OBJ_RPDO_COMM + 1, CO_OBJ_RPDO_MAP + 1, CO_PDO_INVALID | (CO_RPDO2 + node_id), NULL, 0);
    add_pdo(od, CO_OBJ_TPDO_COMM, CO_OBJ_TPDO_MAP, CO_TPDO1 + node_id, tpdo1, 1);
    add_pdo(od, CO_OBJ_TPDO_COMM + 1, CO_OBJ_TPDO_MAP + 1, CO_PDO_INVALID | (CO_TPDO2 + node_id), NULL, 0);
    add(od, VENDOR_PARAMS, 0, 1, SIM_RO, 0, 4);
    for (uint8_t i = 1; i <= 4; i++)
        add(od, VENDOR_PARAMS, i, 4, SIM_RW, 0, 0);
    add(od, VENDOR_READ_ONLY, 0, 4, SIM_RO, 0, 0x12345678u);
    add(od, CIA402_ERROR_CODE, 0, 2, SIM_RO, 1, 0);
    add(od, CIA402_CONTROLWORD, 0, 2, SIM_RW, 1, 0);
    add(od, CIA402_STATUSWORD, 0, 2, SIM_RO, 1, 0);
    add(od, CIA402_MODE, 0, 1, SIM_RW, 1, 0);
    add(od, CIA402_MODE_DISPLAY, 0, 1, SIM_RO, 1, 0);
    add(od, CIA402_POSITION_ACTUAL, 0, 4, SIM_RO, 1, 0);
    add(od, CIA402_VELOCITY_ACTUAL, 0, 4, SIM_RO, 1, 0);
    add(od, CIA402_TORQUE_ACTUAL, 0, 2, SIM_RO, 1, 0);
    add(od, CIA402_TARGET_POSITION, 0, 4, SIM_RW, 1, 0);
    add(od, CIA402_INTERPOLATION_PERIOD, 0, 1, SIM_RO, 0, 2);
    add(od, CIA402_INTERPOLATION_PERIOD, 1, 1, SIM_RW, 0, 0);
    add(od, CIA402_INTERPOLATION_PERIOD, 2, 1, SIM_RW, 0, (uint8_t)-3);
    add(od, 0x6502, 0, 4, SIM_RO, 0, SUPPORTED_MODES);
}

/* Every object back to its power-on value; comm_only: only 0x1000-0x1FFF. */
void sim_od_reset(sim_od_t *od, int comm_only)
{
    for (int i = 0; i < od->count; i++)
        if (!comm_only || od->entries[i].index < 0x2000)
            od->entries[i].value = od->entries[i].initial;
}

/* The entry, or NULL. */
sim_entry_t *sim_od_find(sim_od_t *od, uint16_t index, uint8_t sub)
{
    for (int i = 0; i < od->count; i++)
        if (od->entries[i].index == index && od->entries[i].sub == sub)
            return &od->entries[i];
    return NULL;
}

/* TRUE when any sub-index of index exists. */
int sim_od_has_index(const sim_od_t *od, uint16_t index)
{
    for (int i = 0; i < od->count; i++)
        if (od->entries[i].index == index)
            return 1;
    return 0;
}

/* The value of an entry (0 when it does not exist). */
uint32_t sim_od_get(sim_od_t *od, uint16_t index, uint8_t sub)
{
    sim_entry_t *e = sim_od_find(od, index, sub);
    return e ? e->value : 0;
}

/* Store a value without any check. */
void sim_od_set(sim_od_t *od, uint16_t index, uint8_t sub, uint32_t value)
{
    sim_entry_t *e = sim_od_find(od, index, sub);
    if (e)
        e->value = value;
}

/* Pack the objects a PDO mapping names into data; returns the length in bytes. */
int sim_od_pack(sim_od_t *od, uint16_t map_index, uint8_t data[8])
{
    int n = (int)sim_od_get(od, map_index, 0), at = 0;
    memset(data, 0, 8);
    for (int i = 1; i <= n && i <= SIM_MAP_ENTRIES; i++) {
        uint32_t m = sim_od_get(od, map_index, (uint8_t)i);
        int bytes = (int)(m & 0xFF) / 8;
        uint32_t v = sim_od_get(od, (uint16_t)(m >> 16), (uint8_t)(m >> 8));
        for (int b = 0; b < bytes && at < 8; b++)
            data[at++] = (uint8_t)(v >> (8 * b));
    }
    return at;
}

/* Unpack PDO data into the mapped objects; returns 0, or -1 when len is shorter than the mapping. */
int sim_od_unpack(sim_od_t *od, uint16_t map_index, const uint8_t *data, int len)
{
    int n = (int)sim_od_get(od, map_index, 0), at = 0;
    for (int i = 1; i <= n && i <= SIM_MAP_ENTRIES; i++) {
        uint32_t m = sim_od_get(od, map_index, (uint8_t)i), v = 0;
        int bytes = (int)(m & 0xFF) / 8;
        if (at + bytes > len)
            return -1;
        for (int b = 0; b < bytes; b++)
            v |= (uint32_t)data[at++] << (8 * b);
        sim_od_set(od, (uint16_t)(m >> 16), (uint8_t)(m >> 8), v);
    }
    return 0;
}
