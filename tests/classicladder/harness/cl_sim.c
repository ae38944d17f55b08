/* cl_sim.c: drives the ClassicLadder loader and scan without HAL from a command script. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cl_data.h"
#include "cl_eval.h"
#include "cl_project.h"
#include "cl_vars.h"

/* Module-parameter names in CL_N_* order, with the module's defaults. */
static const char *const size_names[CL_N_SIZES] = {
    "numRungs", "numBits", "numWords", "numTimers", "numMonostables", "numCounters",
    "numPhysInputs", "numPhysOutputs", "numArithmExpr", "numSections", "numSymbols",
    "numS32in", "numS32out", "numFloatIn", "numFloatOut", "numTimersIec", "numErrorBits"
};
static int32_t sizes[CL_N_SIZES] = { 100, 20, 20, 10, 10, 10, 15, 15, 50, 10, 100, 10, 10, 10,
                                     10, 10, 10 };
static cl_mem_t mem;
static void *image;

/* "size NAME VALUE": change a size before the next load. */
static void cmd_size(const char *name, const char *value)
{
    for (int i = 0; i < CL_N_SIZES; i++)
        if (strcmp(name, size_names[i]) == 0) {
            sizes[i] = atoi(value);
            return;
        }
    printf("unknown size %s\n", name);
}

/* "load FILE": lay out a fresh image and load the project into it. */
static void cmd_load(const char *path)
{
    cl_header_t hdr;
    char err[CL_ERR_LEN];
    size_t total = cl_layout(&hdr, sizes);

    free(image);
    image = calloc(1, total);
    memcpy(image, &hdr, sizeof(hdr));
    cl_map(&mem, image);
    if (cl_project_load(&mem, path, err, sizeof(err)) < 0) {
        printf("error: %s\n", err);
        return;
    }
    cl_clear_state(&mem);
    printf("loaded %s\n", path);
}

/* "set VAR VALUE": inputs go to the input arrays, others through the variable writer. */
static void cmd_set(const char *var, const char *value)
{
    int type, num;

    if (!image || !cl_var_parse(var, &type, &num) || num >= cl_var_count(&mem, type)) {
        printf("bad variable %s\n", var);
        return;
    }
    if (type == VAR_PHYS_INPUT)
        mem.phys_in[num] = atoi(value) != 0;
    else if (type == VAR_PHYS_WORD_INPUT)
        mem.s32_in[num] = atoi(value);
    else if (type == VAR_PHYS_FLOAT_INPUT)
        mem.float_in[num] = atof(value);
    else
        cl_var_write(&mem, type, num, atoi(value));
}

/* "get VAR...": print each value (floats of %QF with two decimals). */
static void cmd_get(char **args, int n)
{
    for (int i = 0; i < n; i++) {
        int type, num;
        if (!image || !cl_var_parse(args[i], &type, &num) || num >= cl_var_count(&mem, type))
            printf(" %s=?", args[i]);
        else if (type == VAR_PHYS_FLOAT_OUTPUT)
            printf(" %s=%.2f", args[i], mem.float_out[num]);
        else
            printf(" %s=%d", args[i], (int)cl_var_read(&mem, type, num));
    }
    printf("\n");
}

/* Run one script line. */
static void run_line(char *line)
{
    char *args[32];
    int n = 0;

    for (char *t = strtok(line, " \t\n"); t && n < 32; t = strtok(NULL, " \t\n"))
        args[n++] = t;
    if (n == 0 || args[0][0] == '#')
        return;
    if (strcmp(args[0], "echo") == 0) {
        for (int i = 1; i < n; i++)
            printf("%s%s", args[i], i + 1 < n ? " " : "");
        printf("\n");
    } else if (strcmp(args[0], "size") == 0 && n == 3) {
        cmd_size(args[1], args[2]);
    } else if (strcmp(args[0], "load") == 0 && n == 2) {
        cmd_load(args[1]);
    } else if (strcmp(args[0], "set") == 0 && n == 3) {
        cmd_set(args[1], args[2]);
    } else if (strcmp(args[0], "get") == 0) {
        cmd_get(args + 1, n - 1);
    } else if (strcmp(args[0], "cycle") == 0 && image) {
        int count = n > 1 ? atoi(args[1]) : 1;
        long period = n > 2 ? atol(args[2]) : 1000000;
        for (int i = 0; i < count; i++)
            cl_scan(&mem, period);
    } else {
        printf("bad command %s\n", args[0]);
    }
}

/* Read the script from stdin. */
int main(void)
{
    char line[1024];

    while (fgets(line, sizeof(line), stdin))
        run_line(line);
    free(image);
    return 0;
}
