/* rtapi_instance.c: instance number from OPENEMC_INSTANCE and the names derived from it. */
#include <stdio.h>
#include <stdlib.h>
#include <pwd.h>
#include <unistd.h>
#include "rtapi_instance.h"

/* Parse $OPENEMC_INSTANCE once. 0..255 are used as they are; larger numbers
   (e.g. runners that use PIDs) fold into 1..255 as 1 + value % 255 so they
   still get an instance of their own; non-numbers mean 0 (with a note). */
int rtapi_instance(void)
{
    static int instance = -1;
    const char *text;
    char *end;
    long value;

    if (instance >= 0)
        return instance;
    text = getenv("OPENEMC_INSTANCE");
    value = 0;
    if (text && *text) {
        value = strtol(text, &end, 10);
        if (*end || value < 0) {
            fprintf(stderr, "rtapi: OPENEMC_INSTANCE='%s' is not a number >= 0, using 0\n",
                    text);
            value = 0;
        }
    }
    if (value > RTAPI_MAX_INSTANCE)
        value = 1 + value % RTAPI_MAX_INSTANCE;
    instance = (int)value;
    return instance;
}

/* The key this instance uses for a LinuxCNC base key. */
int rtapi_instance_key(int base_key)
{
    return (int)((unsigned)base_key ^ ((unsigned)rtapi_instance() << 24));
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
    if (len >= 0 && rtapi_instance() != 0 && (unsigned long)len < size)
        len += snprintf(buf + len, size - len, ".%d", rtapi_instance());
    if (len < 0 || (unsigned long)len >= size)
        return -1;
    return len;
}
