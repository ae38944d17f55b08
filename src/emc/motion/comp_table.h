/* comp_table.h: a joint's screw-compensation table (nominal, forward, reverse corrections), pure. */
#ifndef COMP_TABLE_H
#define COMP_TABLE_H

#define COMP_MAX_ENTRIES 256

/* Corrections by nominal position, nominal strictly increasing. */
typedef struct comp_table {
    int count;
    double nominal[COMP_MAX_ENTRIES];
    double forward[COMP_MAX_ENTRIES];   /* correction while moving + */
    double reverse[COMP_MAX_ENTRIES];   /* correction while moving - */
} comp_table_t;

/* Append a row; 0, -ENOSPC (table full) or -EINVAL (nominal not above the last one). */
int comp_table_add(comp_table_t *table, double nominal, double forward, double reverse);
/* Correction at pos for direction dir (> 0 forward, < 0 reverse): linear between rows,
 * the first/last row's value outside the table. */
double comp_table_lookup(const comp_table_t *table, double pos, int dir);

#endif
