// interp.cc: interpreter life cycle: init, open, line loop, error capture, close and exit.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "inifile.hh"
#include "interp.hh"

namespace {

// strip trailing blanks and CR
std::string rstrip(const std::string &s)
{
    size_t n = s.size();
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r' || s[n - 1] == '\n'))
        n--;
    return s.substr(0, n);
}

// true when the line is a lone '%' (blanks allowed)
bool is_percent(const std::string &line)
{
    size_t i = line.find_first_not_of(" \t");
    return i != std::string::npos && line[i] == '%' &&
           line.find_first_not_of(" \t", i + 1) == std::string::npos;
}

} // namespace

// Create an interpreter writing canon calls to out.
Interp::Interp(Canon &out) : real_out_(out)
{
    if (cutcomp::make_engine) comp_ = cutcomp::make_engine(s_, out);
    calls_.emplace_back();
    s_.tools.resize(1);
    s_.params[5599] = 1;
}

Interp::~Interp() = default;

// The canon to call: the comp filter when present.
Canon &Interp::out()
{
    return comp_ ? comp_->canon() : real_out_;
}

// Initialise the state from the canon and the parameter file; emits the init calls.
void Interp::init()
{
    INTERP_FRAME();
    Canon &c = real_out_;
    c.init_canon();
    s_.external_length_units = c.get_external_length_units();
    s_.machine_units = s_.external_length_units > 0.5 ? CANON_UNITS_MM : CANON_UNITS_INCHES;
    s_.units = start_in_machine_units_ ? c.get_external_length_unit_type() : CANON_UNITS_MM;
    double clear = s_.units == CANON_UNITS_MM ? 1.0 : 0.050;
    s_.peck_clearance_g73 = s_.settings.g73_peck_clearance >= 0 ? s_.settings.g73_peck_clearance : clear;
    s_.peck_clearance_g83 = s_.settings.g83_peck_clearance >= 0 ? s_.settings.g83_peck_clearance : clear;
    s_.control_mode = c.get_external_motion_control_mode();
    s_.tolerance = c.get_external_motion_control_tolerance();
    s_.naivecam_tolerance = c.get_external_motion_control_naivecam_tolerance();
    s_.feed_hold = c.get_external_feed_hold_enable();
    s_.adaptive_feed = c.get_external_adaptive_feed_enable();
    read_var_file();
    if (s_.settings.disable_g92_persistence)
        for (int i = 5210; i <= 5219; i++) s_.params[i] = 0;
    s_.current_pocket = c.get_external_tool_slot();
    s_.selected_pocket = c.get_external_selected_tool_slot();
    c.use_length_units(s_.units);
    int index = clamp_int(s_.params[5220]);
    if (index < 1 || index > 9) index = 1;
    s_.origin_index = index;
    s_.params[5220] = index;
    bool apply = s_.params[5210] != 0.0 && !s_.settings.disable_g92_persistence;
    for (int i = 0; i < AX_COUNT; i++) {
        bool rot = i >= AX_A && i <= AX_C;
        double g5x = s_.params[5201 + 20 * index + i], g92 = s_.params[5211 + i];
        s_.origin_offset[i] = rot ? g5x : s_.user_to_program(g5x);
        s_.axis_offset[i] = apply ? (rot ? g92 : s_.user_to_program(g92)) : 0.0;
    }
    s_.rotation_xy = s_.params[5210 + 20 * index];
    emit_g5x();
    emit_g92();
    c.set_xy_rotation(s_.rotation_xy);
    c.set_feed_reference(CANON_XYZ);
    CanonPose p = c.get_external_position();
    s_.current = Pose{p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w};
    write_var_file();
    start_python();
}

// Load a file into memory (nullptr when unreadable).
std::shared_ptr<SourceFile> Interp::load_file(const std::string &path)
{
    INTERP_FRAME();
    FILE *in = fopen(path.c_str(), "rb");
    if (!in) return nullptr;
    std::string text;
    char buf[1 << 16];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, in)) > 0) text.append(buf, n);
    fclose(in);
    return make_source(path, text);
}

// Split program text into a SourceFile.
std::shared_ptr<SourceFile> Interp::make_source(const std::string &path, const std::string &text)
{
    INTERP_FRAME();
    auto f = std::make_shared<SourceFile>();
    f->path = path;
    f->lines.reserve((size_t)std::count(text.begin(), text.end(), '\n') + 1);
    size_t start = 0;
    while (start < text.size()) {
        size_t nl = text.find('\n', start);
        if (nl == std::string::npos) nl = text.size();
        size_t end = nl;
        while (end > start && (text[end - 1] == ' ' || text[end - 1] == '\t' || text[end - 1] == '\r'))
            end--;
        f->lines.emplace_back(text, start, end - start);
        start = nl + 1;
    }
    for (size_t i = 0; i < f->lines.size(); i++) {
        if (f->lines[i].find_first_not_of(" \t") == std::string::npos) continue;
        f->percent = is_percent(f->lines[i]);
        f->percent_line = i;
        break;
    }
    return f;
}

// True when line i is the '%' that ends a percent-delimited program.
bool SourceFile::closes(size_t i) const
{
    return percent && i != percent_line && i < lines.size() && is_percent(lines[i]);
}

// Open the main program.
void Interp::open(const std::string &path)
{
    INTERP_FRAME();
    auto f = load_file(path);
    if (!f) throw InterpError("Unable to open file <" + path + ">");
    // LinuxCNC reads up to the first non-blank line while opening: a file without one fails
    // there, before the interpreter is reset (so no ON_RESET is emitted)
    bool blank = std::all_of(f->lines.begin(), f->lines.end(), [](const std::string &l) {
        return std::all_of(l.begin(), l.end(), [](unsigned char ch) { return std::isspace(ch); });
    });
    if (blank) throw InterpError("File ended with no percent sign (%)");
    open_source(f);
}

// Open program text held in memory (fuzzing, previews).
void Interp::open_text(const std::string &name, const std::string &text)
{
    INTERP_FRAME();
    open_source(make_source(name, text));
}

// Make f the main program.
void Interp::open_source(const std::shared_ptr<SourceFile> &f)
{
    INTERP_FRAME();
    const std::string &path = f->path;
    remap_stack_.clear();
    calls_.resize(1);
    calls_[0] = CallFrame();
    calls_[0].file = f;
    total_iterations_ = 0;
    spline_continues_ = false;
    nurbs_open_ = false;
    s_.filename = path;
    file_open_ = true;
    skipping_ = false;
    s_.line_text.clear();
    real_out_.on_reset();
}

// Close the program file (ON_RESET unless lazy close).
void Interp::close()
{
    INTERP_FRAME();
    if (comp_) comp_->reset();
    file_open_ = false;
    s_.line_text.clear();
    if (!s_.settings.lazy_close) real_out_.on_reset();
}

// Interpreter exit: save parameters and reset the canon.
void Interp::exit()
{
    INTERP_FRAME();
    write_var_file();
    if (py_) {
        PyOutcome o = py_->call_delete();
        if (o.kind == PyOutcome::ERROR) fprintf(stderr, "%s\n", o.error.c_str());
    }
    s_.line_text.clear();
    real_out_.on_reset();
}

// Read and execute the next line of the open program.
InterpStatus Interp::execute_next()
{
    INTERP_FRAME();
    if (remap_suspended()) {
        try {
            return resume_remap();
        } catch (const InterpError &e) {
            return fail(e, s_.line_text);
        }
    }
    CallFrame &f = calls_.back();
    if (!f.file || f.pos >= f.file->lines.size()) {
        s_.line_text.clear();
        error_line_.clear();
        bool pct = calls_[0].file && calls_[0].file->percent;
        eof_error_ = true;
        error_ = pct ? "File ended with no percent sign (%)"
                     : "File ended with no percent sign (%) or program end (M2)";
        return INTERP_ERROR;
    }
    s_.sequence_number = (int)f.pos + 1;
    const std::string &line = f.file->lines[f.pos++];
    if (f.file->percent && f.pos - 1 == f.file->percent_line) {
        s_.line_text = line;
        return INTERP_OK;
    }
    if (f.file->closes(f.pos - 1) && !skipping_) {
        s_.line_text = line;
        out().finish();
        return INTERP_EXIT;
    }
    return run_line(line);
}

// Execute one MDI line.
InterpStatus Interp::execute_line(const std::string &text)
{
    INTERP_FRAME();
    if (remap_suspended()) {
        if (text.find_first_not_of(" \t\r\n") != std::string::npos) {
            error_ = "Cannot execute '" + text + "': a remapped code waits to be resumed";
            error_line_ = text;
            return INTERP_ERROR;
        }
        try {
            return resume_remap();
        } catch (const InterpError &e) {
            return fail(e, s_.line_text);
        }
    }
    if (calls_.size() <= 1 && (calls_.empty() || calls_[0].flow.empty())) total_iterations_ = 0;
    return run_line(rstrip(text));
}

// Parse and execute one line, turning errors into INTERP_ERROR.
InterpStatus Interp::run_line(const std::string &raw)
{
    INTERP_FRAME();
    s_.line_text = raw;
    eof_error_ = false;
    error_stack_.clear();
    try {
        return run_line_body(raw);
    } catch (const InterpError &e) {
        return fail(e, raw);
    }
}

// Skip, parse and execute one line; errors propagate.
InterpStatus Interp::run_line_body(const std::string &raw)
{
    INTERP_FRAME();
    if (line_budget_ >= 0 && line_budget_-- == 0) throw InterpError("Line budget exhausted");
    if (skipping_) {
        std::string name;
        OKind kind;
        if (!peek_oword(raw, name, kind) || !skip_match(name, kind)) return INTERP_OK;
    }
    s_.params[5600] = real_out_.get_external_toolchanger_fault();
    s_.params[5601] = real_out_.get_external_toolchanger_reason();
    Block b;
    parse_line(raw, b);
    if (b.block_delete && block_delete_) return INTERP_OK;
    return execute_block(b);
}

// Record an error (an InterpErrorAt names its own line, e.g. the call line a remap generates) and unwind.
InterpStatus Interp::fail(const InterpError &e, const std::string &raw)
{
    error_ = e.what();
    auto at = dynamic_cast<const InterpErrorAt *>(&e);
    error_line_ = at ? at->line() : raw;
    unwind_after_error();
    return INTERP_ERROR;
}

// After an error: drop subroutine levels, skips and held comp moves.
void Interp::unwind_after_error()
{
    INTERP_FRAME();
    remap_stack_.clear();
    while (calls_.size() > 1) pop_call();
    skipping_ = false;
    nurbs_open_ = false;
    if (comp_) comp_->reset();
    s_.comp_side = CANON_SIDE_OFF;
    s_.comp_code = 400;
}

// A ':'-separated directory list (at most 10 entries, as SUBROUTINE_PATH allows).
static std::vector<std::string> split_path(const std::string &list)
{
    std::vector<std::string> dirs;
    size_t start = 0;
    while (start <= list.size() && dirs.size() < 10) {
        size_t colon = list.find(':', start);
        if (colon == std::string::npos) colon = list.size();
        dirs.push_back(list.substr(start, colon - start));
        start = colon + 1;
    }
    return dirs;
}

// Read the [RS274NGC] settings of an INI file.
bool Interp::load_ini(const std::string &path)
{
    INTERP_FRAME();
    IniFile ini;
    ini.SetQuiet(true);
    if (!ini.Open(path)) return false;
    ini_path_ = path;
    InterpSettings &st = s_.settings;
    st.ini_file = path;
    st.lazy_close = true;
    auto real = [&](const char *key, const char *sec, double def) {
        auto v = ini.FindReal(key, sec);
        return v ? *v : def;
    };
    auto flag = [&](const char *key, const char *sec, bool def) {
        auto v = ini.FindInt(key, sec);
        return v ? *v != 0 : def;
    };
    st.g73_peck_clearance = real("G73_PECK_CLEARANCE", "RS274NGC", -1);
    st.g83_peck_clearance = real("G83_PECK_CLEARANCE", "RS274NGC", -1);
    st.orient_offset = real("ORIENT_OFFSET", "RS274NGC", 0);
    st.retain_g43 = flag("RETAIN_G43", "RS274NGC", false);
    st.disable_g92_persistence = flag("DISABLE_G92_PERSISTENCE", "RS274NGC", false);
    st.disable_auto_g54 = flag("DISABLE_AUTO_G54", "RS274NGC", false);
    st.oword_narg = flag("OWORD_NARGS", "RS274NGC", false);
    st.oword_warnonly = flag("OWORD_WARNONLY", "RS274NGC", false);
    st.disable_fanuc_style_sub = flag("DISABLE_FANUC_STYLE_SUB", "RS274NGC", false);
    st.ini_vars = flag("INI_VARS", "RS274NGC", true);
    st.loop_limit = (long)real("MAX_LOOP_ITERATIONS", "RS274NGC", (double)st.loop_limit);
    st.total_loop_limit =
        (long)real("MAX_TOTAL_LOOP_ITERATIONS", "RS274NGC", (double)st.total_loop_limit);
    st.hal_pin_vars = flag("HAL_PIN_VARS", "RS274NGC", true);
    st.tool_change_quill_up = flag("TOOL_CHANGE_QUILL_UP", "EMCIO", false);
    st.tool_change_at_g30 = flag("TOOL_CHANGE_AT_G30", "EMCIO", false);
    st.tool_change_with_spindle_on = flag("TOOL_CHANGE_WITH_SPINDLE_ON", "EMCIO", false);
    st.random_toolchanger = flag("RANDOM_TOOLCHANGER", "EMCIO", false);
    auto spindles = ini.FindInt("SPINDLES", "TRAJ");
    if (spindles && *spindles >= 1 && *spindles <= SPINDLE_COUNT) s_.num_spindles = *spindles;
    auto units = ini.Find("LINEAR_UNITS", "TRAJ");
    st.metric_machine = !units ? -1 : *units == "inch" ? 0 : 1;
    if (auto v = ini.Find("PROGRAM_PREFIX", "DISPLAY")) st.program_prefix = IniFile::TildeExpand(*v);
    if (auto v = ini.Find("WIZARD_ROOT", "WIZARD")) st.wizard_root = *v;
    if (auto v = ini.Find("SUBROUTINE_PATH", "RS274NGC")) st.subroutine_path = split_path(*v);
    if (auto v = ini.Find("USER_M_PATH", "RS274NGC")) st.user_m_path = split_path(*v);
    if (auto v = ini.Find("PARAMETER_FILE", "RS274NGC")) var_file_ = *v;
    load_remaps(ini);
    load_python_config(ini);
    return true;
}
