/* halcmd_ini.c: [SECTION]KEY lookups for -i, through the INI library (parsed once per run). */
#include <stdlib.h>
#include <string.h>
#include "inifile.h"
#include "halcmd.h"

/* Return a malloc'd copy of the first KEY value in SECTION ("" = any section), or NULL. */
char *hc_ini_lookup(const char *file, const char *section, const char *key)
{
    static ini_file_t *ini;
    static char *loaded_path;
    const char *value;
    if (!file)
        return NULL;
    if (!loaded_path || strcmp(loaded_path, file) != 0) {
        ini_close(ini);
        free(loaded_path);
        ini = ini_open(file);
        loaded_path = strdup(file);
    }
    value = ini ? ini_find(ini, key, section, 1) : NULL;
    return value ? strdup(value) : NULL;
}
