/* parport_cfg.h: the hal_parport cfg= string as a list of ports (pure parsing, no I/O). */
#ifndef PARPORT_CFG_H
#define PARPORT_CFG_H

#define PP_MAX_PORTS 8
#define PP_MAX_LINUX_PORTS 16
#define PP_DEVICE_LEN 64
#define PP_ERROR_LEN 256

/* How the data port and the control lines are used (the type token). */
typedef enum {
    PP_MODE_OUT = 0, /* data port out: 12 outputs, 5 inputs */
    PP_MODE_EPP,     /* like out, the ECR switched to EPP */
    PP_MODE_IN,      /* data port in: 4 outputs, 13 inputs */
    PP_MODE_X        /* data out, control lines open-collector inputs: 8 outputs, 9 inputs */
} pp_mode_t;

/* What the address token named. */
typedef enum {
    PP_WHERE_INDEX = 0, /* 0..15: the Nth Linux parallel port */
    PP_WHERE_ADDRESS,   /* a base I/O address (>= 16) */
    PP_WHERE_DEVICE     /* a ppdev device: parportN or a /dev path */
} pp_where_t;

/* One configured port. */
typedef struct {
    pp_where_t where;
    unsigned long value;            /* the index or the base address */
    char device[PP_DEVICE_LEN];     /* the ppdev path for PP_WHERE_DEVICE */
    pp_mode_t mode;
} pp_port_cfg_t;

/* Parse cfg into ports[]; returns the port count (0 for an empty cfg) or -1 with a message in err. */
int pp_cfg_parse(const char *cfg, pp_port_cfg_t ports[PP_MAX_PORTS], char err[PP_ERROR_LEN]);

/* The mode's name as cfg spells it ("out", "epp", "in", "x"). */
const char *pp_mode_name(pp_mode_t mode);

#endif
