/* cl_expr_compile.c: parses ClassicLadder expression text into reverse Polish operations. */
#include <stdio.h>
#include <string.h>
#include <ctype.h>
#include "cl_expr.h"
#include "cl_vars.h"

/* Parser state over one expression text. */
typedef struct {
    const cl_mem_t *m;
    const char *s;
    cl_expr_t *out;
    int depth, max_depth;
    int nest;                 /* recursion depth of parse_primary */
    char *err;
    int errlen;
    int failed;
} parser_t;

static void parse_or(parser_t *p);

/* Record the first error with the remaining text for context. */
static void fail(parser_t *p, const char *what)
{
    if (p->failed)
        return;
    p->failed = 1;
    if (*p->s)
        snprintf(p->err, p->errlen, "%s at '%.20s'", what, p->s);
    else
        snprintf(p->err, p->errlen, "%s at end of expression", what);
}

/* Skip blanks. */
static void blanks(parser_t *p)
{
    while (*p->s == ' ' || *p->s == '\t')
        p->s++;
}

/* Consume token tok if next; returns 1 when consumed. */
static int accept(parser_t *p, const char *tok)
{
    size_t n = strlen(tok);
    blanks(p);
    if (strncmp(p->s, tok, n) != 0)
        return 0;
    p->s += n;
    return 1;
}

/* Append an operation and track the stack depth it leaves. */
static void emit(parser_t *p, int op, int var_type, int32_t arg)
{
    if (p->failed)
        return;
    if (p->out->count >= CL_EXPR_MAX_OPS) {
        fail(p, "expression too long");
        return;
    }
    p->out->ops[p->out->count++] = (cl_op_t){ (int16_t)op, (int16_t)var_type, arg };
    if (op == OP_CONST || op == OP_VAR)
        p->depth++;
    else if (op != OP_NEG && op != OP_ABS && op != OP_NOT)
        p->depth--;
    if (p->depth > p->max_depth)
        p->max_depth = p->depth;
    if (p->max_depth > CL_EXPR_STACK)
        fail(p, "expression nested too deeply");
}

/* Parse a variable in @type/num@ or %name form; returns 1 with type/num when found. */
static int parse_var(parser_t *p, int *type, int *num)
{
    int used;
    blanks(p);
    if (*p->s == '@') {
        if (sscanf(p->s, "@%d/%d@%n", type, num, &used) != 2 || used <= 0) {
            fail(p, "bad variable");
            return 0;
        }
    } else if (*p->s == '%') {
        used = cl_var_parse(p->s, type, num);
        if (!used) {
            fail(p, "unknown variable");
            return 0;
        }
    } else {
        return 0;
    }
    if (!cl_var_desc(*type))
        fail(p, "unsupported variable type");
    else if (*num < 0 || *num >= cl_var_count(p->m, *type))
        fail(p, "variable number out of range");
    p->s += used;
    return !p->failed;
}

/* Function call NAME(a[,b]) for the known functions; returns 1 when one was parsed. */
static int parse_function(parser_t *p)
{
    static const struct { const char *name; int op, args; } fn[] = {
        { "ABS(", OP_ABS, 1 }, { "MINI(", OP_MIN, 2 }, { "MAXI(", OP_MAX, 2 },
        { "MOY(", OP_AVG, 2 }, { "POW(", OP_POW, 2 },
    };
    for (size_t i = 0; i < sizeof(fn) / sizeof(fn[0]); i++) {
        if (!accept(p, fn[i].name))
            continue;
        parse_or(p);
        if (fn[i].args == 2) {
            if (!accept(p, ","))
                fail(p, "expected ','");
            parse_or(p);
        }
        if (!accept(p, ")"))
            fail(p, "expected ')'");
        emit(p, fn[i].op, 0, 0);
        return 1;
    }
    return 0;
}

/* Primary: number, variable, function, (expr), unary minus or bitwise not. */
static void parse_primary(parser_t *p)
{
    int type, num;
    blanks(p);
    if (p->failed)
        return;
    if (++p->nest > CL_EXPR_MAX_OPS) {
        fail(p, "expression nested too deeply");
        return;
    }
    if (accept(p, "-")) {
        parse_primary(p);
        emit(p, OP_NEG, 0, 0);
    } else if (accept(p, "!")) {
        parse_primary(p);
        emit(p, OP_NOT, 0, 0);
    } else if (accept(p, "(")) {
        parse_or(p);
        if (!accept(p, ")"))
            fail(p, "expected ')'");
    } else if (isdigit((unsigned char)*p->s)) {
        long long v = 0;
        while (isdigit((unsigned char)*p->s) && v <= 2147483647LL)
            v = v * 10 + (*p->s++ - '0');
        if (v > 2147483647LL)
            fail(p, "number too large");
        emit(p, OP_CONST, 0, (int32_t)v);
    } else if (parse_var(p, &type, &num)) {
        emit(p, OP_VAR, type, num);
    } else if (!p->failed && !parse_function(p)) {
        fail(p, "expected a value");
    }
    p->nest--;
}

/* One precedence level: operand (op operand)* for the operators in tab. */
static void parse_level(parser_t *p, void (*operand)(parser_t *),
                        const char *const toks[], const int ops[], int n)
{
    operand(p);
    for (;;) {
        int i;
        for (i = 0; i < n && !accept(p, toks[i]); i++)
            ;
        if (i == n || p->failed)
            return;
        operand(p);
        emit(p, ops[i], 0, 0);
    }
}

/* Multiplicative level. */
static void parse_term(parser_t *p)
{
    static const char *const t[] = { "*", "/", "%" };
    static const int o[] = { OP_MUL, OP_DIV, OP_MOD };
    parse_level(p, parse_primary, t, o, 3);
}

/* Additive level. */
static void parse_sum(parser_t *p)
{
    static const char *const t[] = { "+", "-" };
    static const int o[] = { OP_ADD, OP_SUB };
    parse_level(p, parse_term, t, o, 2);
}

/* Comparison level (two-character operators tried first). */
static void parse_cmp(parser_t *p)
{
    static const char *const t[] = { "<>", "<=", ">=", "=", "<", ">" };
    static const int o[] = { OP_NE, OP_LE, OP_GE, OP_EQ, OP_LT, OP_GT };
    parse_level(p, parse_sum, t, o, 6);
}

/* Bitwise and / logical and of comparisons. */
static void parse_and(parser_t *p)
{
    static const char *const t[] = { "&" };
    static const int o[] = { OP_AND };
    parse_level(p, parse_cmp, t, o, 1);
}

/* Bitwise exclusive or. */
static void parse_xor(parser_t *p)
{
    static const char *const t[] = { "^" };
    static const int o[] = { OP_XOR };
    parse_level(p, parse_and, t, o, 1);
}

/* Bitwise / logical or: the lowest level. */
static void parse_or(parser_t *p)
{
    static const char *const t[] = { "|" };
    static const int o[] = { OP_OR };
    parse_level(p, parse_xor, t, o, 1);
}

/* Parse the optional "VAR :=" of an operate expression. */
static void parse_target(parser_t *p)
{
    const char *start = p->s;
    int type, num;

    p->out->store_type = -1;
    if (!strstr(p->s, ":="))
        return;
    if (!parse_var(p, &type, &num)) {
        fail(p, "expected a variable before ':='");
        return;
    }
    if (!cl_var_desc(type)->writable) {
        p->s = start;
        fail(p, "variable is read-only");
        return;
    }
    if (!accept(p, ":="))
        fail(p, "expected ':='");
    p->out->store_type = (int16_t)type;
    p->out->store_num = num;
}

/* Compile text into out; returns 0, or -1 with a message in err. */
int cl_expr_compile(const cl_mem_t *m, const char *text, cl_expr_t *out, char *err, int errlen)
{
    parser_t p = { m, text, out, 0, 0, 0, err, errlen, 0 };

    memset(out, 0, sizeof(*out));
    parse_target(&p);
    parse_or(&p);
    blanks(&p);
    if (!p.failed && *p.s)
        fail(&p, "unexpected text");
    return p.failed ? -1 : 0;
}
