/* app_modules.c: rtapi_app's module table: load (dlopen + parameters + init), unload, list. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <libgen.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "app.h"
#include "rtapi.h"
#include "rtapi_modparam.h"

#define HAL_LIB_NAME "hal_lib"

typedef struct app_module {
    char *name;
    void *handle;
    void (*exit_fn)(void);
    rtapi_modparam_strings_t strings;
    struct app_module *next;     /* older module */
} app_module_t;

static app_module_t *modules;    /* newest first */

/* $RTLIB_DIR, else the rtlib/ beside this program's bin/. */
static void rtlib_dir(char *buf, size_t size)
{
    const char *env = getenv("RTLIB_DIR");
    char exe[PATH_MAX];
    ssize_t n;

    if (env && *env) {
        snprintf(buf, size, "%s", env);
        return;
    }
    n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    exe[n > 0 ? n : 0] = '\0';
    snprintf(buf, size, "%s/../rtlib", dirname(exe));
}

/* Module called name, or NULL. */
static app_module_t *find_module(const char *name)
{
    for (app_module_t *m = modules; m; m = m->next)
        if (strcmp(m->name, name) == 0)
            return m;
    return NULL;
}

/* Parameter lookup for rtapi_modparam_apply: the module's rtapi_info_<name>. */
static const rtapi_param_info_t *lookup_param(void *ctx, const char *name)
{
    char symbol[256];

    if (snprintf(symbol, sizeof symbol, "rtapi_info_%s", name) >= (int)sizeof symbol)
        return NULL;
    return dlsym(ctx, symbol);
}

/* Reject duplicate names and names with '/' or "..". */
static int check_name(app_reply_t *reply, const char *name)
{
    if (find_module(name)) {
        app_error(reply, "%s: already exists\n", name);
        return -1;
    }
    if (!*name || strchr(name, '/') || strstr(name, "..")) {
        app_error(reply, "%s: Not allowed as module name. Slashes or with \"..\" "
                  "(even /a..b/) are not allowed.\n", name);
        return -1;
    }
    return 0;
}

/* dlopen RTLIB_DIR/<name>.so and find its entry points; 0 or -1. */
static int open_module(app_reply_t *reply, app_module_t *m, int (**main_fn)(void))
{
    char dir[PATH_MAX], path[PATH_MAX + 300];

    rtlib_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/%s.so", dir, m->name);
    m->handle = dlopen(path, RTLD_NOW | RTLD_GLOBAL);
    if (!m->handle) {
        app_error(reply, "%s: dlopen: %s\n", m->name, dlerror());
        return -1;
    }
    dlerror();
    *(void **)main_fn = dlsym(m->handle, "rtapi_app_main");
    if (!*main_fn) {
        const char *err = dlerror();
        app_error(reply, "%s: dlsym: %s\n", m->name, err ? err : "rtapi_app_main is NULL");
        return -1;
    }
    *(void **)&m->exit_fn = dlsym(m->handle, "rtapi_app_exit");
    if (!m->exit_fn) {
        app_error(reply, "%s: component is missing rtapi_app_exit\n", m->name);
        return -1;
    }
    return 0;
}

/* Apply every name=value argument in order; 0 or -1. */
static int apply_params(app_reply_t *reply, app_module_t *m, int argc, char **argv)
{
    char err[512];

    for (int i = 0; i < argc; i++) {
        if (rtapi_modparam_apply(argv[i], lookup_param, m->handle, &m->strings,
                                 err, sizeof err) < 0) {
            app_error(reply, "%s: %s\n", m->name, err);
            return -1;
        }
    }
    return 0;
}

/* Free a module record (after dlclose). */
static void free_module(app_module_t *m)
{
    if (m->handle)
        dlclose(m->handle);
    rtapi_modparam_free(&m->strings);
    free(m->name);
    free(m);
}

/* Load a module: name checks, dlopen, parameters, rtapi_app_main. */
int app_load(app_reply_t *reply, int argc, char **argv)
{
    int (*main_fn)(void) = NULL;
    app_module_t *m;
    int rc;

    if (argc < 1) {
        app_error(reply, "rtapi_app: load: missing module name\n");
        return -1;
    }
    if (check_name(reply, argv[0]) < 0)
        return -1;
    m = calloc(1, sizeof *m);
    if (!m || !(m->name = strdup(argv[0]))) {
        free(m);
        app_error(reply, "%s: out of memory\n", argv[0]);
        return -1;
    }
    rc = open_module(reply, m, &main_fn);
    if (rc == 0)
        rc = apply_params(reply, m, argc - 1, argv + 1);
    if (rc == 0) {
        rc = main_fn();
        if (rc < 0)
            app_error(reply, "%s: rtapi_app_main: %s (%d)\n", m->name, strerror(-rc), rc);
    }
    if (rc < 0) {
        free_module(m);
        return rc;
    }
    m->next = modules;
    modules = m;
    return 0;
}

/* Unlink m from the table, run its exit and free it. */
static void remove_module(app_module_t *m)
{
    app_module_t **pp = &modules;

    while (*pp != m)
        pp = &(*pp)->next;
    *pp = m->next;
    m->exit_fn();
    free_module(m);
}

/* Unload one module by name. */
int app_unload(app_reply_t *reply, const char *name)
{
    app_module_t *m = find_module(name);

    if (!m) {
        app_error(reply, "%s: not loaded\n", name);
        return -1;
    }
    if (strcmp(name, HAL_LIB_NAME) == 0) {
        app_error(reply, "%s: cannot be unloaded while rtapi_app runs (use \"realtime stop\")\n",
                  name);
        return -1;
    }
    remove_module(m);
    return 0;
}

/* Names in load order (oldest first). */
static void list_from(app_reply_t *reply, app_module_t *m)
{
    if (!m)
        return;
    list_from(reply, m->next);
    app_say(reply, "%s\n", m->name);
}

/* List loaded modules, oldest first. */
void app_list(app_reply_t *reply)
{
    list_from(reply, modules);
}

/* Unload all modules, hal_lib last. */
void app_unload_all(void)
{
    app_module_t *hal = find_module(HAL_LIB_NAME);

    for (;;) {
        app_module_t *m = modules;
        while (m && m == hal)
            m = m->next;
        if (!m)
            break;
        remove_module(m);
    }
    if (hal)
        remove_module(hal);
}

/* Make liblinuxcnchal's symbols global for modules. */
void app_preload_hal_library(void)
{
    Dl_info info;
    char lib[PATH_MAX], path[PATH_MAX + 32];

    if (!dladdr((void *)rtapi_init, &info) || !info.dli_fname)
        return;
    snprintf(lib, sizeof lib, "%s", info.dli_fname);
    snprintf(path, sizeof path, "%s/liblinuxcnchal.so", dirname(lib));
    if (access(path, R_OK) == 0 && !dlopen(path, RTLD_NOW | RTLD_GLOBAL))
        fprintf(stderr, "rtapi_app: %s\n", dlerror());
}
