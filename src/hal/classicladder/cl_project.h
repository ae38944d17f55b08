/* cl_project.h: reading a ClassicLadder .clp project into a PLC data image. */
#ifndef CL_PROJECT_H
#define CL_PROJECT_H

#include "cl_data.h"

#define CL_ERR_LEN 512

/* One line of an embedded project file, with its line number in the .clp. */
typedef struct {
    char *text;
    int line;
} cl_line_t;

/* Loader state: target image, file name and the first error. */
typedef struct {
    cl_mem_t *m;
    const char *path;
    int have_sections;
    int *rung_lines;          /* per rung: line of its _FILE- marker */
    int *row_lines;           /* per rung and row: line of the grid row */
    int *section_lines;       /* per section: line of its sections.csv entry */
    char err[CL_ERR_LEN];
} cl_load_t;

int cl_project_load(cl_mem_t *m, const char *path, char *err, int errlen);
int cl_load_error(cl_load_t *ld, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
int cl_parse_rung(cl_load_t *ld, int rung, const cl_line_t *lines, int count);
int cl_parse_table(cl_load_t *ld, const char *name, const cl_line_t *lines, int count);
int cl_check_project(cl_load_t *ld);

#endif
