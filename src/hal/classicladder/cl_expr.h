/* cl_expr.h: arithmetic expressions of compare and operate elements (compile and evaluate). */
#ifndef CL_EXPR_H
#define CL_EXPR_H

#include "cl_data.h"

/* Operations of the compiled (reverse Polish) form. */
enum {
    OP_CONST, OP_VAR, OP_NEG, OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_MOD, OP_AND, OP_OR,
    OP_XOR, OP_EQ, OP_NE, OP_LT, OP_GT, OP_LE, OP_GE, OP_ABS, OP_MIN, OP_MAX, OP_AVG,
    OP_POW, OP_NOT
};

#define CL_EXPR_STACK 32

int cl_expr_compile(const cl_mem_t *m, const char *text, cl_expr_t *out, char *err, int errlen);
int32_t cl_expr_value(const cl_mem_t *m, const cl_expr_t *e);
void cl_expr_operate(cl_mem_t *m, const cl_expr_t *e);

#endif
