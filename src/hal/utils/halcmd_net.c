/* halcmd_net.c: the net command: validate every pin first, then create and link. */
#include <stdio.h>
#include <string.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_cmds.h"
#include "halcmd_hal.h"

/* Running state of one net validation. */
typedef struct {
    const char *sig_name;
    hal_sig_t *sig;
    int type;                 /* -1 until known */
    const char *writer;       /* OUT pin name, or NULL */
    const char *bidir;        /* an IO pin name, or NULL */
} hc_net_t;

/* Direction word used in writer conflict messages. */
static const char *hc_dir_word(int dir)
{
    return dir == HAL_IO ? "I/O" : "OUT";
}

/* Seed the writer state from the pins already on the signal. */
static void hc_net_seed(hc_net_t *n)
{
    if (!n->sig)
        return;
    n->type = n->sig->type;
    for (hal_pin_t *p = halpr_first_sig_pin(n->sig); p; p = halpr_next_sig_pin(p)) {
        if (p->dir == HAL_OUT && !n->writer)
            n->writer = p->name;
        if (p->dir == HAL_IO && !n->bidir)
            n->bidir = p->name;
    }
}

/* Check the writer rules for one new pin and record it. */
static int hc_net_writer(hc_net_t *n, hal_pin_t *pin, const char *name)
{
    const char *other = NULL;
    int other_dir = HAL_OUT;
    if (pin->dir == HAL_OUT) {
        other = n->writer ? n->writer : n->bidir;
        other_dir = n->writer ? HAL_OUT : HAL_IO;
    } else if (pin->dir == HAL_IO) {
        other = n->writer;
    }
    if (other) {
        hc_error("Signal '%s' can not add %s pin '%s', it already has %s pin '%s'",
                 n->sig_name, hc_dir_word(pin->dir), name, hc_dir_word(other_dir), other);
        return -1;
    }
    if (pin->dir == HAL_OUT)
        n->writer = pin->name;
    if (pin->dir == HAL_IO && !n->bidir)
        n->bidir = pin->name;
    return 0;
}

/* Validate one pin of the net (mutex held). */
static int hc_net_check_pin(hc_net_t *n, const char *name)
{
    hal_pin_t *pin = halpr_find_pin_by_name(name);
    if (!pin) {
        hc_error("Pin '%s' does not exist", name);
        return -1;
    }
    if (pin->signal && (!n->sig || pin->signal != SHMOFF(n->sig))) {
        hal_sig_t *other = SHMPTR(pin->signal);
        hc_error("Pin '%s' was already linked to signal '%s'", name, other->name);
        return -1;
    }
    if (pin->signal)
        return 0;
    if (n->type < 0) {
        n->type = pin->type;
    } else if ((int)pin->type != n->type) {
        hc_error("Signal '%s' of type '%s' cannot add pin '%s' of type '%s'",
                 n->sig_name, hc_type_name(n->type), name, hc_type_name(pin->type));
        return -1;
    }
    return hc_net_writer(n, pin, name);
}

/* Validate all pins and the signal name (mutex held). */
static int hc_net_validate(hc_net_t *n, int npins, char *pins[])
{
    n->sig = halpr_find_sig_by_name(n->sig_name);
    hc_net_seed(n);
    for (int i = 0; i < npins; i++)
        if (hc_net_check_pin(n, pins[i]) < 0)
            return -1;
    if (halpr_find_pin_by_name(n->sig_name)) {
        hc_error("Signal name '%s' must not be the same as a pin.  "
                 "Did you omit the signal name?", n->sig_name);
        return -1;
    }
    return n->sig ? 1 : 0;
}

/* net sig pin...: create the signal when missing and link every pin. */
int hc_cmd_net(int argc, char *argv[])
{
    hc_net_t n = {argv[0], NULL, -1, NULL, NULL};
    int exists;
    if (argc < 2) {
        hc_error("'net' requires at least one pin, none given");
        return -1;
    }
    halpr_mutex_get();
    exists = hc_net_validate(&n, argc - 1, argv + 1);
    halpr_mutex_give();
    if (exists < 0)
        return -1;
    if (!exists && hal_signal_new(argv[0], n.type) < 0) {
        hc_error("Failed to create signal '%s'", argv[0]);
        return -1;
    }
    for (int i = 1; i < argc; i++) {
        if (hal_link(argv[i], argv[0]) < 0) {
            hc_error("link failed");
            return -1;
        }
    }
    hc_info("Signal '%s' linked to %d pin(s)", argv[0], argc - 1);
    return 0;
}
