/* rtapi_instance.h: instance isolation (OPENEMC_INSTANCE) for SysV keys and sockets. */
#ifndef RTAPI_INSTANCE_H
#define RTAPI_INSTANCE_H

#ifdef __cplusplus
extern "C" {
#endif

/* SysV base keys (instance 0 values, as LinuxCNC uses them). */
#define RTAPI_HAL_KEY 0x48414C32
#define RTAPI_RTAPI_KEY 0x90280A48
#define RTAPI_IDCOUNTER_KEY 0x48484C34

/* Instances 0..255 XOR their number into the key's top byte (LinuxCNC's keys for instance 0);
   256..RTAPI_MAX_INSTANCE XOR (number << 8 | RTAPI_WIDE_INSTANCE_TAG), whose non-zero low byte
   keeps them apart from the first range. Every instance number gives distinct keys. */
#define RTAPI_MAX_INSTANCE 16777215
#define RTAPI_NARROW_INSTANCE_MAX 255
#define RTAPI_WIDE_INSTANCE_TAG 0xA5u

/* This process's instance number: $OPENEMC_INSTANCE (decimal 0..16777215), default 0; -EINVAL
   (reported once on stderr) for anything else, and then nothing may attach. */
int rtapi_instance(void);
/* The SysV key this instance uses for base (see RTAPI_MAX_INSTANCE); -1 when the instance
   is invalid (check rtapi_instance() first). */
int rtapi_instance_key(int base_key);
/* Abstract socket name of this instance's master (without the leading NUL). */
int rtapi_instance_socket_name(char *buf, unsigned long size);

#ifdef __cplusplus
}
#endif

#endif
