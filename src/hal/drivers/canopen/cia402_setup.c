/* cia402_setup.c: build the set-up sequence of one drive: pre-operational, heartbeat, PDO mapping
   (RPDO1 controlword + target position, TPDO1 statusword + position, TPDO2 velocity + torque),
   CSP mode, the period objects, the configuration's own SDO lines, then NMT start. */
#include "canopen.h"
#include "cia402_setup.h"

#define CO_MAP_BITS_16 16
#define CO_MAP_BITS_32 32
#define NS_PER_S 1000000000LL
#define INTERP_DIGITS_MAX 255

/* Builder state: the array and its fill level. */
typedef struct {
    cia402_step_t *steps;
    int count;
    const char *what;
    int line;
} builder_t;

/* Append one SDO write step. */
static void sdo(builder_t *b, uint16_t index, uint8_t sub, uint8_t size, uint32_t value)
{
    cia402_step_t *s = &b->steps[b->count++];
    s->kind = CIA402_STEP_SDO;
    s->value_kind = CIA402_VALUE_FIXED;
    s->write.index = index;
    s->write.sub = sub;
    s->write.size = size;
    s->write.value = value;
    s->what = b->what;
    s->line = b->line;
}

/* Append the steps that map entries[] into one PDO (disable, clear, map, count, type, enable). */
static void map_pdo(builder_t *b, uint16_t comm, uint16_t map, uint32_t cob_id, const uint32_t *entries, int n)
{
    sdo(b, comm, 1, 4, cob_id | CO_PDO_INVALID);
    sdo(b, map, 0, 1, 0);
    for (int i = 0; i < n; i++)
        sdo(b, map, (uint8_t)(i + 1), 4, entries[i]);
    sdo(b, map, 0, 1, (uint32_t)n);
    sdo(b, comm, 2, 1, CO_PDO_SYNC_EVERY);
    sdo(b, comm, 1, 4, cob_id);
}

/* Append a step that only carries its kind. */
static void bare(builder_t *b, cia402_step_kind_t kind)
{
    cia402_step_t *s = &b->steps[b->count++];
    s->kind = kind;
    s->value_kind = CIA402_VALUE_FIXED;
    s->what = b->what;
    s->line = b->line;
}

/* The PDO mappings and the mode of operation. */
static void add_pdos(builder_t *b, const cia402_drive_cfg_t *d)
{
    static const uint32_t rpdo1[] = { CO_MAP(CIA402_CONTROLWORD, 0, CO_MAP_BITS_16),
                                      CO_MAP(CIA402_TARGET_POSITION, 0, CO_MAP_BITS_32) };
    static const uint32_t tpdo1[] = { CO_MAP(CIA402_STATUSWORD, 0, CO_MAP_BITS_16),
                                      CO_MAP(CIA402_POSITION_ACTUAL, 0, CO_MAP_BITS_32) };
    static const uint32_t tpdo2[] = { CO_MAP(CIA402_VELOCITY_ACTUAL, 0, CO_MAP_BITS_32),
                                      CO_MAP(CIA402_TORQUE_ACTUAL, 0, CO_MAP_BITS_16) };
    b->what = "the RPDO1 mapping (controlword, target position)";
    map_pdo(b, CO_OBJ_RPDO_COMM, CO_OBJ_RPDO_MAP, CO_RPDO1 + d->node_id, rpdo1, 2);
    b->what = "the TPDO1 mapping (statusword, position actual value)";
    map_pdo(b, CO_OBJ_TPDO_COMM, CO_OBJ_TPDO_MAP, CO_TPDO1 + d->node_id, tpdo1, 2);
    if (d->velocity_feedback) {
        b->what = "the TPDO2 mapping (velocity and torque actual values)";
        b->line = d->velocity_line ? d->velocity_line : d->section_line;
        map_pdo(b, CO_OBJ_TPDO_COMM + 1, CO_OBJ_TPDO_MAP + 1, CO_TPDO2 + d->node_id, tpdo2, 2);
        b->line = d->section_line;
    }
    b->what = "the mode of operation (cyclic synchronous position)";
    sdo(b, CIA402_MODE, 0, 1, CIA402_MODE_CSP);
}

/* The objects that carry the thread period. */
static void add_period(builder_t *b, const cia402_drive_cfg_t *d)
{
    if (!d->sync_period_objects)
        return;
    b->line = d->sync_line ? d->sync_line : d->section_line;
    b->what = "the communication cycle period";
    sdo(b, CO_OBJ_CYCLE_PERIOD, 0, 4, 0);
    b->steps[b->count - 1].value_kind = CIA402_VALUE_CYCLE_US;
    b->what = "the interpolation time period";
    sdo(b, CIA402_INTERPOLATION_PERIOD, 1, 1, 0);
    b->steps[b->count - 1].value_kind = CIA402_VALUE_INTERP_DIGITS;
    sdo(b, CIA402_INTERPOLATION_PERIOD, 2, 1, 0);
    b->steps[b->count - 1].value_kind = CIA402_VALUE_INTERP_EXPONENT;
    b->line = d->section_line;
}

/* Fill steps[] for drive d; returns the count. */
int cia402_setup_build(const cia402_drive_cfg_t *d, cia402_step_t steps[CIA402_SETUP_MAX])
{
    builder_t b = { steps, 0, "the NMT pre-operational command", d->section_line };
    bare(&b, CIA402_STEP_PRE_OPERATIONAL);
    b.what = "the heartbeat time";
    b.line = d->heartbeat_line ? d->heartbeat_line : d->section_line;
    sdo(&b, CO_OBJ_HEARTBEAT_TIME, 0, 2, (uint32_t)d->heartbeat_ms);
    b.line = d->section_line;
    add_pdos(&b, d);
    add_period(&b, d);
    b.what = "the SDO line";
    for (int i = 0; i < d->sdo_count; i++) {
        b.line = d->sdo[i].line;
        sdo(&b, d->sdo[i].write.index, d->sdo[i].write.sub, d->sdo[i].write.size, d->sdo[i].write.value);
    }
    b.what = "the NMT start command";
    b.line = d->section_line;
    bare(&b, CIA402_STEP_START);
    return b.count;
}

/* The interpolation period as digits x 10^exponent s: the coarsest exact unit, else rounded. */
static void interp_period(long period_ns, uint32_t *digits, int *exponent)
{
    long long unit = NS_PER_S / 1000;
    for (int e = -3; e >= -9; e--, unit /= 10) {
        long long v = unit ? period_ns / unit : 0;
        if (unit && period_ns % unit == 0 && v >= 1 && v <= INTERP_DIGITS_MAX) {
            *digits = (uint32_t)v;
            *exponent = e;
            return;
        }
    }
    unit = NS_PER_S / 1000;
    for (int e = -3; e >= -9; e--, unit /= 10)
        if ((period_ns + unit / 2) / unit <= INTERP_DIGITS_MAX && (period_ns + unit / 2) / unit >= 26) {
            *digits = (uint32_t)((period_ns + unit / 2) / unit);
            *exponent = e;
            return;
        }
    *digits = 1;
    *exponent = -3;
}

/* The value a step writes for a thread period of period_ns. */
uint32_t cia402_setup_value(const cia402_step_t *step, long period_ns)
{
    uint32_t digits;
    int exponent;
    switch (step->value_kind) {
    case CIA402_VALUE_CYCLE_US:
        return (uint32_t)((period_ns + 500) / 1000);
    case CIA402_VALUE_INTERP_DIGITS:
        interp_period(period_ns, &digits, &exponent);
        return digits;
    case CIA402_VALUE_INTERP_EXPONENT:
        interp_period(period_ns, &digits, &exponent);
        return (uint32_t)(uint8_t)(int8_t)exponent;
    default:
        return step->write.value;
    }
}
