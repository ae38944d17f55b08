/* rtapi_instance.c: instance number from OPENEMC_INSTANCE and the names derived from it. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <pwd.h>
#include <unistd.h>
#include "rtapi_instance.h"

/* Parse $OPENEMC_INSTANCE once: unset or empty is 0, a decimal 0..16777215 is itself. Anything else
   is refused (reported once), because two sessions must never share keys or sockets. */
int rtapi_instance(void)
{
    static int instance = -1;
    const char *text;
    long value = 0;

    if (instance != -1)
        return instance;
    text = getenv("OPENEMC_INSTANCE");
    if (text && *text) {
        size_t digits = strspn(text, "0123456789");
        value = digits > 0 && digits <= 8 && text[digits] == '\0' ? strtol(text, NULL, 10) : -1;
    }
    if (value < 0 || value > RTAPI_MAX_INSTANCE) {
        fprintf(stderr, "rtapi: OPENEMC_INSTANCE='%s' is not an instance number 0..%d; "
                "refusing to share another session's HAL and RTAPI\n", text, RTAPI_MAX_INSTANCE);
        instance = -EINVAL;
        return instance;
    }
    instance = (int)value;
    return instance;
}

/* The key this instance uses for a LinuxCNC base key (-1 for an invalid instance). */
int rtapi_instance_key(int base_key)
{
    unsigned instance;

    if (rtapi_instance() < 0)
        return -1;
    instance = (unsigned)rtapi_instance();
    if (instance <= RTAPI_NARROW_INSTANCE_MAX)
        return (int)((unsigned)base_key ^ (instance << 24));
    return (int)((unsigned)base_key ^ (instance << 8 | RTAPI_WIDE_INSTANCE_TAG));
}

/* $HOME, else the password entry's home, else /tmp. */
static const char *home_dir(void)
{
    const char *home = getenv("HOME");
    struct passwd *pw;

    if (home && *home)
        return home;
    pw = getpwuid(getuid());
    if (pw && pw->pw_dir)
        return pw->pw_dir;
    return "/tmp";
}

/* $RTAPI_FIFO_PATH, else $HOME/.rtapi_fifo, plus .<instance> for instance != 0. */
int rtapi_instance_socket_name(char *buf, unsigned long size)
{
    const char *path = getenv("RTAPI_FIFO_PATH");
    int len;

    if (path && *path)
        len = snprintf(buf, size, "%s", path);
    else
        len = snprintf(buf, size, "%s/.rtapi_fifo", home_dir());
    if (rtapi_instance() < 0)
        return -1;
    if (len >= 0 && rtapi_instance() != 0 && (unsigned long)len < size)
        len += snprintf(buf + len, size - len, ".%d", rtapi_instance());
    if (len < 0 || (unsigned long)len >= size)
        return -1;
    return len;
}
