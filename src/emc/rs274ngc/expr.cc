// expr.cc: real values of a normalized line: numbers, parameters, [expressions] and functions (gcode.md §7).
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "interp.hh"

namespace {

constexpr double DEG = M_PI / 180.0;
constexpr double EQ_TOL = 1e-6;

// precedence of a binary operator (gcode.md §7 levels), 0 if not an operator
int precedence(const std::string &op)
{
    if (op == "**") return 5;
    if (op == "*" || op == "/" || op == "mod") return 4;
    if (op == "+" || op == "-") return 3;
    if (op == "eq" || op == "ne" || op == "gt" || op == "ge" || op == "lt" || op == "le") return 2;
    if (op == "and" || op == "or" || op == "xor") return 1;
    return 0;
}

// apply a one-argument function by name
double apply_unary(const std::string &name, double v)
{
    if (name == "abs") return std::fabs(v);
    if (name == "acos") {
        if (v < -1.0 || v > 1.0) throw InterpError("Argument to acos out of range");
        return std::acos(v) / DEG;
    }
    if (name == "asin") {
        if (v < -1.0 || v > 1.0) throw InterpError("Argument to asin out of range");
        return std::asin(v) / DEG;
    }
    if (name == "cos") return std::cos(v * DEG);
    if (name == "exp") return std::exp(v);
    if (name == "fix") return std::floor(v);
    if (name == "fup") return std::ceil(v);
    if (name == "ln") {
        if (v <= 0.0) throw InterpError("Zero or negative argument to ln");
        return std::log(v);
    }
    if (name == "round") return std::round(v);
    if (name == "sin") return std::sin(v * DEG);
    if (name == "sqrt") {
        if (v < 0.0) throw InterpError("Negative argument to sqrt");
        return std::sqrt(v);
    }
    if (name == "tan") return std::tan(v * DEG);
    throw InterpError("Unknown word starting with " + name.substr(0, 1));
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

// a value must stay finite
double checked(double v)
{
    if (!std::isfinite(v)) throw InterpError("Calculation resulted in an invalid number");
    return v;
}

} // namespace

// Read a number: optional sign, digits and at most one point, at least one digit.
double Interp::read_number(const std::string &t, size_t &pos)
{
    size_t start = pos;
    if (pos < t.size() && (t[pos] == '+' || t[pos] == '-')) pos++;
    while (pos < t.size() && (isdigit((unsigned char)t[pos]) || t[pos] == '.')) pos++;
    std::string text = t.substr(start, pos - start);
    const char *c = text.c_str();
    char *end = nullptr;
    bool digit = strpbrk(c, "0123456789") != nullptr;
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
    size_t start = pos;
    while (pos < t.size() && t[pos] >= 'a' && t[pos] <= 'z') pos++;
    std::string name = t.substr(start, pos - start);
    if (!is_unary(name))
        throw InterpError(std::string("Unknown word starting with ") + t[start]);
    if (pos >= t.size() || t[pos] != '[')
        throw InterpError("Left bracket missing after unary operation name");
    if (name == "exists") {
        pos++;
        if (t.compare(pos, 2, "#<") != 0)
            throw InterpError("EXISTS argument must be a named parameter");
        pos++;
        std::string pname = read_name(t, pos);
        if (pos >= t.size() || t[pos] != ']')
            throw InterpError("Expected ']' after EXISTS parameter");
        pos++;
        return named_exists(pname) ? 1.0 : 0.0;
    }
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

// Read a binary operator name at pos (symbols or lower-case words).
std::string Interp::read_operator(const std::string &t, size_t &pos)
{
    if (pos >= t.size()) throw InterpError("Unclosed expression");
    char c = t[pos];
    if (c == '*') {
        bool pow = pos + 1 < t.size() && t[pos + 1] == '*';
        pos += pow ? 2 : 1;
        return pow ? "**" : "*";
    }
    if (c == '/' || c == '+' || c == '-') {
        pos++;
        return std::string(1, c);
    }
    static const char *const words[] = {"mod", "and", "xor", "or", "eq", "ne", "gt",
                                        "ge", "lt", "le"};
    for (const char *w : words) {
        if (t.compare(pos, strlen(w), w) == 0) {
            pos += strlen(w);
            return w;
        }
    }
    if (c == ']') return "]";
    throw InterpError(std::string("Unknown operation name starting with ") +
                      (char)toupper((unsigned char)c));
}

// Apply a binary operator.
double Interp::eval_binary(double a, const std::string &op, double b)
{
    if (op == "**") {
        if (a < 0.0 && std::floor(b) != b)
            throw InterpError("Attempt to raise negative to non integer power");
        return checked(std::pow(a, b));
    }
    if (op == "*") return checked(a * b);
    if (op == "/") {
        if (b == 0.0) throw InterpError("Attempt to divide by zero");
        return checked(a / b);
    }
    if (op == "mod") {
        if (b == 0.0) throw InterpError("Attempt to divide by zero");
        double r = std::fmod(a, b);
        return r < 0.0 ? r + std::fabs(b) : r;
    }
    if (op == "+") return checked(a + b);
    if (op == "-") return checked(a - b);
    if (op == "eq") return std::fabs(a - b) < EQ_TOL ? 1 : 0;
    if (op == "ne") return std::fabs(a - b) >= EQ_TOL ? 1 : 0;
    if (op == "gt") return a > b ? 1 : 0;
    if (op == "ge") return (a > b || std::fabs(a - b) < EQ_TOL) ? 1 : 0;
    if (op == "lt") return a < b ? 1 : 0;
    if (op == "le") return (a < b || std::fabs(a - b) < EQ_TOL) ? 1 : 0;
    if (op == "and") return (a != 0.0 && b != 0.0) ? 1 : 0;
    if (op == "or") return (a != 0.0 || b != 0.0) ? 1 : 0;
    return ((a != 0.0) != (b != 0.0)) ? 1 : 0;
}

// Evaluate "[ ... ]" starting at the '[' with left-associative precedence levels.
double Interp::eval_expression(const std::string &t, size_t &pos)
{
    pos++;
    double values[16];
    std::string ops[16];
    int depth = 0;
    values[0] = read_real_value(t, pos);
    for (;;) {
        std::string op = read_operator(t, pos);
        int prec = op == "]" ? 0 : precedence(op);
        while (depth > 0 && precedence(ops[depth - 1]) >= prec) {
            values[depth - 1] = eval_binary(values[depth - 1], ops[depth - 1], values[depth]);
            depth--;
        }
        if (op == "]") {
            pos++;
            return values[0];
        }
        ops[depth] = op;
        depth++;
        values[depth] = read_real_value(t, pos);
    }
}
