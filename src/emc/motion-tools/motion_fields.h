/* motion_fields.h: command and status fields by name, for the test injector (and anything scripting motion). */
#ifndef MOTION_FIELDS_H
#define MOTION_FIELDS_H

#include <stddef.h>
#include "motion_cmd.h"
#include "motion_status.h"

typedef enum motion_field_type {
    MF_DOUBLE,
    MF_INT32,
    MF_UINT32
} motion_field_type_t;

/* Where a named value lives in a struct. */
typedef struct motion_field {
    const char *name;
    size_t offset;
    motion_field_type_t type;
} motion_field_t;

/* A command field ("pos.x", "vel", "joint", "tag.line_number", "tag.gcodes.5"); 0 or -1. */
int motion_command_field(const char *name, motion_field_t *out);
/* A status field ("enabled", "joint.0.homed", "carte_pos_cmd.x", "synch_do.3"); 0 or -1. */
int motion_status_field(const char *name, motion_field_t *out);
/* Store text (number, nan, inf, 0x hex) into the field of base; 0 or -1 when it does not parse. */
int motion_field_set(void *base, const motion_field_t *f, const char *text);
/* The field's value as a double. */
double motion_field_get(const void *base, const motion_field_t *f);

#endif
