/* cia402_sdo_line.h: the value of an "SDO = INDEX:SUB TYPE VALUE" configuration line. */
#ifndef CIA402_SDO_LINE_H
#define CIA402_SDO_LINE_H

#include <stddef.h>
#include "canopen_sdo.h"

/* Parse text into w; returns 0, or -1 with the reason in why. INDEX and SUB are hexadecimal
   (0x optional), TYPE is u8 u16 u32 i8 i16 i32, VALUE decimal or 0x hexadecimal. */
int cia402_sdo_line_parse(const char *text, co_sdo_write_t *w, char *why, size_t why_len);

/* Why the driver keeps object index for itself, or NULL when a configuration may write it.
   sync_objects: 0x1006 and 0x60C2 are written from the thread period. */
const char *cia402_sdo_reserved(uint16_t index, int sync_objects);

#endif
