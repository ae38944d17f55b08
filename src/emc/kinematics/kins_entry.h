/* kins_entry.h: exports, load, unload and switching shared by every kinematics frame. */
#ifndef KINS_ENTRY_H
#define KINS_ENTRY_H

#include "kinematics.h"

/* What a frame hands to kins_entry_start. */
typedef struct kins_entry {
    const char *name;               /* HAL component name, also kins_ops.name */
    int (*build)(int comp_id);      /* make the pins; 0 or negative errno */
    int highest_type;               /* 0: not switchable; else kinematicsSwitch takes 0..this */
    void (*switched)(int new_type); /* called with every accepted kinematicsSwitch (or NULL) */
    int announce_switch;            /* print "kinematicsSwitch(): type=N" first (LinuxCNC's templates) */
} kins_entry_t;

/* The exported table; kins_entry_start fills in the module name. */
extern kins_ops_t kins_ops;

/* Keep *entry, register the component, run build(comp_id), mark it ready; on failure remove it. */
int kins_entry_start(const kins_entry_t *entry);
/* 0 when new_type is 0..highest, else report kinematicsSwitch:BAD VALUE and return -1. */
int kins_switch_valid(int new_type, int highest);

#endif
