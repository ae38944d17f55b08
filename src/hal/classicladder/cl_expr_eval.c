/* cl_expr_eval.c: runs a compiled expression on a bounded stack (realtime safe). */
#include "cl_expr.h"
#include "cl_vars.h"

/* Result of binary operator op on a and b; division by zero gives 0. */
static int32_t binary(int op, int32_t a, int32_t b)
{
    int64_t r;
    switch (op) {
    case OP_ADD: r = (int64_t)a + b; break;
    case OP_SUB: r = (int64_t)a - b; break;
    case OP_MUL: r = (int64_t)a * b; break;
    case OP_DIV: r = (b == 0 || (a == INT32_MIN && b == -1)) ? 0 : a / b; break;
    case OP_MOD: r = (b == 0 || b == -1) ? 0 : a % b; break;
    case OP_AND: r = a & b; break;
    case OP_OR: r = a | b; break;
    case OP_XOR: r = a ^ b; break;
    case OP_EQ: r = a == b; break;
    case OP_NE: r = a != b; break;
    case OP_LT: r = a < b; break;
    case OP_GT: r = a > b; break;
    case OP_LE: r = a <= b; break;
    case OP_GE: r = a >= b; break;
    case OP_MIN: r = a < b ? a : b; break;
    case OP_MAX: r = a > b ? a : b; break;
    case OP_AVG: r = ((int64_t)a + b) / 2; break;
    default: r = 0; break;
    }
    return (int32_t)(uint32_t)(uint64_t)r;
}

/* Integer power a^b (b < 0 gives 0 unless |a| is 1), wrapping like the other operators. */
static int32_t power(int32_t a, int32_t b)
{
    uint32_t r = 1, base = (uint32_t)a;
    if (b < 0)
        return a == 1 ? 1 : a == -1 ? ((b & 1) ? -1 : 1) : 0;
    for (uint32_t e = (uint32_t)b; e; e >>= 1) {  /* square and multiply: at most 31 rounds */
        if (e & 1)
            r *= base;
        base *= base;
    }
    return (int32_t)r;
}

/* Apply one operation to the stack; returns the new stack depth. */
static int step(const cl_mem_t *m, const cl_op_t *op, int32_t *st, int sp)
{
    switch (op->op) {
    case OP_CONST: st[sp++] = op->arg; break;
    case OP_VAR: st[sp++] = cl_var_read(m, op->var_type, op->arg); break;
    case OP_NEG: st[sp - 1] = (int32_t)(0u - (uint32_t)st[sp - 1]); break;
    case OP_NOT: st[sp - 1] = ~st[sp - 1]; break;
    case OP_ABS: if (st[sp - 1] < 0 && st[sp - 1] != INT32_MIN) st[sp - 1] = -st[sp - 1]; break;
    case OP_POW: sp--; st[sp - 1] = power(st[sp - 1], st[sp]); break;
    default: sp--; st[sp - 1] = binary(op->op, st[sp - 1], st[sp]); break;
    }
    return sp;
}

/* Value of expression e (the compiler guarantees the stack stays in bounds). */
int32_t cl_expr_value(const cl_mem_t *m, const cl_expr_t *e)
{
    int32_t st[CL_EXPR_STACK];
    int sp = 0;

    for (int i = 0; i < e->count && i < CL_EXPR_MAX_OPS; i++) {
        const cl_op_t *op = &e->ops[i];
        if ((op->op == OP_CONST || op->op == OP_VAR) ? sp >= CL_EXPR_STACK : sp < 1)
            return 0;
        if (op->op >= OP_ADD && op->op != OP_ABS && op->op != OP_NOT && sp < 2)
            return 0;
        sp = step(m, op, st, sp);
    }
    return sp > 0 ? st[sp - 1] : 0;
}

/* Evaluate an operate expression and store the result in its target variable. */
void cl_expr_operate(cl_mem_t *m, const cl_expr_t *e)
{
    if (e->store_type >= 0)
        cl_var_write(m, e->store_type, e->store_num, cl_expr_value(m, e));
}
