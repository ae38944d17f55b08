/* mb2hal_config.h: the parsed mb2hal configuration ([MB2HAL_INIT] and [TRANSACTION_NN]). */
#ifndef MB2HAL_CONFIG_H
#define MB2HAL_CONFIG_H

#define MB2HAL_MAX_TX 100
#define MB2HAL_NAME_LEN 48

enum mb_link_type { MB_LINK_TCP, MB_LINK_SERIAL };

/* Where and how a transaction talks; equal links share one connection. */
typedef struct {
    int type;            /* MB_LINK_TCP or MB_LINK_SERIAL */
    char tcp_ip[64];
    int tcp_port;
    char serial_port[256];
    int serial_baud, serial_bits, serial_stop, serial_delay_ms;
    char serial_parity;  /* 'N', 'E' or 'O' */
} mb_link_cfg_t;

/* One [TRANSACTION_NN] section. */
typedef struct {
    char section[32];
    mb_link_cfg_t link;
    int slave_id, first_element, nelements;
    int code;                      /* Modbus function code: 1..6, 15, 16 */
    int resp_timeout_ms, byte_timeout_ms;
    char tx_name[MB2HAL_NAME_LEN];
    char (*pin_names)[MB2HAL_NAME_LEN]; /* NULL: pins are numbered NN */
    double max_update_rate;        /* Hz, 0 = as often as possible */
    int debug;
    int version;                   /* [MB2HAL_INIT] VERSION: 10 or 11 (pin naming) */
} mb_tx_cfg_t;

/* The whole configuration. */
typedef struct {
    int init_debug;
    int version;                   /* 10 for 1.0, 11 for 1.1 */
    char module_name[MB2HAL_NAME_LEN];
    double slowdown;               /* seconds between transactions */
    int ntx;
    mb_tx_cfg_t tx[MB2HAL_MAX_TX];
} mb2hal_cfg_t;

/* Parses path into cfg; returns 0, or -1 after printing every error found. */
int mb2hal_config_load(mb2hal_cfg_t *cfg, const char *path);
/* Frees the pin name lists of cfg. */
void mb2hal_config_free(mb2hal_cfg_t *cfg);
/* "fnct_03_read_holding_registers" style name of a function code. */
const char *mb2hal_code_name(int code);
/* Non-zero when the function code reads from the device. */
int mb2hal_code_is_read(int code);
/* Non-zero when the function code works on bits (coils, discrete inputs). */
int mb2hal_code_is_bits(int code);

#endif
