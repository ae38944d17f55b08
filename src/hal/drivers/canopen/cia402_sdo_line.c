/* cia402_sdo_line.c: parse "SDO = INDEX:SUB TYPE VALUE" and name the objects the driver owns. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cia402_sdo_line.h"

/* The data types an SDO line may name. */
static const struct {
    const char *name;
    uint8_t size;
    long long min, max;
} types[] = {
    { "u8", 1, 0, 0xFF }, { "u16", 2, 0, 0xFFFF }, { "u32", 4, 0, 0xFFFFFFFFLL },
    { "i8", 1, -128, 127 }, { "i16", 2, -32768, 32767 }, { "i32", 4, -2147483648LL, 2147483647LL },
};

/* Objects the driver writes itself, with the reason given to the user. */
static const struct {
    uint16_t first, last;
    int only_with_sync_objects;
    const char *why;
} reserved[] = {
    { 0x1006, 0x1006, 1, "the communication cycle period is written from the thread period "
                         "(SYNC_PERIOD_OBJECTS = 0 lets you write it)" },
    { 0x1017, 0x1017, 0, "the heartbeat time is set by HEARTBEAT_MS" },
    { 0x1400, 0x1BFF, 0, "the driver sets up the PDOs itself" },
    { 0x6040, 0x6040, 0, "the controlword is sent in RPDO1 every cycle" },
    { 0x6060, 0x6060, 0, "the driver selects cyclic synchronous position mode" },
    { 0x607A, 0x607A, 0, "the target position is sent in RPDO1 every cycle" },
    { 0x60C2, 0x60C2, 1, "the interpolation period is written from the thread period "
                         "(SYNC_PERIOD_OBJECTS = 0 lets you write it)" },
};

/* Parse hexadecimal digits (0x optional) up to max; 0 on success. */
static int parse_hex(const char *s, unsigned long max, unsigned long *out)
{
    char *end;
    if (!*s || *s == '-' || *s == '+')
        return -1;
    errno = 0;
    *out = strtoul(s, &end, 16);
    return (*end || errno || *out > max) ? -1 : 0;
}

/* Split "INDEX:SUB" into its two numbers; 0 on success. */
static int parse_address(char *word, co_sdo_write_t *w)
{
    unsigned long index, sub;
    char *colon = strchr(word, ':');
    if (!colon)
        return -1;
    *colon = '\0';
    if (parse_hex(word, 0xFFFF, &index) != 0 || parse_hex(colon + 1, 0xFF, &sub) != 0)
        return -1;
    w->index = (uint16_t)index;
    w->sub = (uint8_t)sub;
    return 0;
}

/* Parse a value: decimal or 0x hexadecimal, optionally negative; 0 on success. */
static int parse_value(const char *s, long long *out)
{
    char *end;
    int negative = *s == '-';
    const char *digits = negative ? s + 1 : s;
    int hex = digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X');
    if (!*digits || *digits == '-' || *digits == '+')
        return -1;
    errno = 0;
    *out = strtoll(digits, &end, hex ? 16 : 10);
    if (negative)
        *out = -*out;
    return (*end || errno) ? -1 : 0;
}

/* Parse text into w; returns 0, or -1 with the reason in why. */
int cia402_sdo_line_parse(const char *text, co_sdo_write_t *w, char *why, size_t why_len)
{
    char copy[128], address[64], type[16], value[64], extra[2];
    long long v;
    unsigned t = 0;
    snprintf(copy, sizeof(copy), "%s", text);
    if (sscanf(copy, "%63s %15s %63s %1s", address, type, value, extra) != 3) {
        snprintf(why, why_len, "SDO must be INDEX:SUB TYPE VALUE (e.g. 6081:00 u32 500000), not '%s'", text);
        return -1;
    }
    if (parse_address(address, w) != 0) {
        snprintf(why, why_len, "SDO object must be INDEX:SUB in hexadecimal (e.g. 6081:00), not '%s'", text);
        return -1;
    }
    while (t < sizeof(types) / sizeof(types[0]) && strcmp(types[t].name, type) != 0)
        t++;
    if (t == sizeof(types) / sizeof(types[0])) {
        snprintf(why, why_len, "SDO type must be u8, u16, u32, i8, i16 or i32, not '%s'", type);
        return -1;
    }
    if (parse_value(value, &v) != 0 || v < types[t].min || v > types[t].max) {
        snprintf(why, why_len, "SDO value '%s' is out of range for %s (%lld to %lld)", value, type, types[t].min,
                 types[t].max);
        return -1;
    }
    w->size = types[t].size;
    w->value = (uint32_t)v & (w->size == 4 ? 0xFFFFFFFFu : (1u << (8 * w->size)) - 1);
    return 0;
}

/* Why the driver keeps object index for itself, or NULL when a configuration may write it. */
const char *cia402_sdo_reserved(uint16_t index, int sync_objects)
{
    for (unsigned i = 0; i < sizeof(reserved) / sizeof(reserved[0]); i++)
        if (index >= reserved[i].first && index <= reserved[i].last &&
            (sync_objects || !reserved[i].only_with_sync_objects))
            return reserved[i].why;
    return NULL;
}
