/* comp_file.h: reading a [JOINT_n]COMP_FILE into SET_JOINT_COMP rows (for task; user space). */
#ifndef COMP_FILE_H
#define COMP_FILE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define COMP_FILE_MAX_ROWS 256

/* One row as motion takes it: corrections moving forward and in reverse. */
typedef struct comp_row {
    double nominal;
    double forward;
    double reverse;
} comp_row_t;

/* Read path for joint (messages name it) with COMP_FILE_TYPE type (0: columns are actual
 * positions, stored as nominal - actual; 1: columns are the corrections).  Rows are
 * "nominal a b"; a blank or '#' line ends the table.  Returns the row count, or a negative
 * errno with "file:line: what" in why. */
int comp_file_read(const char *path, int joint, int type, comp_row_t *rows, int max_rows,
                   char *why, size_t why_size);

#ifdef __cplusplus
}
#endif

#endif
