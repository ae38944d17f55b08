/* stub_hal.h: failure injection of the stub HAL used by the frame unit test. */
#ifndef STUB_HAL_H
#define STUB_HAL_H

/* A pin name hal_pin_float_newf refuses with -EEXIST (NULL: none). */
extern const char *stub_fail_pin;

#endif
