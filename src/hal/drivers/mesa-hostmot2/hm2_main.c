/* hm2_main.c: the hostmot2 module: its parameters, load/unload and the list of boards. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "hm2.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Driver core for Mesa FPGA cards running the HostMot2 firmware");

int debug_idrom = 0;
RTAPI_MP_INT(debug_idrom, "print the IDROM header");
int debug_module_descriptors = 0;
RTAPI_MP_INT(debug_module_descriptors, "print each module descriptor");
int debug_pin_descriptors = 0;
RTAPI_MP_INT(debug_pin_descriptors, "print every pin descriptor");
int debug_modules = 0;
RTAPI_MP_INT(debug_modules, "print each module's state after registration");
int use_serial_numbers = 0;
RTAPI_MP_INT(use_serial_numbers, "name smart-serial remotes by serial number");
int sserial_baudrate = -1;
RTAPI_MP_INT(sserial_baudrate, "override the smart-serial baud rate");

static int comp_id;
static hm2_board_t *boards;

/* First registered board (the serial API searches them by instance name). */
hm2_board_t *hm2_first_board(void)
{
    return boards;
}

/* Add a board to the list (hm2_register). */
void hm2_board_list_add(hm2_board_t *hm2)
{
    hm2_board_t **p = &boards;
    while (*p)
        p = &(*p)->next;
    hm2->next = NULL;
    *p = hm2;
}

/* Remove a board from the list (hm2_unregister). */
void hm2_board_list_remove(hm2_board_t *hm2)
{
    for (hm2_board_t **p = &boards; *p; p = &(*p)->next) {
        if (*p == hm2) {
            *p = hm2->next;
            return;
        }
    }
}

/* Load: create the (empty) hostmot2 component. */
int rtapi_app_main(void)
{
    rtapi_print("hm2: loading Mesa HostMot2 driver version " HM2_VERSION "\n");
    comp_id = hal_init("hostmot2");
    if (comp_id < 0)
        return comp_id;
    hal_ready(comp_id);
    return 0;
}

/* Unload: unregister what the board drivers left, then remove the component. */
void rtapi_app_exit(void)
{
    while (boards)
        hm2_unregister(boards->llio);
    rtapi_print("hm2: unloading\n");
    hal_exit(comp_id);
}
