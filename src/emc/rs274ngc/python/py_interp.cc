// py_interp.cc: the interpreter's side of embedded Python: [PYTHON] settings, plugin start, O-word
// subroutines in module oword, ;py, comments, namedparams parameters and self.execute().
#include <cctype>
#include <cstdio>
#include <cstring>
#include <strings.h>
#include <unistd.h>

#include "inifile.hh"
#include "../interp.hh"

namespace {

// directory part of a path ("." when none)
std::string dir_of(const std::string &path)
{
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

// a relative TOPLEVEL is taken from the working directory (as LinuxCNC does), else from the INI's directory
std::string resolve_toplevel(const std::string &path, const std::string &base)
{
    std::string p = IniFile::TildeExpand(path);
    if (p.empty() || p[0] == '/' || access(p.c_str(), F_OK) == 0) return p;
    std::string beside = base + "/" + p;
    return access(beside.c_str(), F_OK) == 0 ? beside : p;
}

// every value of key in [PYTHON] (relative directories stay relative to the working directory)
std::vector<std::string> python_paths(const IniFile &ini, const char *key)
{
    std::vector<std::string> out;
    for (const std::string &v : ini.FindAll(key, "PYTHON")) out.push_back(IniFile::TildeExpand(v));
    return out;
}

// the text after "kw," when c starts with it (case-insensitive, leading blanks skipped)
bool starts_with_keyword(const std::string &c, const char *kw, std::string &rest)
{
    size_t i = c.find_first_not_of(" \t");
    if (i == std::string::npos) return false;
    size_t n = strlen(kw);
    if (strncasecmp(c.c_str() + i, kw, n) != 0) return false;
    rest = c.substr(i + n);
    return true;
}

} // namespace

// Read [PYTHON]: TOPLEVEL, PATH_PREPEND, PATH_APPEND, LOG_LEVEL, RELOAD_ON_CHANGE.
void Interp::load_python_config(const IniFile &ini)
{
    INTERP_FRAME();
    std::string base = dir_of(ini.Path());
    py_config_ = PythonConfig();
    py_config_.ini_file = ini.Path();
    if (auto v = ini.Find("TOPLEVEL", "PYTHON")) py_config_.toplevel = resolve_toplevel(*v, base);
    py_config_.path_prepend = python_paths(ini, "PATH_PREPEND");
    py_config_.path_append = python_paths(ini, "PATH_APPEND");
    if (auto v = ini.FindInt("LOG_LEVEL", "PYTHON")) py_config_.log_level = (int)*v;
    if (auto v = ini.FindBool("RELOAD_ON_CHANGE", "PYTHON")) py_config_.reload_on_change = *v;
    py_configured_ = ini.HasSection("PYTHON");
    for (const auto *table : {&g_remaps_, &m_remaps_})
        for (const auto &kv : *table) py_configured_ = py_configured_ || kv.second.needs_python();
    for (const auto &kv : letter_remaps_) py_configured_ = py_configured_ || kv.second.needs_python();
}

// The Python host, started on first use; a clear error names what needed it when it cannot start.
PyHost *Interp::python(const char *why)
{
    INTERP_FRAME();
    if (py_) return py_.get();
    std::string err;
    if (!py_failed_) {
        py_ = load_python_host(*this, py_config_, err);
        if (py_ && !py_->start(err)) py_.reset();
        py_failed_ = !py_;
    }
    if (py_) return py_.get();
    if (err.empty()) err = "the embedded Python failed to start";
    throw InterpError(std::string(why) + ": " + err);
}

// At the end of init(): start Python when [PYTHON] is configured, call __init__ and check the REMAP functions.
void Interp::start_python()
{
    INTERP_FRAME();
    if (!py_configured_) return;
    PyHost *py = python("embedded Python");
    py_named_.clear();
    for (const std::string &n : py->named_param_names()) {
        double v;
        if (n.compare(0, 5, "_ini[") != 0 && predefined(n, v))
            fprintf(stderr, "warning: namedparams.%s redefines the predefined parameter #<%s>\n",
                    n.c_str(), n.c_str());
        py_named_.insert(n);
    }
    PyOutcome o = py->call_init();
    if (o.kind == PyOutcome::ERROR) throw InterpError(o.error);
    auto check = [py](const RemapDef &d) {
        for (const std::string *f : {&d.prolog, &d.python, &d.epilog})
            if (!f->empty() && !py->callable(PY_REMAP, *f))
                fprintf(stderr, "%s:%d: REMAP=%s: '%s' is not a function of module remap\n",
                        d.ini_file.c_str(), d.ini_line, d.code.c_str(), f->c_str());
    };
    for (const auto &kv : g_remaps_) check(kv.second);
    for (const auto &kv : m_remaps_) check(kv.second);
    for (const auto &kv : letter_remaps_) check(kv.second);
}

// ;py,<statement> / ;pyrun,<statement> / ;pyreload (and the same in parentheses); false when not one.
bool Interp::python_comment(const std::string &text)
{
    INTERP_FRAME();
    std::string rest;
    PyOutcome o;
    if (starts_with_keyword(text, "pyreload", rest) && rest.find_first_not_of(" \t") == std::string::npos)
        o = python("pyreload")->reload();
    else if (starts_with_keyword(text, "pyrun,", rest))
        o = python("pyrun")->run(rest);
    else if (starts_with_keyword(text, "py,", rest))
        o = python("py")->run(rest);
    else
        return false;
    if (o.kind == PyOutcome::ERROR) throw InterpError(o.error);
    return true;
}

// The ';' comment of a raw line when it is a Python one ("" otherwise); ';' inside (...) does not count.
std::string Interp::semicolon_python(const std::string &raw)
{
    if (raw.find(';') == std::string::npos) return "";
    bool in_paren = false;
    for (size_t i = 0; i < raw.size(); i++) {
        if (raw[i] == '(') in_paren = true;
        if (raw[i] == ')') in_paren = false;
        if (raw[i] != ';' || in_paren) continue;
        std::string rest, text = raw.substr(i + 1);
        bool py = starts_with_keyword(text, "py", rest);
        return py ? text : "";
    }
    return "";
}

// "o<name> call" of a function in module oword: call it at a new call level; false when there is none.
bool Interp::python_oword(Block &b)
{
    INTERP_FRAME();
    if (!py_configured_ || !python("O-word call")->callable(PY_OWORD, b.o_name)) return false;
    push_call(SubDef{}, b.o_name, b.o_args, false);
    calls_.back().python = true;
    PyOutcome o = py_->call_oword(b.o_name, b.o_args);
    pop_call();
    if (o.kind == PyOutcome::ERROR) throw InterpError(o.error);
    value_ = o.kind == PyOutcome::VALUE ? o.value : 0.0;
    value_returned_ = o.kind == PyOutcome::VALUE ? 1.0 : 0.0;
    return true;
}

// #<name> defined by a function of module namedparams; false when it is not one.
bool Interp::python_named(const std::string &name, double &v)
{
    INTERP_FRAME();
    if (!py_ || !py_named_.count(name)) return false;
    PyOutcome o = py_->named_param(name);
    if (o.kind == PyOutcome::ERROR) throw InterpError(o.error);
    v = o.value;
    return true;
}

// self.execute(): run one line now, and any procedure it calls to its end; errors come back as status.
InterpStatus Interp::execute_nested(const std::string &text)
{
    INTERP_FRAME();
    size_t depth = calls_.size(), remaps = remap_stack_.size();
    std::string outer_line = s_.line_text;
    InterpStatus st = INTERP_OK;
    try {
        s_.line_text = text;
        st = run_line_body(text);
        while (st != INTERP_EXIT && (calls_.size() > depth || remap_stack_.size() > remaps))
            st = remap_suspended() && remap_stack_.size() > remaps ? resume_remap() : run_frame_line();
    } catch (const InterpError &e) {
        error_ = e.what();
        auto at = dynamic_cast<const InterpErrorAt *>(&e);
        error_line_ = at ? at->line() : s_.line_text;
        while (remap_stack_.size() > remaps) remap_stack_.pop_back();
        while (calls_.size() > depth) pop_call();
        st = INTERP_ERROR;
    }
    s_.line_text = outer_line;
    return st;
}

// The next line of the current call level, run without catching errors (nested execution).
InterpStatus Interp::run_frame_line()
{
    INTERP_FRAME();
    CallFrame &f = calls_.back();
    if (!f.file || f.pos >= f.file->lines.size())
        throw InterpError("File ended inside subroutine " + f.sub_name + " called from Python");
    s_.sequence_number = (int)f.pos + 1;
    std::string line = f.file->lines[f.pos++];
    s_.line_text = line;
    return run_line_body(line);
}
