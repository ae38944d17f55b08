/* sim_od.h: the object dictionary of the simulated CiA 402 drive (cia402-sim). */
#ifndef SIM_OD_H
#define SIM_OD_H

#include <stdint.h>

#define SIM_OD_MAX 128
#define SIM_PDO_COUNT 2                 /* RPDO1-2 and TPDO1-2 */
#define SIM_MAP_ENTRIES 8

/* Access rights. */
enum { SIM_RO = 1, SIM_WO = 2, SIM_RW = 3 };

/* One object (index, sub-index) with its current and power-on values. */
typedef struct {
    uint16_t index;
    uint8_t sub;
    uint8_t size;                       /* bytes: 1, 2 or 4 */
    uint8_t access;
    uint8_t mappable;
    uint32_t value;
    uint32_t initial;
} sim_entry_t;

/* A node's dictionary. */
typedef struct {
    sim_entry_t entries[SIM_OD_MAX];
    int count;
} sim_od_t;

/* Fill od with the drive's objects at their power-on values for node_id. */
void sim_od_init(sim_od_t *od, int node_id);

/* Every object back to its power-on value (NMT reset node); comm_only: only 0x1000-0x1FFF. */
void sim_od_reset(sim_od_t *od, int comm_only);

/* The entry, or NULL. */
sim_entry_t *sim_od_find(sim_od_t *od, uint16_t index, uint8_t sub);

/* TRUE when any sub-index of index exists. */
int sim_od_has_index(const sim_od_t *od, uint16_t index);

/* The value of an entry (0 when it does not exist). */
uint32_t sim_od_get(sim_od_t *od, uint16_t index, uint8_t sub);

/* Store a value without any check (the drive's own updates). */
void sim_od_set(sim_od_t *od, uint16_t index, uint8_t sub, uint32_t value);

/* Pack the objects a PDO mapping names into data; returns the length in bytes. */
int sim_od_pack(sim_od_t *od, uint16_t map_index, uint8_t data[8]);

/* Unpack PDO data into the mapped objects; returns 0, or -1 when len is shorter than the mapping. */
int sim_od_unpack(sim_od_t *od, uint16_t map_index, const uint8_t *data, int len);

#endif
