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

#define RTAPI_MAX_INSTANCE 255

/* This process's instance number: $OPENEMC_INSTANCE (decimal 0..255), default 0; -EINVAL
   (reported once on stderr) for anything else, and then nothing may attach. */
int rtapi_instance(void);
/* base ^ (instance << 24): the SysV key this instance uses for base; -1 when the instance
   is invalid (check rtapi_instance() first). */
int rtapi_instance_key(int base_key);
/* Abstract socket name of this instance's master (without the leading NUL). */
int rtapi_instance_socket_name(char *buf, unsigned long size);

#ifdef __cplusplus
}
#endif

#endif
