// oword.cc: O-word control flow: subroutines, if/elseif/else, while, do, repeat, break, continue.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <unistd.h>

#include "interp.hh"

namespace {

constexpr size_t MAX_CALL_LEVELS = 10;

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
    size_t pos = skip_line_number(t);
    if (pos >= t.size() || t[pos] != 'o' || !peek_label(t, ++pos, name)) return false;
    size_t start = pos;
    while (pos < t.size() && t[pos] >= 'a' && t[pos] <= 'z') pos++;
    std::string key = t.substr(start, pos - start);
    static const char *const keys[] = {"", "sub", "endsub", "call", "return", "if", "elseif",
                                       "else", "endif", "while", "endwhile", "do", "break",
                                       "continue", "repeat", "endrepeat"};
    kind = O_NONE;
    for (int i = 1; i < 16; i++)
        if (key == keys[i]) kind = (OKind)i;
    return kind != O_NONE;
}

// Position after the block-delete slash and line number of a normalized line.
size_t skip_line_number(const std::string &t)
{
    size_t pos = 0;
    if (pos < t.size() && t[pos] == '/') pos++;
    if (pos < t.size() && t[pos] == 'n') {
        pos++;
        while (pos < t.size() && (isdigit((unsigned char)t[pos]) || t[pos] == '.')) pos++;
    }
    return pos;
}

// The label after an 'o' of a normalized line: "<name>" or digits; false when neither.
bool peek_label(const std::string &t, size_t &pos, std::string &name)
{
    if (pos < t.size() && t[pos] == '<') {
        size_t end = t.find('>', pos);
        if (end == std::string::npos) return false;
        name = t.substr(pos + 1, end - pos - 1);
        pos = end + 1;
        return true;
    }
    size_t start = pos;
    while (pos < t.size() && isdigit((unsigned char)t[pos])) pos++;
    if (pos == start) return false;
    name = std::to_string(atol(t.c_str() + start));
    return true;
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

// Dispatch an O-word line to its keyword's handler.
InterpStatus Interp::execute_oword(Block &b)
{
    INTERP_FRAME();
    static const struct { OKind kind; void (Interp::*run)(Block &); } handlers[] = {
        {O_SUB, &Interp::o_sub},           {O_CALL, &Interp::o_call},
        {O_IF, &Interp::o_if},             {O_ELSEIF, &Interp::o_else},
        {O_ELSE, &Interp::o_else},         {O_ENDIF, &Interp::o_endif},
        {O_WHILE, &Interp::o_while},       {O_DO, &Interp::o_do},
        {O_ENDWHILE, &Interp::o_loop_end}, {O_ENDREPEAT, &Interp::o_loop_end},
        {O_REPEAT, &Interp::o_repeat},     {O_BREAK, &Interp::o_break},
        {O_CONTINUE, &Interp::o_continue},
    };
    if (b.o_kind == O_ENDSUB || b.o_kind == O_RETURN) return o_return(b);
    for (const auto &h : handlers)
        if (h.kind == b.o_kind) (this->*h.run)(b);
    return INTERP_OK;
}

// "sub" met in normal flow: remember the definition and skip its body.
void Interp::o_sub(Block &b)
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    if (f.sub_name == b.o_name && f.pos - 1 == f.sub_line) return;
    if (calls_.size() > 1) throw InterpError("Nested subroutine definition");
    auto it = subs_.find(b.o_name);
    if (it != subs_.end() && (it->second.file != f.file || it->second.line != f.pos - 1))
        throw InterpError("Subroutine o" + label_text(b.o_name) + " is already defined (" +
                          it->second.file->path + " line " +
                          std::to_string(it->second.line + 1) + ")");
    subs_[b.o_name] = SubDef{f.file, f.pos - 1, false};
    skip_to(b.o_name, {O_ENDSUB}, true);
    skip_sub_ = true;
}

// "return"/"endsub": leave the subroutine with an optional value; for a remap procedure the epilog
// runs at this call level, then the block that called it finishes.
InterpStatus Interp::o_return(Block &b)
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    if (f.fanuc) throw InterpError("Fanuc 'O....' subroutine definition must end with 'M99'");
    if (calls_.size() < 2 || (b.o_kind == O_ENDSUB && f.sub_name != b.o_name)) {
        flow_fail("not in a subroutine definition", b);
        return INTERP_OK;
    }
    if (f.autorestore && f.saved.valid) modal_restore(f.saved);
    bool remap = in_remap_frame();
    if (!remap) pop_call();
    value_ = b.o_has_expr ? b.o_value : 0.0;
    value_returned_ = b.o_has_expr ? 1.0 : 0.0;
    return remap ? remap_after_body() : INTERP_OK;
}

// "call": find the subroutine and enter it.
void Interp::o_call(Block &b)
{
    INTERP_FRAME();
    if (python_oword(b)) return;
    SubDef def;
    if (!find_sub(b.o_name, def, false)) sub_not_found(b.o_name, false);
    push_call(def, b.o_name, b.o_args, false);
}

// A subroutine a remap or a lathe cycle names: known, in its own file, or anywhere in the
// main program (no side effects).
bool Interp::lookup_sub(const std::string &name, SubDef &def)
{
    INTERP_FRAME();
    auto it = subs_.find(name);
    if (it != subs_.end() && !it->second.fanuc) {
        def = it->second;
        return true;
    }
    if (find_sub_file(name, def)) return true;
    const auto &main = calls_[0].file;
    size_t line;
    if (!main || scan_for_sub(*main, 0, name, line) != SubScan::SUB) return false;
    def = SubDef{main, line, false};
    return true;
}

// "<name>" for named labels, the number for numbered ones.
std::string label_text(const std::string &name)
{
    return isdigit((unsigned char)name[0]) ? name : "<" + name + ">";
}

// The error for a call whose subroutine exists nowhere.
void Interp::sub_not_found(const std::string &name, bool)
{
    INTERP_FRAME();
    size_t level = calls_.size() - 1;
    while (level > 0 && !calls_[level].file) level--;   // Python's call levels read no file
    const std::string &path = calls_[level].file ? calls_[level].file->path : std::string("(MDI)");
    throw InterpError("EOF in file:" + path + " seeking o-word: o" +
                      label_text(name) + " from line: " + std::to_string(s_.sequence_number));
}

// Scan f from line `from` for the definition of `name` ("o<name> sub" or a bare Fanuc
// "O<n>"), stopping at the '%' that closes the program.
SubScan Interp::scan_for_sub(const SourceFile &f, size_t from, const std::string &name,
                             size_t &line)
{
    INTERP_FRAME();
    std::string n;
    OKind k;
    for (line = from; line < f.lines.size(); line++) {
        if (f.closes(line)) return SubScan::PERCENT;
        if (peek_oword(f.lines[line], n, k) && k == O_SUB && n == name) return SubScan::SUB;
        if (fanuc_label_name(f.lines[line]) == name) return SubScan::FANUC;
    }
    return SubScan::END;
}

// A call of one style must not reach a definition of the other.
void Interp::check_sub_style(const SubDef &def, bool fanuc) const
{
    INTERP_FRAME();
    if (def.fanuc == fanuc) return;
    const std::string &line = def.file->lines[def.line];
    if (fanuc)
        throw InterpErrorAt("'O.... sub' subroutine must be called with 'O.... call'", line);
    throw InterpErrorAt("Fanuc 'O....' subroutine must be called with 'M98'", line);
}

// Locate a subroutine: known, later in the current file (top level only), or in a file on the
// search path. A search that reaches the closing '%' ends the program there (FINISH).
bool Interp::find_sub(const std::string &name, SubDef &def, bool fanuc)
{
    INTERP_FRAME();
    auto it = subs_.find(name);
    if (it != subs_.end()) {
        def = it->second;
        check_sub_style(def, fanuc);
        return true;
    }
    CallFrame &f = calls_.back();
    if ((calls_.size() > 1 && !fanuc) || !f.file) return !fanuc && find_sub_file(name, def);
    size_t line;
    SubScan hit = scan_for_sub(*f.file, f.pos, name, line);
    if (hit == SubScan::PERCENT) {
        out().finish();
        throw InterpErrorAt("EOF in file:" + f.file->path + " seeking o-word: o" +
                            label_text(name) + " from line: " +
                            std::to_string(s_.sequence_number), f.file->lines[line]);
    }
    if (hit == SubScan::END) return !fanuc && find_sub_file(name, def);
    def = SubDef{f.file, line, hit == SubScan::FANUC};
    check_sub_style(def, fanuc);
    subs_[name] = def;
    return true;
}

// A subroutine in its own file <name>.ngc on PROGRAM_PREFIX, SUBROUTINE_PATH, WIZARD_ROOT or
// beside the main program.
bool Interp::find_sub_file(const std::string &name, SubDef &def)
{
    INTERP_FRAME();
    std::vector<std::string> dirs;
    if (!s_.settings.program_prefix.empty()) dirs.push_back(s_.settings.program_prefix);
    for (const std::string &d : s_.settings.subroutine_path) dirs.push_back(d);
    if (!s_.settings.wizard_root.empty()) dirs.push_back(s_.settings.wizard_root);
    const std::string &main = calls_[0].file ? calls_[0].file->path : std::string();
    size_t slash = main.rfind('/');
    dirs.push_back(slash == std::string::npos ? "." : main.substr(0, slash));
    for (const std::string &d : dirs) {
        auto file = load_sub_file((d.empty() ? std::string(".") : d) + "/" + name + ".ngc");
        if (!file) continue;
        size_t line;
        if (scan_for_sub(*file, 0, name, line) != SubScan::SUB) continue;
        def = SubDef{file, line, false};
        return true;
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

// "break": leave the loop.
void Interp::o_break(Block &b)
{
    leave_loop(b, false);
}

// "continue": next iteration of the loop.
void Interp::o_continue(Block &b)
{
    leave_loop(b, true);
}

// Skip to the end of the innermost loop named by b (past it for break, onto it for continue).
void Interp::leave_loop(Block &b, bool cont)
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

// Guard against endless loops: a clear error instead of a hang ([RS274NGC]
// MAX_LOOP_ITERATIONS / MAX_TOTAL_LOOP_ITERATIONS, 0 = no limit).
void Interp::count_iteration(long &iterations, const std::string &name)
{
    INTERP_FRAME();
    long limit = s_.settings.loop_limit, total = s_.settings.total_loop_limit;
    if (++iterations > limit && limit > 0)
        throw InterpError(std::to_string(s_.sequence_number) + ": loop o" + name +
                          " ran more than " + std::to_string(limit) + " iterations");
    if (++total_iterations_ > total && total > 0)
        throw InterpError(std::to_string(s_.sequence_number) + ": loop o" + name +
                          " ran more than " + std::to_string(total) +
                          " iterations of all loops in this program");
}
