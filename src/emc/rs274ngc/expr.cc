// expr.cc: real values of a normalized line: numbers, parameters, [expressions] and functions (LinuxCNC's expression rules).
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "interp.hh"

namespace {

constexpr double DEG = M_PI / 180.0;
constexpr double EQ_TOL = 1e-6;

// a value must stay finite
double checked(double v)
{
    if (!std::isfinite(v)) throw InterpError("Calculation resulted in an invalid number");
    return v;
}

// the one-argument functions, by name; arguments and results in degrees
double fn_abs(double v) { return std::fabs(v); }
double fn_acos(double v)
{
    if (v < -1.0 || v > 1.0) throw InterpError("Argument to acos out of range");
    return std::acos(v) / DEG;
}
double fn_asin(double v)
{
    if (v < -1.0 || v > 1.0) throw InterpError("Argument to asin out of range");
    return std::asin(v) / DEG;
}
double fn_cos(double v) { return std::cos(v * DEG); }
double fn_exp(double v) { return std::exp(v); }
double fn_fix(double v) { return std::floor(v); }
double fn_fup(double v) { return std::ceil(v); }
double fn_ln(double v)
{
    if (v <= 0.0) throw InterpError("Zero or negative argument to ln");
    return std::log(v);
}
double fn_round(double v) { return std::round(v); }
double fn_sin(double v) { return std::sin(v * DEG); }
double fn_sqrt(double v)
{
    if (v < 0.0) throw InterpError("Negative argument to sqrt");
    return std::sqrt(v);
}
double fn_tan(double v) { return std::tan(v * DEG); }

const struct { const char *name; double (*fn)(double); } UNARY[] = {
    {"abs", fn_abs}, {"acos", fn_acos}, {"asin", fn_asin}, {"cos", fn_cos}, {"exp", fn_exp},
    {"fix", fn_fix}, {"fup", fn_fup},   {"ln", fn_ln},     {"round", fn_round},
    {"sin", fn_sin}, {"sqrt", fn_sqrt}, {"tan", fn_tan},
};

// apply a one-argument function by name
double apply_unary(const std::string &name, double v)
{
    for (const auto &u : UNARY)
        if (name == u.name) return u.fn(v);
    throw InterpError("Unknown word starting with " + name.substr(0, 1));
}

// the binary operators (LinuxCNC's expression rules): precedence level and evaluation, indexed by BinOp
double op_pow(double a, double b)
{
    if (a < 0.0 && std::floor(b) != b)
        throw InterpError("Attempt to raise negative to non integer power");
    return checked(std::pow(a, b));
}
double op_mul(double a, double b) { return checked(a * b); }
double op_div(double a, double b)
{
    if (b == 0.0) throw InterpError("Attempt to divide by zero");
    return checked(a / b);
}
double op_mod(double a, double b)
{
    if (b == 0.0) throw InterpError("Attempt to divide by zero");
    double r = std::fmod(a, b);
    return r < 0.0 ? r + std::fabs(b) : r;
}
double op_add(double a, double b) { return checked(a + b); }
double op_sub(double a, double b) { return checked(a - b); }
double op_eq(double a, double b) { return std::fabs(a - b) < EQ_TOL ? 1 : 0; }
double op_ne(double a, double b) { return std::fabs(a - b) >= EQ_TOL ? 1 : 0; }
double op_gt(double a, double b) { return a > b ? 1 : 0; }
double op_ge(double a, double b) { return (a > b || std::fabs(a - b) < EQ_TOL) ? 1 : 0; }
double op_lt(double a, double b) { return a < b ? 1 : 0; }
double op_le(double a, double b) { return (a < b || std::fabs(a - b) < EQ_TOL) ? 1 : 0; }
double op_and(double a, double b) { return (a != 0.0 && b != 0.0) ? 1 : 0; }
double op_or(double a, double b) { return (a != 0.0 || b != 0.0) ? 1 : 0; }
double op_xor(double a, double b) { return ((a != 0.0) != (b != 0.0)) ? 1 : 0; }

const struct { int level; double (*fn)(double, double); } BINARY[] = {
    {0, nullptr}, {5, op_pow}, {4, op_mul}, {4, op_div}, {4, op_mod}, {3, op_add}, {3, op_sub},
    {2, op_eq},   {2, op_ne},  {2, op_gt},  {2, op_ge},  {2, op_lt},  {2, op_le},  {1, op_and},
    {1, op_or},   {1, op_xor},
};

// precedence of a binary operator (LinuxCNC's levels); OP_END is 0
int precedence(BinOp op)
{
    return BINARY[op].level;
}

// true when name is a one-argument function
bool is_unary(const std::string &name)
{
    static const char *const names[] = {"abs", "acos", "asin", "atan", "cos", "exp", "fix",
                                        "fup", "ln", "round", "sin", "sqrt", "tan", "exists"};
    for (const char *n : names)
        if (name == n) return true;
    return false;
}

} // namespace

// Exactly rounded fast path for short decimals (mantissa < 2^53, <= 22 decimals); false otherwise.
static bool fast_decimal(const char *p, const char *end, double &v)
{
    bool neg = *p == '-';
    if (*p == '+' || *p == '-') p++;
    unsigned long long mant = 0;
    int digits = 0, decimals = 0, points = 0;
    for (; p < end; p++) {
        if (*p == '.') {
            if (++points > 1) return false;
            continue;
        }
        if (digits == 0 && *p == '0' && !points) continue;
        if (++digits > 15) return false;
        mant = mant * 10 + (unsigned)(*p - '0');
        if (points) decimals++;
    }
    if (points && digits == 0) return false;
    static const double pow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
                                   1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21,
                                   1e22};
    if (decimals > 22) return false;
    v = (double)mant / pow10[decimals];
    if (neg) v = -v;
    return true;
}

// Read a number: optional sign, digits and at most one point, at least one digit.
double Interp::read_number(const std::string &t, size_t &pos)
{
    INTERP_FRAME();
    size_t start = pos;
    if (pos < t.size() && (t[pos] == '+' || t[pos] == '-')) pos++;
    bool digit = false;
    int points = 0;
    for (; pos < t.size() && (isdigit((unsigned char)t[pos]) || t[pos] == '.'); pos++) {
        if (t[pos] == '.') points++;
        else digit = true;
    }
    double fast;
    if (digit && points <= 1 && fast_decimal(t.data() + start, t.data() + pos, fast)) return fast;
    std::string text = t.substr(start, pos - start);
    const char *c = text.c_str();
    char *end = nullptr;
    double v = digit ? strtod(c, &end) : 0.0;
    if (!digit || end == c)
        throw InterpError("bad number format (conversion failed) parsing '" + text + "'");
    if (*end != '\0')
        throw InterpError("bad number format (trailing characters) parsing '" + text + "'");
    return v;
}

// Read a real value: [expr], #param, unary function, signed value or number.
double Interp::read_real_value(const std::string &t, size_t &pos)
{
    INTERP_FRAME();
    if (pos >= t.size()) throw InterpError("No characters found in reading real value");
    char c = t[pos];
    char next = pos + 1 < t.size() ? t[pos + 1] : 0;
    if (c == '[') return eval_expression(t, pos);
    if (c == '#') return read_parameter(t, pos);
    if ((c == '+' || c == '-') && next && !isdigit((unsigned char)next) && next != '.') {
        pos++;
        double v = read_real_value(t, pos);
        return c == '-' ? -v : v;
    }
    if (c >= 'a' && c <= 'z') return read_unary(t, pos);
    return read_number(t, pos);
}

// Read a function call such as sin[...], atan[..]/[..] or exists[#<name>].
double Interp::read_unary(const std::string &t, size_t &pos)
{
    INTERP_FRAME();
    size_t start = pos;
    while (pos < t.size() && t[pos] >= 'a' && t[pos] <= 'z') pos++;
    std::string name = t.substr(start, pos - start);
    if (!is_unary(name))
        throw InterpError(std::string("Unknown word starting with ") + t[start]);
    if (pos >= t.size() || t[pos] != '[')
        throw InterpError("Left bracket missing after unary operation name");
    if (name == "exists") return read_exists(t, pos);
    double v = eval_expression(t, pos);
    if (name == "atan") {
        if (pos >= t.size() || t[pos] != '/')
            throw InterpError("Slash missing after first atan argument");
        pos++;
        if (pos >= t.size() || t[pos] != '[')
            throw InterpError("Left bracket missing after slash with atan");
        double x = eval_expression(t, pos);
        return std::atan2(v, x) / DEG;
    }
    return checked(apply_unary(name, v));
}

// EXISTS[#<name>], EXISTS[#n] or EXISTS[##n] (pos on '['): 1 when the named parameter is
// defined or the number is a parameter number, else 0.
double Interp::read_exists(const std::string &t, size_t &pos)
{
    INTERP_FRAME();
    pos++;
    if (pos >= t.size() || t[pos] != '#')
        throw InterpError("EXISTS argument must be a parameter: #<name>, #n or ##n");
    pos++;
    double found;
    if (pos < t.size() && t[pos] == '<') {
        found = named_exists(read_name(t, pos)) ? 1.0 : 0.0;
    } else {
        double n = read_real_value(t, pos);
        found = (n == std::nearbyint(n) && n >= 1 && n < PARAM_COUNT) ? 1.0 : 0.0;
    }
    if (pos >= t.size() || t[pos] != ']')
        throw InterpError("Right bracket missing after EXISTS parameter");
    pos++;
    return found;
}

// Read a binary operator at pos (symbols or lower-case words); ']' gives OP_END.
BinOp Interp::read_operator(const std::string &t, size_t &pos)
{
    INTERP_FRAME();
    if (pos >= t.size()) throw InterpError("Unclosed expression");
    char c = t[pos];
    switch (c) {
    case '*':
        if (pos + 1 < t.size() && t[pos + 1] == '*') { pos += 2; return OP_POW; }
        pos++;
        return OP_MUL;
    case '/': pos++; return OP_DIV;
    case '+': pos++; return OP_ADD;
    case '-': pos++; return OP_SUB;
    case ']': return OP_END;
    default: break;
    }
    static const struct { const char *name; BinOp op; } words[] = {
        {"mod", OP_MOD}, {"and", OP_AND}, {"xor", OP_XOR}, {"or", OP_OR}, {"eq", OP_EQ},
        {"ne", OP_NE}, {"gt", OP_GT}, {"ge", OP_GE}, {"lt", OP_LT}, {"le", OP_LE}};
    for (const auto &w : words) {
        size_t n = strlen(w.name);
        if (t.compare(pos, n, w.name) == 0) {
            pos += n;
            return w.op;
        }
    }
    throw InterpError(std::string("Unknown operation name starting with ") +
                      (char)toupper((unsigned char)c));
}

// Apply a binary operator.
double Interp::eval_binary(double a, BinOp op, double b)
{
    INTERP_FRAME();
    return BINARY[op].fn(a, b);
}

// Evaluate "[ ... ]" starting at the '[' with left-associative precedence levels.
double Interp::eval_expression(const std::string &t, size_t &pos)
{
    INTERP_FRAME();
    pos++;
    double values[16];
    BinOp ops[16];
    int depth = 0;
    values[0] = read_real_value(t, pos);
    for (;;) {
        BinOp op = read_operator(t, pos);
        int prec = precedence(op);
        while (depth > 0 && precedence(ops[depth - 1]) >= prec) {
            values[depth - 1] = eval_binary(values[depth - 1], ops[depth - 1], values[depth]);
            depth--;
        }
        if (op == OP_END) {
            pos++;
            return values[0];
        }
        ops[depth] = op;
        depth++;
        values[depth] = read_real_value(t, pos);
    }
}
