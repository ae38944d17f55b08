/* tpb_canon.c: a program read from the canonical calls `rs274 -g` prints, as bench moves in mm. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tpb.h"

/* Rapids run at the machine velocity: a feed far above it stands for "as fast as allowed". */
#define TPB_RAPID_FEED 1e9

/* Modal state the canonical calls set (lengths in mm). */
typedef struct canon_state {
    double unit;                /* mm per program unit */
    double g5x[3], g92[3], tool[3];
    double rot_deg;
    double feed;                /* mm/min */
    double tol, naive;
    int exact;
    int plane[3];               /* first, second, normal axis of ARC_FEED */
    double pos[3];
} canon_state_t;

/* Program coordinates (program units) to machine coordinates (mm). */
static void to_machine(const canon_state_t *st, const double *p, double *out)
{
    double x = p[0] * st->unit + st->g92[0], y = p[1] * st->unit + st->g92[1];
    double z = p[2] * st->unit + st->g92[2];
    if (st->rot_deg != 0.0) {
        double c = cos(st->rot_deg * M_PI / 180.0), s = sin(st->rot_deg * M_PI / 180.0);
        double xr = x * c - y * s;
        y = x * s + y * c;
        x = xr;
    }
    out[0] = x + st->g5x[0] + st->tool[0];
    out[1] = y + st->g5x[1] + st->tool[1];
    out[2] = z + st->g5x[2] + st->tool[2];
}

/* The numbers in a call's argument list. */
static int numbers(const char *args, double *v, int max)
{
    int n = 0;
    const char *p = args;
    while (*p && n < max) {
        char *end;
        double x = strtod(p, &end);
        if (end != p) {
            v[n++] = x;
            p = end;
        } else {
            p++;
        }
    }
    return n;
}

static tpb_move_t *push_move(tpb_program_t *p, const canon_state_t *st, int line)
{
    if (p->n == p->cap) {
        p->cap = p->cap ? 2 * p->cap : 1024;
        p->m = realloc(p->m, (size_t)p->cap * sizeof(*p->m));
    }
    tpb_move_t *m = &p->m[p->n++];
    memset(m, 0, sizeof(*m));
    m->feed = st->feed;
    m->tol = st->tol;
    m->naive = st->naive;
    m->exact = st->exact;
    m->line = line;
    return m;
}

static void straight(tpb_program_t *p, canon_state_t *st, const double *v, int rapid, int line)
{
    tpb_move_t *m = push_move(p, st, line);
    to_machine(st, v, m->end);
    if (rapid)
        m->feed = TPB_RAPID_FEED;
    memcpy(st->pos, m->end, sizeof(st->pos));
}

/* ARC_FEED(first_end, second_end, first_centre, second_centre, rotation, normal_end, ...). */
static void arc(tpb_program_t *p, canon_state_t *st, const double *v, int line)
{
    int a = st->plane[0], b = st->plane[1], c = st->plane[2];
    double end[3], cen[3], pe[3], pc[3];
    pe[a] = v[0];
    pe[b] = v[1];
    pe[c] = v[5];
    pc[a] = v[2];
    pc[b] = v[3];
    pc[c] = v[5];
    to_machine(st, pe, end);
    to_machine(st, pc, cen);
    int rot = (int)v[4];
    tpb_move_t *m = push_move(p, st, line);
    m->arc = 1;
    memcpy(m->end, end, sizeof(end));
    memcpy(m->center, cen, sizeof(cen));
    m->normal[c] = rot > 0 ? 1.0 : -1.0;
    m->turn = abs(rot) - 1;
    memcpy(st->pos, end, sizeof(end));
}

/* One canonical call: name and argument text. */
static void call(tpb_program_t *p, canon_state_t *st, const char *name, const char *args, int line)
{
    double v[16];
    int n = numbers(args, v, 16);
    if (!strcmp(name, "USE_LENGTH_UNITS"))
        st->unit = strstr(args, "INCHES") ? 25.4 : strstr(args, "CM") ? 10.0 : 1.0;
    else if (!strcmp(name, "SET_G5X_OFFSET") && n >= 4)
        for (int i = 0; i < 3; i++)
            st->g5x[i] = v[i + 1] * st->unit;
    else if (!strcmp(name, "SET_G92_OFFSET") && n >= 3)
        for (int i = 0; i < 3; i++)
            st->g92[i] = v[i] * st->unit;
    else if (!strcmp(name, "USE_TOOL_LENGTH_OFFSET") && n >= 3)
        for (int i = 0; i < 3; i++)
            st->tool[i] = v[i] * st->unit;
    else if (!strcmp(name, "SET_XY_ROTATION") && n >= 1)
        st->rot_deg = v[0];
    else if (!strcmp(name, "SET_FEED_RATE") && n >= 1)
        st->feed = v[0] * st->unit;
    else if (!strcmp(name, "SET_NAIVECAM_TOLERANCE") && n >= 1)
        st->naive = v[0] * st->unit;
    else if (!strcmp(name, "SET_MOTION_CONTROL_MODE")) {
        st->exact = strstr(args, "EXACT") != NULL;
        if (!st->exact)
            st->tol = n >= 1 ? v[0] * st->unit : 0.0;
    } else if (!strcmp(name, "SELECT_PLANE")) {
        static const int yz[3] = {1, 2, 0}, xz[3] = {2, 0, 1}, xy[3] = {0, 1, 2};
        memcpy(st->plane, strstr(args, "YZ") ? yz : strstr(args, "XZ") ? xz : xy, sizeof(st->plane));
    } else if (!strcmp(name, "STRAIGHT_FEED") && n >= 3)
        straight(p, st, v, 0, line);
    else if (!strcmp(name, "STRAIGHT_TRAVERSE") && n >= 3)
        straight(p, st, v, 1, line);
    else if (!strcmp(name, "ARC_FEED") && n >= 6)
        arc(p, st, v, line);
}

/* Read the canonical calls in file path; 0, or -1 when it cannot be read. */
int tpb_load_canon(tpb_program_t *p, const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    memset(p, 0, sizeof(*p));
    p->name = path;
    canon_state_t st;
    memset(&st, 0, sizeof(st));
    st.unit = 1.0;
    st.plane[0] = 0;
    st.plane[1] = 1;
    st.plane[2] = 2;
    char buf[4096];
    int line = 0;
    while (fgets(buf, sizeof(buf), f)) {
        line++;
        char *open = strchr(buf, '('), *close = strrchr(buf, ')');
        if (!open || !close || close < open)
            continue;
        *open = *close = '\0';
        char *name = open;
        while (name > buf && (name[-1] == '_' || (name[-1] >= 'A' && name[-1] <= 'Z') ||
                              (name[-1] >= '0' && name[-1] <= '9')))
            name--;
        call(p, &st, name, open + 1, line);
    }
    fclose(f);
    return p->n > 0 ? 0 : -1;
}
