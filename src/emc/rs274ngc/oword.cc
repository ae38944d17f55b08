// oword.cc: O-word control flow: subroutines, if/elseif/else, while, do, repeat, break, continue.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <unistd.h>

#include "interp.hh"

namespace {

constexpr size_t MAX_CALL_LEVELS = 10;
constexpr long LOOP_LIMIT = 1000000;
// Passes of all loops together that one program (or MDI command) may run: a runaway guard for nested loops.
constexpr long TOTAL_LOOP_LIMIT = 10000000;

} // namespace

// Cheap look at a line: its O-word label and keyword without evaluating anything.
bool Interp::peek_oword(const std::string &line, std::string &name, OKind &kind)
{
    INTERP_FRAME();
    std::string t;
    for (char c : line) {
        if (c == '(' || c == ';') break;
        if (c != ' ' && c != '\t') t += (char)tolower((unsigned char)c);
    }
    size_t pos = 0;
    if (pos < t.size() && t[pos] == '/') pos++;
    if (pos < t.size() && t[pos] == 'n') {
        pos++;
        while (pos < t.size() && (isdigit((unsigned char)t[pos]) || t[pos] == '.')) pos++;
    }
    if (pos >= t.size() || t[pos] != 'o') return false;
    pos++;
    if (pos < t.size() && t[pos] == '<') {
        size_t end = t.find('>', pos);
        if (end == std::string::npos) return false;
        name = t.substr(pos + 1, end - pos - 1);
        pos = end + 1;
    } else {
        size_t start = pos;
        while (pos < t.size() && isdigit((unsigned char)t[pos])) pos++;
        if (pos == start) return false;
        name = std::to_string(atol(t.c_str() + start));
    }
    size_t start = pos;
    while (pos < t.size() && t[pos] >= 'a' && t[pos] <= 'z') pos++;
    Block b;
    std::string key = t.substr(start, pos - start);
    static const char *const keys[] = {"", "sub", "endsub", "call", "return", "if", "elseif",
                                       "else", "endif", "while", "endwhile", "do", "break",
                                       "continue", "repeat", "endrepeat"};
    kind = O_NONE;
    for (int i = 1; i < 16; i++)
        if (key == keys[i]) kind = (OKind)i;
    return kind != O_NONE;
}

// Start skipping lines until an O-word with this name and one of these kinds.
void Interp::skip_to(const std::string &name, std::initializer_list<OKind> kinds, bool past)
{
    INTERP_FRAME();
    skipping_ = true;
    skip_name_ = name;
    skip_kinds_.assign(kinds.begin(), kinds.end());
    skip_past_ = past;
    skip_start_ = s_.sequence_number;
}

// While skipping: does this O-word end the skip? (consumes it when skipping past)
bool Interp::skip_match(const std::string &name, OKind kind)
{
    INTERP_FRAME();
    if (kind == O_SUB && skip_sub_ && name != skip_name_)
        throw InterpError("Nested subroutine definition");
    if (name != skip_name_) return false;
    bool hit = false;
    for (OKind k : skip_kinds_) hit = hit || k == kind;
    if (!hit) return false;
    skipping_ = false;
    skip_sub_ = false;
    return !skip_past_;
}

// A flow problem: an error, or with OWORD_WARNONLY=1 a warning on stderr after which the line is ignored.
void Interp::flow_fail(const std::string &what, const Block &b)
{
    INTERP_FRAME();
    if (!s_.settings.oword_warnonly) throw InterpError(flow_error(what, b));
    fflush(stdout);
    fprintf(stderr, "%s\n", flow_error(what, b).c_str());
}

// Error text for flow problems: "<line>: what: '<source line>'".
std::string Interp::flow_error(const std::string &what, const Block &) const
{
    INTERP_FRAME();
    return std::to_string(s_.sequence_number) + ": " + what + ": '" + s_.line_text + "'";
}

// Dispatch an O-word line.
InterpStatus Interp::execute_oword(Block &b)
{
    INTERP_FRAME();
    switch (b.o_kind) {
    case O_SUB: o_sub(b); break;
    case O_ENDSUB: case O_RETURN: o_return(b); break;
    case O_CALL: o_call(b); break;
    case O_IF: o_if(b); break;
    case O_ELSEIF: case O_ELSE: o_else(b); break;
    case O_ENDIF: o_endif(b); break;
    case O_WHILE: o_while(b); break;
    case O_DO: o_do(b); break;
    case O_ENDWHILE: case O_ENDREPEAT: o_loop_end(b); break;
    case O_REPEAT: o_repeat(b); break;
    case O_BREAK: o_break(b, false); break;
    case O_CONTINUE: o_break(b, true); break;
    default: break;
    }
    return INTERP_OK;
}

// "sub" met in normal flow: remember the definition and skip its body.
void Interp::o_sub(Block &b)
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    if (f.sub_name == b.o_name && f.pos - 1 == f.sub_line) return;
    subs_[b.o_name] = SubDef{f.file, f.pos - 1};
    skip_to(b.o_name, {O_ENDSUB}, true);
    skip_sub_ = true;
}

// "return"/"endsub": leave the subroutine with an optional value.
void Interp::o_return(Block &b)
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    if (calls_.size() < 2 || f.fanuc || (b.o_kind == O_ENDSUB && f.sub_name != b.o_name))
        return flow_fail("not in a subroutine definition", b);
    if (f.autorestore && f.saved.valid) modal_restore(f.saved);
    pop_call();
    value_ = b.o_has_expr ? b.o_value : 0.0;
    value_returned_ = b.o_has_expr ? 1.0 : 0.0;
}

// "call": find the subroutine and enter it.
void Interp::o_call(Block &b)
{
    INTERP_FRAME();
    SubDef def;
    if (!find_sub(b.o_name, def)) {
        std::string label = isdigit((unsigned char)b.o_name[0]) ? b.o_name : "<" + b.o_name + ">";
        const auto &file = calls_.back().file;
        throw InterpError("EOF in file:" + (file ? file->path : std::string()) + " seeking o-word: o" +
                          label + " from line: " + std::to_string(s_.sequence_number));
    }
    push_call(def, b.o_name, b.o_args, false);
}

// Locate a subroutine: known, later in the current file, or in a file on the search path.
bool Interp::find_sub(const std::string &name, SubDef &def)
{
    INTERP_FRAME();
    auto it = subs_.find(name);
    if (it != subs_.end()) { def = it->second; return true; }
    CallFrame &f = calls_.back();
    std::string n;
    OKind k;
    for (size_t i = f.pos; f.file && i < f.file->lines.size(); i++) {
        if (peek_oword(f.file->lines[i], n, k) && k == O_SUB && n == name) {
            def = SubDef{f.file, i};
            subs_[name] = def;
            return true;
        }
    }
    std::vector<std::string> dirs;
    if (!s_.settings.program_prefix.empty()) dirs.push_back(s_.settings.program_prefix);
    for (const std::string &d : s_.settings.subroutine_path) dirs.push_back(d);
    if (!s_.settings.wizard_root.empty()) dirs.push_back(s_.settings.wizard_root);
    for (const std::string &d : dirs) {
        auto file = load_file(d + "/" + name + ".ngc");
        if (!file) continue;
        for (size_t i = 0; i < file->lines.size(); i++) {
            if (peek_oword(file->lines[i], n, k) && k == O_SUB && n == name) {
                def = SubDef{file, i};
                return true;
            }
        }
    }
    return false;
}

// Enter a subroutine: save #1-#30, set the arguments, new local scope.
void Interp::push_call(const SubDef &def, const std::string &name, const std::vector<double> &args,
                       bool fanuc)
{
    INTERP_FRAME();
    if (calls_.size() >= MAX_CALL_LEVELS) throw InterpError("Too many subroutine levels");
    CallFrame f;
    f.file = def.file;
    f.pos = def.line + 1;
    f.sub_line = def.line;
    f.sub_name = name;
    f.fanuc = fanuc;
    f.return_line = s_.sequence_number;
    for (int i = 1; i <= 30; i++) f.saved_args[i] = s_.params[i];
    if (!fanuc) {
        for (int i = 1; i <= 30; i++) s_.params[i] = i <= (int)args.size() ? args[i - 1] : 0.0;
        if (s_.settings.oword_narg) f.locals["n_args"] = (double)args.size();
    }
    calls_.push_back(std::move(f));
    s_.call_level = (int)calls_.size() - 1;
    value_ = 0;
    value_returned_ = 0;
}

// Leave a subroutine level: restore #1-#30 (not for Fanuc subs).
void Interp::pop_call()
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    if (!f.fanuc)
        for (int i = 1; i <= 30; i++) s_.params[i] = f.saved_args[i];
    if (f.remap) remap_level_--;
    if (f.remap_motion != -1) s_.motion_mode = f.remap_motion;
    calls_.pop_back();
    s_.call_level = (int)calls_.size() - 1;
}

// "if [c]": run the branch or skip to the next elseif/else/endif.
void Interp::o_if(Block &b)
{
    INTERP_FRAME();
    if (!b.o_has_expr) return flow_fail("missing condition", b);
    CallFrame &f = calls_.back();
    f.flow.push_back(FlowFrame{O_IF, b.o_name, f.pos - 1, 0, b.o_value != 0.0});
    if (b.o_value == 0.0) skip_to(b.o_name, {O_ELSEIF, O_ELSE, O_ENDIF}, false);
}

// "elseif"/"else": take the branch only if no earlier one ran.
void Interp::o_else(Block &b)
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    if (f.flow.empty() || f.flow.back().kind != O_IF || f.flow.back().name != b.o_name)
        return flow_fail("undefined O-word label", b);
    FlowFrame &ff = f.flow.back();
    if (ff.taken) {
        skip_to(b.o_name, {O_ENDIF}, false);
        return;
    }
    bool take = b.o_kind == O_ELSE || b.o_value != 0.0;
    if (b.o_kind == O_ELSEIF && !b.o_has_expr) return flow_fail("missing condition", b);
    ff.taken = take;
    if (!take) skip_to(b.o_name, {O_ELSEIF, O_ELSE, O_ENDIF}, false);
}

// "endif": close the conditional.
void Interp::o_endif(Block &b)
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    if (f.flow.empty() || f.flow.back().kind != O_IF || f.flow.back().name != b.o_name)
        return flow_fail("undefined O-word label", b);
    f.flow.pop_back();
}

// "while [c]": start/continue a while loop, or close a do loop.
void Interp::o_while(Block &b)
{
    INTERP_FRAME();
    if (!b.o_has_expr) return flow_fail("missing condition", b);
    CallFrame &f = calls_.back();
    bool top = !f.flow.empty() && f.flow.back().name == b.o_name;
    if (top && f.flow.back().kind == O_DO) {
        if (b.o_value != 0.0) {
            count_iteration(f.flow.back().iterations, b.o_name);
            f.pos = f.flow.back().start + 1;
        } else {
            f.flow.pop_back();
        }
        return;
    }
    if (b.o_value == 0.0) {
        if (top) f.flow.pop_back();
        skip_to(b.o_name, {O_ENDWHILE}, true);
        return;
    }
    if (!top) f.flow.push_back(FlowFrame{O_WHILE, b.o_name, f.pos - 1, 0, false});
}

// "do": open a do-while loop.
void Interp::o_do(Block &b)
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    bool top = !f.flow.empty() && f.flow.back().name == b.o_name;
    if (!top) f.flow.push_back(FlowFrame{O_DO, b.o_name, f.pos - 1, 0, false});
}

// "repeat [n]": run the body n times.
void Interp::o_repeat(Block &b)
{
    INTERP_FRAME();
    if (!b.o_has_expr) return flow_fail("missing repeat count", b);
    CallFrame &f = calls_.back();
    long n = (long)clamp_int(std::floor(b.o_value));
    if (n <= 0) {
        skip_to(b.o_name, {O_ENDREPEAT}, true);
        return;
    }
    f.flow.push_back(FlowFrame{O_REPEAT, b.o_name, f.pos - 1, n, false});
}

// "endwhile"/"endrepeat": jump back or finish the loop.
void Interp::o_loop_end(Block &b)
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    OKind want = b.o_kind == O_ENDWHILE ? O_WHILE : O_REPEAT;
    if (f.flow.empty() || f.flow.back().kind != want || f.flow.back().name != b.o_name)
        return flow_fail("undefined O-word label", b);
    FlowFrame &ff = f.flow.back();
    count_iteration(ff.iterations, b.o_name);
    if (want == O_WHILE) {
        f.pos = ff.start;
        return;
    }
    if (--ff.count > 0)
        f.pos = ff.start + 1;
    else
        f.flow.pop_back();
}

// "break" (leave the loop) or "continue" (next iteration).
void Interp::o_break(Block &b, bool cont)
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    while (!f.flow.empty() && f.flow.back().kind == O_IF) f.flow.pop_back();
    if (f.flow.empty() || f.flow.back().name != b.o_name)
        return flow_fail("undefined O-word label", b);
    OKind kind = f.flow.back().kind;
    OKind end = kind == O_WHILE ? O_ENDWHILE : kind == O_REPEAT ? O_ENDREPEAT : O_WHILE;
    if (!cont) f.flow.pop_back();
    skip_to(b.o_name, {end}, !cont);
}

// Guard against endless loops: a clear error instead of a hang.
void Interp::count_iteration(long &iterations, const std::string &name)
{
    INTERP_FRAME();
    if (++iterations > LOOP_LIMIT)
        throw InterpError(std::to_string(s_.sequence_number) + ": loop o" + name +
                          " ran more than " + std::to_string(LOOP_LIMIT) + " iterations");
    if (++total_iterations_ > TOTAL_LOOP_LIMIT)
        throw InterpError(std::to_string(s_.sequence_number) + ": loop o" + name +
                          " ran more than " + std::to_string(TOTAL_LOOP_LIMIT) +
                          " iterations of all loops in this program");
}
