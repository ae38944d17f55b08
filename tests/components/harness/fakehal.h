/* fakehal.h: in-process HAL/RTAPI stand-in used by comptest to drive component modules. */
#ifndef FAKEHAL_H
#define FAKEHAL_H
#include "hal.h"

typedef enum { FAKE_PIN, FAKE_PARAM, FAKE_FUNCT } fake_kind_t;

/* One registered pin, param or funct. */
typedef struct {
    char name[HAL_NAME_LEN + 1];
    fake_kind_t kind;
    int comp_id;                     /* owner; hal_exit removes its items */
    hal_type_t type;
    int dir;
    void **pin_ptr;                  /* pins: address of the component's pointer */
    void *data;                      /* params: storage; pins: private cell */
    void (*funct)(void *, long);     /* functs */
    void *arg;
} fake_item_t;

/* Find an item by exact name, or NULL. */
fake_item_t *fake_find(const char *name);
/* Number of registered items; item i (sorted by name once fake_sort ran). */
int fake_count(void);
fake_item_t *fake_item(int i);
/* Sort the registry by name (strcmp), as HAL listings are. */
void fake_sort(void);
/* Value cell of a pin or param. */
void *fake_cell(fake_item_t *it);
/* Ready flag of the last component, and whether hal_exit was called. */
int fake_ready(void);
int fake_exited(void);
/* A module is about to be loaded: clear both flags. */
void fake_new_load(void);
/* Free all hal_malloc memory (the fake HAL shuts down). */
void fake_free_memory(void);
#endif
