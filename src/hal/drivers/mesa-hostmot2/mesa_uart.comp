component mesa_uart "Send and receive bytes through a Mesa HostMot2 UART (example of the hostmot2 serial API)";

description """
Each instance drives one HostMot2 UART named by its instance name. Load it with
*names=* set to the UART instances that hostmot2 printed when the board registered
(for example *hm2_7i92.0.uart.0*); loading by *count=* is refused, because the
instance name is the UART to use.

  loadrt mesa_uart names=hm2_5i23.0.uart.0,hm2_5i23.0.uart.7

At load the UART is set to 250000 bit/s with the transmit driver enabled
(TX mode 0x40). An unknown UART name is reported by hostmot2 and the instance then
sends and receives nothing.

*send* sends the low byte of the first *tx-bytes* (at most 16) *tx-data-NN* pins.
*receive* reads what the receive FIFO holds (at most 16 bytes) into *rx-data-NN* and
sets *rx-bytes* to the count (-1 when the UART could not be read).
""";

pin in ui32 tx_data_##[16] "Bytes to send (low 8 bits of each pin)";
pin out ui32 rx_data_##[16] "Bytes received";
pin in si32 tx_bytes "Number of bytes to send (0-16)";
pin out si32 rx_bytes "Number of bytes received by the last receive, -1 on error";

modparam dummy uart_chans """UART instances to use, by instance position, when they differ
from the instance names (up to 16, comma separated)""";

option extra_setup yes;
option period no;

variable char *name;

function send "Send tx-bytes bytes from tx-data";
function receive "Receive into rx-data and rx-bytes";

license "GPL";
author "OpenEMC";
see_also "hostmot2(9)";

include <hostmot2-serial.h>;
;;

#define MESA_UART_MAX_BYTES 16

static char *uart_chans[MESA_UART_MAX_BYTES];
RTAPI_MP_ARRAY_STRING(uart_chans, MESA_UART_MAX_BYTES, "UART instances, when they differ from names");

static int instance_index = 0;

FUNCTION(send)
{
    unsigned char data[MESA_UART_MAX_BYTES];
    int count = tx_bytes;
    if (count > MESA_UART_MAX_BYTES)
        count = MESA_UART_MAX_BYTES;
    if (count <= 0)
        return;
    for (int i = 0; i < count; i++)
        data[i] = (unsigned char)(tx_data(i) & 0xFF);
    hm2_uart_send(name, data, count);
}

FUNCTION(receive)
{
    unsigned char data[MESA_UART_MAX_BYTES];
    int count = hm2_uart_read(name, data);
    rx_bytes_set(count);
    for (int i = 0; i < count && i < MESA_UART_MAX_BYTES; i++)
        rx_data_set(i, data[i]);
}

EXTRA_SETUP()
{
    const char *uart = prefix;
    if (prefix[0] == 'm') {
        rtapi_print_msg(RTAPI_MSG_ERR, "mesa_uart can not be loaded using the 'count' parameter, "
                        "see man mesa_uart for details\n");
        return -1;
    }
    if (instance_index < MESA_UART_MAX_BYTES && uart_chans[instance_index] && uart_chans[instance_index][0])
        uart = uart_chans[instance_index];
    instance_index++;
    name = hal_malloc(strlen(uart) + 1);
    if (!name)
        return -ENOMEM;
    strcpy(name, uart);
    hm2_uart_setup(name, 250000, 0x40, -1);
    return 0;
}
