/* classicladder.c: loads a .clp project into the running classicladder_rt module. */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "rtapi.h"
#include "cl_data.h"
#include "cl_project.h"

#define WAIT_SCAN_TRIES 5000     /* 1 ms apart: a scan never takes this long */

/* Attachment to the module's data segment. */
typedef struct {
    int module_id, shm_id;
    cl_header_t layout;     /* the header as checked when attaching */
    cl_mem_t mem;
} cl_link_t;

/* Print usage to out; returns the exit status (0 when asked for with --help). */
static int usage(FILE *out, int status)
{
    fprintf(out, "Usage: classicladder [--nogui] [--modmaster] PROJECT.clp\n"
                 "Loads PROJECT.clp into the realtime module classicladder_rt "
                 "(loadrt classicladder_rt first).\n"
                 "  --nogui      load and exit (the only mode of this build)\n"
                 "  --modmaster  accepted for compatibility; Modbus is not supported\n"
                 "  --help       this text\n");
    return status;
}

/* Map the header, read the total size, then map the whole segment. */
static int attach(cl_link_t *k)
{
    void *base;

    k->module_id = rtapi_init("classicladder");
    if (k->module_id < 0) {
        fprintf(stderr, "classicladder: cannot initialise rtapi (%d)\n", k->module_id);
        return -1;
    }
    k->shm_id = rtapi_shmem_new(CL_SHM_KEY, k->module_id, sizeof(cl_header_t));
    if (k->shm_id >= 0 && rtapi_shmem_getptr(k->shm_id, &base) == 0)
        memcpy(&k->layout, base, sizeof(k->layout));
    if (k->shm_id < 0 || k->layout.magic != CL_MAGIC || k->layout.version != CL_LAYOUT_VERSION) {
        fprintf(stderr, "classicladder: the realtime module classicladder_rt is not loaded "
                        "(use 'loadrt classicladder_rt' first)\n");
        return -1;
    }
    if (!cl_layout_valid(&k->layout)) {
        fprintf(stderr, "classicladder: the PLC data segment is damaged (its layout does not "
                        "match its sizes); reload classicladder_rt\n");
        return -1;
    }
    rtapi_shmem_delete(k->shm_id, k->module_id);
    k->shm_id = rtapi_shmem_new(CL_SHM_KEY, k->module_id, k->layout.total_size);
    if (k->shm_id < 0 || rtapi_shmem_getptr(k->shm_id, &base) < 0) {
        fprintf(stderr, "classicladder: cannot map the PLC data segment (%d)\n", k->shm_id);
        return -1;
    }
    if (memcmp(base, &k->layout, offsetof(cl_header_t, loading)) != 0) {
        fprintf(stderr, "classicladder: classicladder_rt was reloaded while attaching; try again\n");
        return -1;
    }
    cl_map(&k->mem, base);
    return 0;
}

/* Release the segment and the rtapi id. */
static void detach(cl_link_t *k)
{
    if (k->shm_id >= 0)
        rtapi_shmem_delete(k->shm_id, k->module_id);
    if (k->module_id >= 0)
        rtapi_exit(k->module_id);
}

/* Stop the scans, copy the new program in, reset the PLC state and run again. */
static int publish(cl_mem_t *shm, const cl_mem_t *image)
{
    cl_header_t *h = shm->hdr;
    int tries = 0;

    h->loading = 1;
    __sync_synchronize();
    while (h->in_scan && tries++ < WAIT_SCAN_TRIES)
        usleep(1000);
    if (h->in_scan) {
        h->loading = 0;
        fprintf(stderr, "classicladder: the realtime scan does not finish; project not loaded\n");
        return -1;
    }
    cl_copy_program(shm, image);
    cl_clear_state(shm);
    h->loaded = 1;
    __sync_synchronize();
    h->loading = 0;
    return 0;
}

/* Parse the project into a private copy of the segment, then publish it. */
static int load_project(cl_link_t *k, const char *path)
{
    char err[CL_ERR_LEN];
    cl_mem_t image;
    void *buf = calloc(1, k->layout.total_size);
    int rc = -1;

    if (!buf) {
        fprintf(stderr, "classicladder: out of memory\n");
        return -1;
    }
    memcpy(buf, &k->layout, sizeof(cl_header_t));
    cl_map(&image, buf);
    if (cl_project_load(&image, path, err, sizeof(err)) < 0)
        fprintf(stderr, "classicladder: %s\n", err);
    else
        rc = publish(&k->mem, &image);
    free(buf);
    return rc;
}

/* Modbus options of ClassicLadder HAL files, accepted and ignored. */
static int is_modbus_option(const char *arg)
{
    return strcmp(arg, "--modmaster") == 0 || strcmp(arg, "--modslave") == 0 ||
           strcmp(arg, "--modserver") == 0;
}

/* classicladder [--nogui] [--modmaster] FILE.clp */
int main(int argc, char **argv)
{
    cl_link_t link = { .module_id = -1, .shm_id = -1 };
    const char *path = NULL;
    int gui = 1, rc;

    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0)
            return usage(stdout, 0);
        if (strcmp(argv[i], "--nogui") == 0)
            gui = 0;
        else if (is_modbus_option(argv[i]))
            fprintf(stderr, "classicladder: Modbus is not supported; %s ignored\n", argv[i]);
        else if (argv[i][0] == '-' || path)
            return usage(stderr, 1);
        else
            path = argv[i];
    }
    if (!path)
        return usage(stderr, 1);
    if (gui)
        fprintf(stderr, "classicladder: no graphical editor in this build; loading %s as with "
                        "--nogui\n", path);
    rc = attach(&link) == 0 && load_project(&link, path) == 0 ? 0 : 1;
    detach(&link);
    return rc;
}
