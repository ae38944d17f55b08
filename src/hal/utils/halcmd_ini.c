/* halcmd_ini.c: [SECTION]KEY substitution values (-i) from the INI library, and LIB: file names. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "emc/ini/inifile.h"
#include "halcmd.h"

/* The parsed -i file, opened on first use and kept for the whole run. */
static ini_file_t *hc_ini;
static const char *hc_ini_path;
static int hc_ini_failed;

/* Open (once) the INI file named by path; NULL when it cannot be parsed (reported once). */
static ini_file_t *hc_ini_get(const char *path)
{
    if (hc_ini && hc_ini_path && strcmp(hc_ini_path, path) == 0)
        return hc_ini;
    if (hc_ini_failed && hc_ini_path && strcmp(hc_ini_path, path) == 0)
        return NULL;
    ini_close(hc_ini);
    hc_ini_path = path;
    hc_ini = ini_open(path);
    hc_ini_failed = hc_ini == NULL;
    if (hc_ini_failed)
        hc_error("cannot use INI file '%s' for substitution (missing or invalid)", path);
    return hc_ini;
}

/* Return a malloc'd copy of the first KEY value in SECTION ("" = any section), or NULL. */
char *hc_ini_lookup(const char *file, const char *section, const char *key)
{
    ini_file_t *ini;
    const char *value;
    if (!file)
        return NULL;
    ini = hc_ini_get(file);
    if (!ini)
        return NULL;
    value = ini_find(ini, key, section, 1);
    return value ? strdup(value) : NULL;
}

/* The directory LIB: names refer to: $HALLIB_DIR, else <dir of halcmd>/../lib/hallib. */
static void hc_hallib_dir(char *buf, size_t size)
{
    const char *env = getenv("HALLIB_DIR");
    char exe[PATH_MAX];
    ssize_t n;
    char *slash;
    if (env && *env) {
        snprintf(buf, size, "%s", env);
        return;
    }
    n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    exe[n > 0 ? n : 0] = '\0';
    slash = strrchr(exe, '/');
    if (slash)
        *slash = '\0';
    if (snprintf(buf, size, "%s/../lib/hallib", n > 0 ? exe : ".") >= (int)size)
        snprintf(buf, size, "../lib/hallib");
    if (realpath(buf, exe))
        snprintf(buf, size, "%s", exe);
}

/* A file name as given, or for "LIB:name" the path of name in the HAL library directory. */
const char *hc_resolve_lib(const char *name, char *buf, size_t size)
{
    char dir[PATH_MAX];
    if (strncmp(name, "LIB:", 4) != 0)
        return name;
    hc_hallib_dir(dir, sizeof dir);
    snprintf(buf, size, "%s/%s", dir, name + 4);
    return buf;
}
