/* sim_remote.h: simulated Smart Serial remotes (7I76 field I/O): records, memory and state. */
#ifndef SIM_REMOTE_H
#define SIM_REMOTE_H

#include <stdbool.h>
#include <stdint.h>
#include "../hm2_sserial_proto.h"

#define SIM_REMOTE_MEM 0x1000
#define SIM_REMOTE_MAX_RECORDS 24
#define SIM_SSERIAL_CHANNELS 2
#define SIM_SSERIAL_BASE 0x5A00
#define SIM_SSERIAL_VERSION 43

/* One record a remote type presents (modes = bit mask of the software modes that carry it). */
typedef struct {
    const char *name, *unit;
    uint8_t data_type, dir, bits;
    float min, max;
    uint8_t modes;
    bool global;
    uint32_t initial;
} sim_record_def_t;

typedef struct {
    const char *name;                   /* 4 characters as the remote reports it, e.g. "7I76" */
    const char *hw_mode;
    const char *sw_modes[4];
    int num_sw_modes;
    const sim_record_def_t *records;
    int num_records;
    uint32_t watchdog_ms;
} sim_remote_type_t;

/* A remote on one channel of the card's Smart Serial port. */
typedef struct {
    const sim_remote_type_t *type;      /* NULL: nothing connected */
    bool unplugged;                     /* cable pulled: nothing answers */
    uint8_t status;                     /* status byte it reports (SSLBP_STATUS_*; 0 = ok) */
    int mode;
    bool setup, started;
    uint32_t unit;
    uint8_t mem[SIM_REMOTE_MEM];
    uint16_t ptoc[4], gtoc, rec_addr[SIM_REMOTE_MAX_RECORDS];
    uint32_t value[SIM_REMOTE_MAX_RECORDS];   /* current raw value of each record */
    long long last_transfer_ns;
    bool ever_transferred;
} sim_remote_t;

/* The card's port: registers and its remotes. */
typedef struct {
    uint32_t command, data;
    uint32_t pending;                   /* a do-it the firmware has not finished (reads back) */
    int busy_doits;                     /* fault injection: do-its left unfinished */
    uint32_t cs_out[SIM_SSERIAL_CHANNELS], cs_in[SIM_SSERIAL_CHANNELS];
    uint32_t iface_out[SIM_SSERIAL_CHANNELS][SSLBP_V0_INTERFACE_REGS];
    uint32_t iface_in[SIM_SSERIAL_CHANNELS][SSLBP_V0_INTERFACE_REGS];
    sim_remote_t remote[SIM_SSERIAL_CHANNELS];
    unsigned long doits;
} sim_sserial_t;

const sim_remote_type_t *sim_remote_type(const char *name);
void sim_remote_attach(sim_remote_t *r, const sim_remote_type_t *type, uint32_t unit);
bool sim_remote_outputs_enabled(const sim_remote_t *r, long long now_ns);
int sim_remote_find(const sim_remote_t *r, const char *name, int *bit);
void sim_remote_exchange(sim_remote_t *r, const uint32_t *out, uint32_t *in, long long now_ns);
uint32_t sim_remote_read32(const sim_remote_t *r, uint32_t addr);
void sim_remote_write32(sim_remote_t *r, uint32_t addr, uint32_t v);

#endif
