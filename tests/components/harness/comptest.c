/* comptest.c: load a component module into the fake HAL and drive it from a script on stdin. */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fakehal.h"

#define MAX_FUNCTS 32
#define MAX_WORDS 64

static void *module;
static long period_ns = 1000000;
static fake_item_t *cycle_list[MAX_FUNCTS];
static int n_cycle;
static char **param_strings;
static size_t n_param_strings;
extern long long fake_clock_ns;
int comptest_kins_dispatch(void *module, int argc, char **argv);
int comptest_home_dispatch(void *module, int argc, char **argv);
int comptest_follow_dispatch(int argc, char **argv);
void comptest_follow_apply(void);
void comptest_follow_clear(void);

/* Copy a string parameter value, remembering it so main can free it at exit. */
static char *keep_string(const char *value)
{
    char **grown = realloc(param_strings, (n_param_strings + 1) * sizeof(*grown));
    char *copy = strdup(value);
    if (!grown || !copy) {
        printf("out of memory\n");
        exit(1);
    }
    param_strings = grown;
    param_strings[n_param_strings++] = copy;
    return copy;
}

/* Free every string parameter value given to the module. */
static void free_param_strings(void)
{
    for (size_t i = 0; i < n_param_strings; i++)
        free(param_strings[i]);
    free(param_strings);
    param_strings = NULL;
    n_param_strings = 0;
}

/* Directory holding the realtime modules. */
static const char *rtlib_dir(void)
{
    const char *d = getenv("RTLIB_DIR");
    static char buf[4096];
    if (d && *d)
        return d;
    d = getenv("EMC2_HOME");
    snprintf(buf, sizeof(buf), "%s/rtlib", d && *d ? d : ".");
    return buf;
}

/* Apply one name=value module argument through its rtapi_info_ record. */
static int set_modparam(const char *arg)
{
    char name[128], sym[160];
    const char *eq = strchr(arg, '=');
    if (!eq || eq - arg >= (long)sizeof(name)) {
        printf("bad module argument '%s'\n", arg);
        return -1;
    }
    memcpy(name, arg, eq - arg);
    name[eq - arg] = '\0';
    snprintf(sym, sizeof(sym), "rtapi_info_%s", name);
    const rtapi_param_info_t *info = dlsym(module, sym);
    if (!info) {
        printf("Unknown parameter `%s'\n", arg);
        return -1;
    }
    char *copy = strdup(eq + 1), *save = NULL, *tok;
    if (!copy) {
        printf("out of memory\n");
        exit(1);
    }
    int i = 0, n = info->count ? info->count : 1;
    for (tok = strtok_r(copy, ",", &save); tok && i < n; tok = strtok_r(NULL, ",", &save), i++) {
        if (info->type == 'i')
            ((int *)info->address)[i] = (int)strtol(tok, NULL, 0);
        else if (info->type == 'l')
            ((long *)info->address)[i] = strtol(tok, NULL, 0);
        else
            ((char **)info->address)[i] = keep_string(info->count ? tok : eq + 1);
    }
    if (!*(eq + 1) && info->type == 's' && !info->count)
        *(char **)info->address = keep_string("");
    free(copy);
    return 0;
}

/* load MOD [args]: dlopen the module, apply args, call rtapi_app_main. */
static void cmd_load(int argc, char **argv)
{
    char path[4200];
    snprintf(path, sizeof(path), "%s/%s.so", rtlib_dir(), argv[1]);
    module = dlopen(path, RTLD_NOW | RTLD_GLOBAL);
    if (!module) {
        printf("dlopen: %s\n", dlerror());
        exit(1);
    }
    for (int i = 2; i < argc; i++)
        if (set_modparam(argv[i]) < 0)
            return;
    fake_new_load();
    int (*app_main)(void) = (int (*)(void))dlsym(module, "rtapi_app_main");
    int r = app_main ? app_main() : -1;
    printf("rtapi_app_main: %d%s%s\n", r, fake_ready() ? " ready" : "",
           fake_exited() ? " exited" : "");
}

/* Format the value of a pin/param into buf. */
static void format_value(fake_item_t *it, char *buf, size_t n)
{
    void *c = fake_cell(it);
    switch (it->type) {
    case HAL_BIT: snprintf(buf, n, "%d", *(hal_bit_t *)c ? 1 : 0); break;
    case HAL_FLOAT: snprintf(buf, n, "%.6f", *(hal_float_t *)c); break;
    case HAL_S32: snprintf(buf, n, "%d", (int)*(hal_s32_t *)c); break;
    case HAL_U32: snprintf(buf, n, "%u", (unsigned)*(hal_u32_t *)c); break;
    case HAL_S64: snprintf(buf, n, "%lld", (long long)*(hal_s64_t *)c); break;
    case HAL_U64: snprintf(buf, n, "%llu", (unsigned long long)*(hal_u64_t *)c); break;
    default: snprintf(buf, n, "%d", *(hal_port_t *)c); break;
    }
}

/* Find a pin/param or report it and return NULL. */
static fake_item_t *need(const char *name)
{
    fake_item_t *it = fake_find(name);
    if (!it || it->kind == FAKE_FUNCT) {
        printf("no pin or param '%s'\n", name);
        return NULL;
    }
    return it;
}

/* set NAME VALUE */
static void cmd_set(int argc, char **argv)
{
    fake_item_t *it = argc == 3 ? need(argv[1]) : NULL;
    if (!it)
        return;
    void *c = fake_cell(it);
    const char *v = argv[2];
    switch (it->type) {
    case HAL_BIT:
        *(hal_bit_t *)c = !strcmp(v, "1") || !strcasecmp(v, "true"); break;
    case HAL_FLOAT: *(hal_float_t *)c = strtod(v, NULL); break;
    case HAL_S32: *(hal_s32_t *)c = (int32_t)strtoll(v, NULL, 0); break;
    case HAL_U32: *(hal_u32_t *)c = (uint32_t)strtoull(v, NULL, 0); break;
    case HAL_S64: *(hal_s64_t *)c = strtoll(v, NULL, 0); break;
    case HAL_U64: *(hal_u64_t *)c = strtoull(v, NULL, 0); break;
    default: break;
    }
}

/* get NAME... : print the values on one line. */
static void print_values(int argc, char **argv, int first)
{
    char buf[64];
    for (int i = first; i < argc; i++) {
        fake_item_t *it = need(argv[i]);
        if (!it)
            return;
        format_value(it, buf, sizeof(buf));
        printf("%s%s", buf, i + 1 < argc ? " " : "\n");
    }
}

/* Run the cycle list once. */
static void one_cycle(void)
{
    for (int i = 0; i < n_cycle; i++)
        cycle_list[i]->funct(cycle_list[i]->arg, period_ns);
    fake_clock_ns += period_ns;
    comptest_follow_apply();
}

/* functs F...: set the list of functs one cycle calls. */
static void cmd_functs(int argc, char **argv)
{
    n_cycle = 0;
    for (int i = 1; i < argc && n_cycle < MAX_FUNCTS; i++) {
        fake_item_t *it = fake_find(argv[i]);
        if (!it || it->kind != FAKE_FUNCT) {
            printf("no funct '%s'\n", argv[i]);
            continue;
        }
        cycle_list[n_cycle++] = it;
    }
}

/* show: every pin, param and funct with type, direction and value. */
static void cmd_show(void)
{
    static const char *tn[] = {"?", "bit", "float", "s32", "u32", "port", "s64", "u64"};
    char buf[64];
    fake_sort();
    n_cycle = 0;
    for (int i = 0; i < fake_count(); i++) {
        fake_item_t *it = fake_item(i);
        if (it->kind == FAKE_FUNCT) {
            printf("funct %s\n", it->name);
            continue;
        }
        format_value(it, buf, sizeof(buf));
        const char *d = it->dir == HAL_IN ? "IN" : it->dir == HAL_OUT ? "OUT" :
                        it->dir == HAL_IO ? "IO" : it->dir == HAL_RO ? "RO" : "RW";
        printf("%s %s %s %s %s\n", it->kind == FAKE_PIN ? "pin" : "param",
               tn[it->type], d, it->name, buf);
    }
}

/* Dispatch one script line already split into words. */
static void dispatch(int argc, char **argv)
{
    const char *c = argv[0];
    if (!strcmp(c, "load") && argc >= 2) cmd_load(argc, argv);
    else if (!strcmp(c, "set")) cmd_set(argc, argv);
    else if (!strcmp(c, "get")) print_values(argc, argv, 1);
    else if (!strcmp(c, "period") && argc == 2) period_ns = strtol(argv[1], NULL, 0);
    else if (!strcmp(c, "functs")) cmd_functs(argc, argv);
    else if (!strcmp(c, "cycle")) {
        long n = argc > 1 ? strtol(argv[1], NULL, 0) : 1;
        while (n-- > 0) one_cycle();
    } else if (!strcmp(c, "trace") && argc >= 3) {
        long n = strtol(argv[1], NULL, 0);
        while (n-- > 0) { one_cycle(); print_values(argc, argv, 2); }
    } else if (!strcmp(c, "show")) cmd_show();
    else if (!strcmp(c, "echo")) {
        for (int i = 1; i < argc; i++) printf("%s%s", argv[i], i + 1 < argc ? " " : "");
        printf("\n");
    } else if (!strcmp(c, "unload")) {
        void (*app_exit)(void) = (void (*)(void))dlsym(module, "rtapi_app_exit");
        if (app_exit) app_exit();
        comptest_follow_clear();
        printf("rtapi_app_exit:%s\n", fake_exited() ? " exited" : "");
        dlclose(module);  /* the next load starts from fresh module variables */
        module = NULL;
    } else if (!comptest_kins_dispatch(module, argc, argv) && !comptest_home_dispatch(module, argc, argv)
               && !comptest_follow_dispatch(argc, argv))
        printf("unknown command '%s'\n", c);
}

/* Split line in place into words as halcmd does: blanks separate, double quotes group (and vanish),
 * '#' outside quotes starts a comment. Returns the number of words. */
static int split_words(char *line, char **argv)
{
    int argc = 0, quoted = 0;
    char *out = line, *in = line;
    while (*in && argc < MAX_WORDS) {
        while (*in == ' ' || *in == '\t' || *in == '\r' || *in == '\n')
            in++;
        if (!*in || *in == '#')
            break;
        argv[argc++] = out;
        for (; *in && (quoted || !strchr(" \t\r\n", *in)); in++) {
            if (*in == '"')
                quoted = !quoted;
            else
                *out++ = *in;
        }
        if (*in)
            in++;
        *out++ = '\0';
    }
    return argc;
}

/* Read script lines from stdin and run them. */
int main(void)
{
    char line[4096], *argv[MAX_WORDS];
    setvbuf(stdout, NULL, _IOLBF, 0);
    while (fgets(line, sizeof(line), stdin)) {
        int argc = split_words(line, argv);
        if (argc)
            dispatch(argc, argv);
    }
    free_param_strings();
    fake_free_memory();
    return 0;
}
