/* config_dump.c: reads a cia402 configuration file and prints the drives and their set-up steps,
   or the errors with file and line. */
#include <stdio.h>
#include <stdlib.h>
#include "cia402_config.h"
#include "cia402_setup.h"

/* Print one error line. */
static void report(void *ctx, const char *text)
{
    (void)ctx;
    printf("error: %s\n", text);
}

/* Print one drive and the steps its set-up sends for a 1 ms period. */
static void show_drive(const cia402_drive_cfg_t *d, long period_ns)
{
    cia402_step_t steps[CIA402_SETUP_MAX];
    int n = cia402_setup_build(d, steps);
    printf("drive %d (line %d): node %d on %s scale %g heartbeat %d/%d ms pdo %d sdo %d enable %d ms "
           "velocity %d period-objects %d\n", d->number, d->section_line, d->node_id, d->interface,
           d->position_scale, d->heartbeat_ms, d->heartbeat_timeout_ms, d->pdo_timeout_ms, d->sdo_timeout_ms,
           d->enable_timeout_ms, d->velocity_feedback, d->sync_period_objects);
    for (int i = 0; i < n; i++) {
        const cia402_step_t *s = &steps[i];
        if (s->kind != CIA402_STEP_SDO)
            printf("  NMT %s (line %d)\n", s->kind == CIA402_STEP_START ? "start" : "pre-operational", s->line);
        else
            printf("  %04X:%02X size %d = 0x%X (%s, line %d)\n", s->write.index, s->write.sub, s->write.size,
                   cia402_setup_value(s, period_ns), s->what, s->line);
    }
}

int main(int argc, char **argv)
{
    static cia402_cfg_t cfg;
    long period_ns = argc > 2 ? atol(argv[2]) : 1000000;
    if (argc < 2) {
        fprintf(stderr, "usage: cia402_config_dump FILE [PERIOD_NS]\n");
        return 2;
    }
    if (cia402_cfg_load(&cfg, argv[1], report, NULL) != 0)
        return 1;
    printf("sync 0x%03X, %d drive(s)\n", cfg.sync_cob_id, cfg.drive_count);
    for (int i = 0; i < cfg.drive_count; i++)
        show_drive(&cfg.drives[i], period_ns);
    return 0;
}
