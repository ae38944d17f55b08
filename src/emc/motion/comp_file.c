/* comp_file.c: parse a screw-compensation file (both COMP_FILE_TYPEs) with file:line errors. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "comp_file.h"

/* Non-zero for a line that ends the table: blank or a '#' comment. */
static int ends_table(const char *line)
{
    line += strspn(line, " \t\r\n");
    return *line == '\0' || *line == '#';
}

/* Exactly three numbers on the line into v; 0 or -1. */
static int three_numbers(const char *line, double v[3])
{
    char *end;
    const char *p = line;

    for (int i = 0; i < 3; i++) {
        v[i] = strtod(p, &end);
        if (end == p)
            return -1;
        p = end;
    }
    p += strspn(p, " \t\r\n");
    return *p == '\0' ? 0 : -1;
}

/* One row into rows[n] after the checks; 0 or a negative errno with why. */
static int add_row(const char *path, int line_no, int joint, int type, const double v[3],
                   comp_row_t *rows, int n, int max_rows, char *why, size_t why_size)
{
    if (n >= max_rows) {
        snprintf(why, why_size, "%s:%d: joint %d: too many compensation entries", path, line_no,
                 joint);
        return -E2BIG;
    }
    if (n > 0 && !(v[0] > rows[n - 1].nominal)) {
        snprintf(why, why_size, "%s:%d: joint %d: compensation values must increase", path,
                 line_no, joint);
        return -EINVAL;
    }
    rows[n].nominal = v[0];
    rows[n].forward = type == 0 ? v[0] - v[1] : v[1];
    rows[n].reverse = type == 0 ? v[0] - v[2] : v[2];
    return 0;
}

/* Read the table. */
int comp_file_read(const char *path, int joint, int type, comp_row_t *rows, int max_rows,
                   char *why, size_t why_size)
{
    char line[1024];
    double v[3];
    int n = 0, line_no = 0, rc = 0;
    FILE *f;

    if (type != 0 && type != 1) {
        snprintf(why, why_size, "joint %d: COMP_FILE_TYPE is %d, must be 0 or 1", joint, type);
        return -EINVAL;
    }
    f = fopen(path, "r");
    if (!f) {
        snprintf(why, why_size, "can't open compensation file %s", path);
        return -errno;
    }
    while (rc == 0 && fgets(line, sizeof line, f)) {
        line_no++;
        if (ends_table(line))
            break;
        if (three_numbers(line, v) < 0) {
            line[strcspn(line, "\r\n")] = '\0';
            snprintf(why, why_size, "%s:%d: joint %d: expected three numbers "
                     "(nominal, forward, reverse), got '%s'", path, line_no, joint, line);
            rc = -EINVAL;
        } else if ((rc = add_row(path, line_no, joint, type, v, rows, n, max_rows, why,
                                 why_size)) == 0) {
            n++;
        }
    }
    fclose(f);
    return rc < 0 ? rc : n;
}
