/* hm2_eth_boards.c: Mesa Ethernet board names -> HAL name, connectors, pins per connector, FPGA, LEDs. */
#include <string.h>
#include "hm2_eth.h"

static const hm2_eth_board_desc_t boards[] = {
    {"7I80DB-16", 10, "7i80", 4, {"J2", "J3", "J4", "J5"}, 17, "XC6SLX16", 4, false},
    {"7I80DB-25", 10, "7i80", 4, {"J2", "J3", "J4", "J5"}, 17, "XC6SLX25", 4, false},
    {"7I80HD-16", 10, "7i80", 3, {"P1", "P2", "P3"}, 24, "XC6SLX16", 4, false},
    {"7I80HD-25", 10, "7i80", 3, {"P1", "P2", "P3"}, 24, "XC6SLX25", 4, false},
    {"7I80HDT", 7, "7i80", 3, {"P1", "P2", "P3"}, 24, "T20F256", 4, false},
    {"7I76E-16", 8, "7i76e", 3, {"P1", "P2", "P3"}, 17, "XC6SLX16", 4, false},
    {"7I76EU\0\0", 8, "7i76e", 3, {"P1", "P2", "P3"}, 17, "T20F256", 4, false},
    {"7I92", 4, "7i92", 2, {"P2", "P1"}, 17, "XC6SLX9", 4, false},
    {"7I93", 4, "7i93", 2, {"P2", "P1"}, 24, "6slx9tqg144", 4, false},
    {"7I94\0\0\0\0", 8, "7i94", 2, {"P2", "J1,J4"}, 21, "6slx9tqg144", 4, false},
    {"7I94T\0\0\0", 8, "7i94", 2, {"P2", "J1,J4"}, 21, "T20F256", 4, false},
    {"7I95\0\0\0\0", 8, "7i95", 2, {"P1", "TB1"}, 29, "6slx9tqg144", 4, false},
    {"7I95T\0\0\0", 8, "7i95", 2, {"P1", "TB1"}, 29, "T20F256", 4, false},
    {"7I96\0\0\0\0", 8, "7i96", 3, {"P1", "TB1", "TB2"}, 17, "6slx9tqg144", 4, false},
    {"7I96S\0\0\0", 8, "7i96s", 3, {"P1", "TB1", "TB2"}, 17, "T20F256", 4, false},
    {"7I97\0\0\0\0", 8, "7i97", 3, {"P1", "TB1", "TB2"}, 17, "6slx9tqg144", 4, false},
    {"7I97T\0\0\0", 8, "7i97", 3, {"P1", "TB1", "TB2"}, 17, "T20F256", 4, false},
    {"7I98", 4, "7i98", 3, {"P1", "P2", "P3"}, 17, "6slx9tqg144", 4, false},
    {"MC04", 4, "mc04", 2, {"P1", "P2"}, 30, "6slx9tqg144", 4, false},
    {"8CSS", 4, "8css", 2, {"P1", "P2"}, 30, "6slx9tqg144", 4, false},
};

/* First table entry whose name matches (compared bytes include NUL padding). */
const hm2_eth_board_desc_t *hm2_eth_find_board(const char name[LBP16_BOARD_NAME_LEN])
{
    for (size_t i = 0; i < sizeof(boards) / sizeof(boards[0]); i++)
        if (memcmp(name, boards[i].match, boards[i].match_len) == 0)
            return &boards[i];
    return NULL;
}
