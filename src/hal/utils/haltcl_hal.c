/* haltcl_hal.c: Tcl package Hal: halcmd's commands run inside a Tcl interpreter (`hal cmd args...`). */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <tcl.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_hal.h"

#define HALTCL_VERSION "1.0"

/* haltcl_ini.cc: the entries of an INI file as a flat {section key value ...} list. */
int haltcl_ini_entries(Tcl_Interp *interp, const char *path);

/* Text a halcmd command wrote while Tcl captured its output and errors. */
typedef struct {
    char *out_text, *err_text;
    size_t out_len, err_len;
} haltcl_capture_t;

/* Leave HAL cleanly when the interpreter is killed, like halcmd does. */
static void haltcl_on_signal(int sig)
{
    (void)sig;
    hc_hal_detach();
    _exit(1);
}

/* Drop halcmd's HAL component when the interpreter exits. */
static void haltcl_exit_handler(ClientData data)
{
    (void)data;
    hc_hal_detach();
}

/* Send halcmd's output and error text to memory instead of stdout/stderr. */
static int haltcl_capture_begin(haltcl_capture_t *cap)
{
    memset(cap, 0, sizeof *cap);
    fflush(stdout);
    hc.out = open_memstream(&cap->out_text, &cap->out_len);
    hc.err = open_memstream(&cap->err_text, &cap->err_len);
    if (!hc.out || !hc.err) {
        if (hc.out)
            fclose(hc.out);
        if (hc.err)
            fclose(hc.err);
        hc.out = hc.err = NULL;
        return -1;
    }
    return 0;
}

/* Drop one trailing newline of captured text. */
static void haltcl_chomp(char *text, size_t *len)
{
    if (*len > 0 && text[*len - 1] == '\n')
        text[--*len] = '\0';
}

/* Restore the streams; output becomes the result, errors the error message (warnings go on). */
static int haltcl_capture_end(Tcl_Interp *interp, haltcl_capture_t *cap, int failed)
{
    fclose(hc.out);
    fclose(hc.err);
    hc.out = hc.err = NULL;
    haltcl_chomp(cap->out_text, &cap->out_len);
    haltcl_chomp(cap->err_text, &cap->err_len);
    if (failed) {
        if (cap->out_len)
            printf("%s\n", cap->out_text);
        Tcl_SetObjResult(interp, Tcl_NewStringObj(cap->err_len ? cap->err_text
                                                                : "HAL command failed", -1));
    } else {
        if (cap->err_len)
            fprintf(stderr, "%s\n", cap->err_text);
        Tcl_SetObjResult(interp, Tcl_NewStringObj(cap->out_text, -1));
    }
    fflush(stdout);
    free(cap->out_text);
    free(cap->err_text);
    return failed ? TCL_ERROR : TCL_OK;
}

/* Run one command given as words (argv mode: no comments, no substitution). */
static int haltcl_run_words(Tcl_Interp *interp, int objc, Tcl_Obj *const objv[])
{
    char *argv[HC_MAX_TOKENS + 1];
    haltcl_capture_t cap;
    int rc;
    if (objc > HC_MAX_TOKENS) {
        Tcl_SetObjResult(interp, Tcl_NewStringObj("too many arguments for a HAL command", -1));
        return TCL_ERROR;
    }
    for (int i = 0; i < objc; i++)
        argv[i] = Tcl_GetString(objv[i]);
    argv[objc] = NULL;
    if (haltcl_capture_begin(&cap) < 0) {
        Tcl_SetObjResult(interp, Tcl_NewStringObj("cannot capture HAL command output", -1));
        return TCL_ERROR;
    }
    hc.argv_mode = 1;
    hc.bare_messages = 1;
    rc = hc_run_tokens(objc, argv);
    hc.bare_messages = 0;
    return haltcl_capture_end(interp, &cap, rc < 0);
}

/* `hal --line FILE LINE TEXT`: one HAL file line with comments and [SEC]KEY/$ENV substitution. */
static int haltcl_run_line(Tcl_Interp *interp, Tcl_Obj *const objv[])
{
    char buf[2 * HC_LINE_MAX];
    haltcl_capture_t cap;
    int line, rc;
    if (Tcl_GetIntFromObj(interp, objv[1], &line) != TCL_OK)
        return TCL_ERROR;
    snprintf(buf, sizeof buf, "%s", Tcl_GetString(objv[2]));
    if (haltcl_capture_begin(&cap) < 0)
        return TCL_ERROR;
    hc.file = Tcl_GetString(objv[0]);
    hc.line = line;
    hc.argv_mode = 0;
    rc = hc_process_line(buf);
    hc.file = NULL;
    return haltcl_capture_end(interp, &cap, rc < 0);
}

/* `hal --substitute TEXT`: TEXT without its comment, with [SEC]KEY and $ENV replaced. */
static int haltcl_substitute(Tcl_Interp *interp, Tcl_Obj *text)
{
    char buf[2 * HC_LINE_MAX], out[HC_LINE_MAX + 16];
    haltcl_capture_t cap;
    int rc;
    snprintf(buf, sizeof buf, "%s", Tcl_GetString(text));
    if (haltcl_capture_begin(&cap) < 0)
        return TCL_ERROR;
    hc.bare_messages = 1;
    rc = hc_strip_comment(buf);
    if (rc == 0)
        rc = hc_substitute(buf, out, sizeof out);
    hc.bare_messages = 0;
    if (rc == 0)
        fputs(out, hc.out);
    return haltcl_capture_end(interp, &cap, rc < 0);
}

/* `hal --commands`: the names of every HAL command. */
static int haltcl_command_names(Tcl_Interp *interp)
{
    Tcl_Obj *list = Tcl_NewListObj(0, NULL);
    const hc_command_t *k;
    for (int i = 0; (k = hc_command_at(i)) != NULL; i++)
        Tcl_ListObjAppendElement(interp, list, Tcl_NewStringObj(k->name, -1));
    Tcl_SetObjResult(interp, list);
    return TCL_OK;
}

/* `hal --ini FILE`: the INI file used for [SECTION]KEY substitution. */
static int haltcl_set_ini(Tcl_Obj *file)
{
    static char *ini_path;
    free(ini_path);
    ini_path = strdup(Tcl_GetString(file));
    hc.ini_file = ini_path;
    return TCL_OK;
}

/* The hal command: `hal cmd args...` or one of the --options above. */
static int haltcl_hal_cmd(ClientData data, Tcl_Interp *interp, int objc, Tcl_Obj *const objv[])
{
    const char *first;
    (void)data;
    if (objc < 2) {
        Tcl_WrongNumArgs(interp, 1, objv, "command ?args?");
        return TCL_ERROR;
    }
    first = Tcl_GetString(objv[1]);
    if (strcmp(first, "--commands") == 0 && objc == 2)
        return haltcl_command_names(interp);
    if (strcmp(first, "--ini") == 0 && objc == 3)
        return haltcl_set_ini(objv[2]);
    if (strcmp(first, "--ini-entries") == 0 && objc == 3)
        return haltcl_ini_entries(interp, Tcl_GetString(objv[2]));
    if (strcmp(first, "--substitute") == 0 && objc == 3)
        return haltcl_substitute(interp, objv[2]);
    if (strcmp(first, "--line") == 0 && objc == 5)
        return haltcl_run_line(interp, objv + 2);
    if (strncmp(first, "--", 2) == 0) {
        Tcl_SetObjResult(interp, Tcl_ObjPrintf("hal: unknown option or wrong arguments: %s"
                                               " (--commands, --ini FILE, --ini-entries FILE,"
                                               " --substitute TEXT, --line FILE LINE TEXT)", first));
        return TCL_ERROR;
    }
    return haltcl_run_words(interp, objc - 1, objv + 1);
}

/* Package entry point: attach to HAL as halcmd<pid> and create the hal command. */
int Hal_Init(Tcl_Interp *interp)
{
    if (Tcl_InitStubs(interp, "8.6", 0) == NULL)
        return TCL_ERROR;
    if (hc.comp_id <= 0 && hc_hal_attach() < 0) {
        Tcl_SetObjResult(interp, Tcl_NewStringObj("hal: cannot attach to HAL", -1));
        return TCL_ERROR;
    }
    signal(SIGINT, haltcl_on_signal);
    signal(SIGTERM, haltcl_on_signal);
    Tcl_CreateExitHandler(haltcl_exit_handler, NULL);
    Tcl_CreateObjCommand(interp, "hal", haltcl_hal_cmd, NULL, NULL);
    return Tcl_PkgProvide(interp, "Hal", HALTCL_VERSION);
}
