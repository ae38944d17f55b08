/* halcmd_cmd_sig.c: newsig, delsig, linkps, linksp, linkpp and unlinkp. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_cmds.h"

/* newsig name type: create a signal. */
int hc_cmd_newsig(int argc, char *argv[])
{
    int type = hc_parse_type(argv[1]);
    (void)argc;
    if (type < 0) {
        hc_error("Unknown signal type '%s'", argv[1]);
        return -1;
    }
    if (hal_signal_new(argv[0], type) < 0) {
        hc_error("newsig failed");
        return -1;
    }
    hc_info("Signal '%s' created", argv[0]);
    return 0;
}

/* Collected signal names for "delsig all". */
typedef struct {
    char **names;
    int count, cap;
} hc_namelist_t;

/* hal_list_s callback: remember one signal name. */
static int hc_collect_name(const char *name, hal_type_t type, int dir, void *ctx)
{
    hc_namelist_t *l = ctx;
    (void)type;
    (void)dir;
    if (l->count == l->cap) {
        int cap = l->cap ? 2 * l->cap : 64;
        char **n = realloc(l->names, cap * sizeof *n);
        if (!n)
            return 1;
        l->names = n;
        l->cap = cap;
    }
    l->names[l->count] = strdup(name);
    if (l->names[l->count])
        l->count++;
    return 0;
}

/* Delete every signal; fails when there is none or a deletion fails. */
static int hc_delsig_all(void)
{
    hc_namelist_t l = {0};
    int rc = 0;
    hal_list_s(hc_collect_name, &l);
    if (l.count == 0) {
        hc_error("no signals found to be deleted");
        rc = -1;
    }
    for (int i = 0; i < l.count; i++) {
        if (hal_signal_delete(l.names[i]) < 0)
            rc = -1;
        free(l.names[i]);
    }
    free(l.names);
    return rc;
}

/* delsig name|all: delete signals (library reports missing ones). */
int hc_cmd_delsig(int argc, char *argv[])
{
    (void)argc;
    if (strcmp(argv[0], "all") == 0)
        return hc_delsig_all();
    if (hal_signal_delete(argv[0]) < 0)
        return -1;
    hc_info("Signal '%s' deleted", argv[0]);
    return 0;
}

/* Link pin to sig, printing "link failed" on error. */
static int hc_link(const char *pin, const char *sig)
{
    if (hal_link(pin, sig) < 0) {
        hc_error("link failed");
        return -1;
    }
    hc_info("Pin '%s' linked to signal '%s'", pin, sig);
    return 0;
}

/* linkps pin sig */
int hc_cmd_linkps(int argc, char *argv[])
{
    (void)argc;
    return hc_link(argv[0], argv[1]);
}

/* linksp sig pin */
int hc_cmd_linksp(int argc, char *argv[])
{
    (void)argc;
    return hc_link(argv[1], argv[0]);
}

/* linkpp pin1 pin2 (legacy): a signal named like pin1 linking both pins. */
int hc_cmd_linkpp(int argc, char *argv[])
{
    hal_type_t type;
    hal_data_u value;
    int dir, rc;
    (void)argc;
    rc = hal_get_p(argv[0], &type, &dir, &value);
    if (rc < 0 || dir == HAL_RO || dir == HAL_RW) {
        hc_error("pin '%s' not found", argv[0]);
        return -1;
    }
    if (hal_signal_new(argv[0], type) < 0) {
        hc_error("Failed to create signal '%s'", argv[0]);
        return -1;
    }
    if (hc_link(argv[0], argv[0]) < 0 || hc_link(argv[1], argv[0]) < 0)
        return -1;
    return 0;
}

/* unlinkp pin */
int hc_cmd_unlinkp(int argc, char *argv[])
{
    (void)argc;
    if (hal_unlink(argv[0]) < 0) {
        hc_error("unlink failed");
        return -1;
    }
    hc_info("Pin '%s' unlinked", argv[0]);
    return 0;
}
