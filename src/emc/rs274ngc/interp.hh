// interp.hh: the RS274/NGC interpreter (reads lines, evaluates them, emits canon calls).
#ifndef OPENEMC_RS274NGC_INTERP_HH
#define OPENEMC_RS274NGC_INTERP_HH

#include <initializer_list>
#include <map>
#include <set>
#include <memory>
#include <string>
#include <vector>

#include "block.hh"
#include "block_steps.hh"
#include "canon.hh"
#include "interp_base.hh"
#include "interp_hooks.hh"
#include "interp_state.hh"
#include "py_host.hh"
#include "remap_def.hh"
#include "spline_geom.hh"
#include "stack_frame.hh"

// Binary operators of expressions (OP_END = closing bracket).
enum BinOp { OP_END, OP_POW, OP_MUL, OP_DIV, OP_MOD, OP_ADD, OP_SUB, OP_EQ, OP_NE, OP_GT, OP_GE,
             OP_LT, OP_LE, OP_AND, OP_OR, OP_XOR };


// A source file held in memory, one string per line.
struct SourceFile {
    std::string path;
    std::vector<std::string> lines;
    bool percent = false;          // first non-blank line is a lone '%'
    size_t percent_line = 0;       // index of that opening '%' line
    // true when line i is the '%' that ends a percent-delimited program
    bool closes(size_t i) const;
};

// What a forward search for a subroutine definition met first.
enum class SubScan { SUB, FANUC, PERCENT, END };

// An active loop or conditional of the current call level.
struct FlowFrame {
    OKind kind;                    // O_WHILE, O_DO, O_REPEAT or O_IF
    std::string name;
    size_t start = 0;              // line index of the opening line
    long count = 0;                // repeat count left
    bool taken = false;            // an if/elseif branch already ran
    long iterations = 0;           // loop passes so far (runaway guard)
};

// Position after the block-delete slash and line number of a normalized line.
size_t skip_line_number(const std::string &t);

// The label after an 'o' of a normalized line ("<name>" or digits); false when neither.
bool peek_label(const std::string &t, size_t &pos, std::string &name);

// "<name>" for a named O-word label, the number for a numbered one.
std::string label_text(const std::string &name);

// Fanuc label "O<n>" of a bare program-number line ("" when the line is not one).
std::string fanuc_label_name(const std::string &line);

// One subroutine call level.
struct CallFrame {
    std::shared_ptr<SourceFile> file;
    size_t pos = 0;                // next line index to read
    std::string sub_name;          // "" for the main program
    double saved_args[31] = {};    // caller's #1..#30
    std::map<std::string, double> locals;
    std::vector<FlowFrame> flow;
    size_t sub_line = 0;           // index of the sub / O<n> line
    int return_line = 0;           // caller's line number
    SavedModal saved;              // M70/M73 context of this level
    bool autorestore = false;      // M73: restore on return
    bool fanuc = false;            // M98 call (#1-#30 global)
    bool python = false;           // a Python O-word sub or remap body (no lines to read)
    long fanuc_count = 0;          // M98 L repeats left
    long fanuc_iterations = 0;
};

// Location of a known subroutine.
struct SubDef {
    std::shared_ptr<SourceFile> file;
    size_t line = 0;               // index of the "sub" (or bare Fanuc "O<n>") line
    bool fanuc = false;            // Fanuc-style "O<n>" ... "M99" program
};

class IniFile;

// The interpreter.
class Interp : public InterpBase, public ProfileSource {
public:
    explicit Interp(Canon &out);
    ~Interp() override;

    // read [RS274NGC] and friends from an INI file; false if unloadable
    bool load_ini(const std::string &path) override;
    // set the .var file path
    void set_var_file(const std::string &path) override { var_file_ = path; }
    // tool table (index 0 = spindle)
    void set_tools(const std::vector<CanonTool> &tools) override { s_.tools = tools; }
    // state access (tool table loading, tests)
    InterpState &state() { return s_; }
    // initialise: canon init calls, parameter file; throws InterpError
    void init() override;
    // open a program file (emits ON_RESET); throws InterpError
    void open(const std::string &path) override;
    // open program text held in memory under a name
    void open_text(const std::string &name, const std::string &text);
    // read and execute the next line of the open file
    InterpStatus execute_next() override;
    // execute one MDI line
    InterpStatus execute_line(const std::string &text) override;
    // close the file (ON_RESET unless lazy)
    void close() override;
    // interpreter exit: save parameters, ON_RESET
    void exit() override;
    // text of the last error
    const std::string &error_text() const override { return error_; }
    // source line of the last error
    const std::string &error_line() const override { return error_line_; }
    // functions the last error unwound through, innermost first
    const std::vector<std::string> &error_stack() const override { return error_stack_; }
    // current line text (for canon markers)
    const std::string &line_text() const override { return s_.line_text; }
    // block delete switch (lines starting with '/' are skipped when on)
    void set_block_delete(bool on) override { block_delete_ = on; }
    // true when the last error was the end of the file
    bool at_end_of_file() const override { return eof_error_; }
    // stop with an error after this many executed lines (-1 = unlimited; fuzzing)
    void set_line_budget(long lines) { line_budget_ = lines; }
    // where #<_hal[name]> values come from
    void set_hal_reader(HalReader fn) override { hal_reader_ = std::move(fn); }
    // what runs M100-M199
    void set_user_m_handler(UserMHandler fn) override { user_m_ = std::move(fn); }
    // executable M<m> from PROGRAM_PREFIX, then USER_M_PATH; "" when none
    std::string find_user_m(int m) const;
    // start in the machine's units (task) instead of mm (rs274's behaviour)
    void set_start_in_machine_units(bool on) { start_in_machine_units_ = on; }
    // mark the process as task (#<_task> = 1)
    void set_task(bool t) override { task_ = t; }
    void set_loop_on_main_m99(bool on) override { loop_main_m99_ = on; }
    // the modal state as LinuxCNC's activeGCodes[17] / activeMCodes[10] / activeSettings[5] (nml.md §5)
    void active_g_codes(int codes[17]) const;
    void active_m_codes(int codes[10]) const;
    void active_settings(double settings[5]) const;
    // ProfileSource: evaluated blocks of a subroutine
    std::vector<Block> sub_blocks(const std::string &name) override;
    void profile_line(std::vector<Block> &blocks, const std::string &name);

    // --- parsing (parse.cc, expr.cc) ---
    void parse_line(const std::string &raw, Block &b);
    double eval_expression(const std::string &text, size_t &pos);
    double read_real_value(const std::string &t, size_t &pos);
    double read_number(const std::string &t, size_t &pos);
    // parameters (params.cc)
    double get_numbered(int n) const;
    double get_named(const std::string &name);
    bool named_exists(const std::string &name);
    void set_named(const std::string &name, double v);
    void check_numbered_writable(int n) const;
    void check_named_writable(const std::string &name) const;

private:
    InterpStatus run_line(const std::string &raw);
    InterpStatus execute_block(Block &b);
    InterpStatus execute_steps(Block &b, size_t first);
    void unwind_after_error();
    Canon &out();

    // parse helpers (parse.cc, expr.cc, params.cc)
    void parse_words(const std::string &t, size_t pos, Block &b);
    void parse_word(char c, const std::string &t, size_t &pos, Block &b);
    void parse_g(const std::string &t, size_t &pos, Block &b);
    void parse_m(const std::string &t, size_t &pos, Block &b);
    void parse_assignment(const std::string &t, size_t &pos, Block &b);
    void parse_oword(const std::string &t, size_t &pos, Block &b);
    void parse_o_args(const std::string &t, size_t &pos, Block &b);
    std::string read_name(const std::string &t, size_t &pos);
    double read_parameter(const std::string &t, size_t &pos);
    double read_unary(const std::string &t, size_t &pos);
    double read_exists(const std::string &t, size_t &pos);
    double eval_binary(double a, BinOp op, double b);
    BinOp read_operator(const std::string &t, size_t &pos);

    // control flow (oword.cc, fanuc.cc)
    InterpStatus execute_oword(Block &b);
    void o_call(Block &b);
    InterpStatus o_return(Block &b);
    void o_sub(Block &b);
    void o_if(Block &b);
    void o_else(Block &b);
    void o_endif(Block &b);
    void o_while(Block &b);
    void o_do(Block &b);
    void o_repeat(Block &b);
    void o_loop_end(Block &b);
    void o_break(Block &b);
    void o_continue(Block &b);
    void leave_loop(Block &b, bool cont);
    void count_iteration(long &iterations, const std::string &name);
    void skip_to(const std::string &name, std::initializer_list<OKind> kinds, bool past);
    bool skip_match(const std::string &name, OKind kind);
    bool peek_oword(const std::string &line, std::string &name, OKind &kind);
    bool find_sub(const std::string &name, SubDef &def, bool fanuc);
    bool find_sub_file(const std::string &name, SubDef &def);
    bool lookup_sub(const std::string &name, SubDef &def);
    std::shared_ptr<SourceFile> load_sub_file(const std::string &path);
    SubScan scan_for_sub(const SourceFile &f, size_t from, const std::string &name, size_t &line);
    void check_sub_style(const SubDef &def, bool fanuc) const;
    [[noreturn]] void sub_not_found(const std::string &name, bool fanuc);
    std::shared_ptr<SourceFile> load_file(const std::string &path);
    std::shared_ptr<SourceFile> make_source(const std::string &path, const std::string &text);
    void open_source(const std::shared_ptr<SourceFile> &f);
    void push_call(const SubDef &def, const std::string &name, const std::vector<double> &args,
                   bool fanuc);
    void pop_call();
    InterpStatus fanuc_label(Block &b);
    void fanuc_call(Block &b);
    bool fanuc_return();
    bool restart_main();
    std::string flow_error(const std::string &what, const Block &b) const;
    void flow_fail(const std::string &what, const Block &b);

public:
    // execution steps (execute.cc, modal.cc, mcodes.cc, comments.cc, tools.cc); public for the
    // step table of execute.cc
    void step_comment(Block &b);
    void step_tool_change(Block &b);
    void step_motion(Block &b);
    void step_stop(Block &b);
    // motion handlers (motion.cc, arcs.cc, spline.cc), public for the table of motion.cc
    void move_straight(const Block &b, int mode);
    void move_arc(const Block &b, int mode);
    void move_probe(const Block &b, int code);
    void move_g33(const Block &b, int code);
    void move_spline(const Block &b, int mode);
    void nurbs_point(const Block &b, int code);
    void check_block(Block &b);
    void check_words(Block &b);
    void check_axis_words(const Block &b) const;
    bool uses_dollar(const Block &b, int motion) const;
    void do_comment(Block &b);
    std::string expand_text(const std::string &text);
    std::string expand_param(const std::string &text, size_t &i, int decimals);
    void do_spindle_mode(Block &b);
    void do_feed_mode(Block &b);
    void do_feed_rate(Block &b);
    void do_speed(Block &b);
    void do_select_tool(Block &b);
    void do_io(Block &b);
    void do_wait_input(Block &b);
    void check_wait_input(const Block &b, int &type, double &timeout) const;
    void spindle_direction(int m, int s);
    void orient_spindle(const Block &b, int sp);
    void modal_state_code(int m);
    bool do_tool_change(Block &b);
    void set_tool_number(const Block &b);
    void load_empty_spindle();
    void tool_change_moves();
    void reapply_tool_length();
    void do_spindle(Block &b);
    void do_coolant(Block &b);
    void do_overrides(Block &b);
    void set_switch(bool &state, bool on, void (Canon::*enable)(), void (Canon::*disable)());
    void do_user_m(Block &b);
    void do_dwell(Block &b);
    void do_plane(Block &b);
    void do_units(Block &b);
    void do_lathe_mode(Block &b);
    void do_comp(Block &b);
    void comp_off();
    double dynamic_comp_radius(const Block &b, int &g, int &orient) const;
    double tool_comp_radius(const Block &b, int &orient) const;
    int h_word_index(const Block &b) const;
    Pose tlo_words(const Block &b, int g) const;
    void do_tool_length(Block &b);
    void do_coord_system(Block &b);
    void do_path_control(Block &b);
    void do_distance(Block &b);
    void do_retract(Block &b);
    void do_nonmodal(Block &b);
    void do_g92_family(Block &b);
    bool do_motion(Block &b);
    bool nonmodal_motion(const Block &b);
    bool motion_runs(const Block &b);
    bool cycle_or_cancel(Block &b, int m);
    InterpStatus do_stop(Block &b);


private:
    // motion helpers (motion.cc, arcs.cc)
    Pose find_end(const Block &b);
    void polar_end(const Block &b, Pose &end);
    double straight_length(const Pose &a, const Pose &e) const;
    void arc_center_r(const Block &b, double s1, double s2, double e1, double e2, int mode,
                      double &c1, double &c2);
    void arc_center_ijk(const Block &b, double s1, double s2, double e1, double e2, double &c1,
                        double &c2);
    int arc_turns(const Block &b) const;
    double arc_length(double s1, double s2, double e1, double e2, double c1, double c2,
                      int rotation, double axial) const;
    void probe_result();
    void move_home(const Block &b, int code);
    void store_home(int code);
    void move_cycle(Block &b);
    void apply_inverse_time(double length, const Block &b);

    // splines (spline.cc)
    void check_spline(const Block &b);
    void check_nurbs(const Block &b, int first, int second);
    spline::Cubic spline_curve(const Block &b, int mode, const Pose &end);
    void nurbs_close(const Block &b);
    Pose machine_to_program_pose(const Pose &m) const;
    Pose program_to_machine_pose(const Pose &p) const;

    // offsets and tools (offsets.cc, tools.cc, modal_save.cc)
    void g10(const Block &b);
    void g10_l2(const Block &b, int l);
    double axis_word(const Block &b, int i) const;
    Pose offsets_for_point(const Block &b, Pose q, const Pose &shift, Pose old, double rot) const;
    void g10_tool(const Block &b, int l);
    void g10_reload_tools();
    int g10_tool_index(const Block &b, int l) const;
    Pose tool_pose(const CanonTool &t) const;
    Pose g10_tool_offsets(const Block &b, int l, const CanonTool &t) const;
    void store_tool_entry(int index, const CanonTool &t);
    void set_origin_index(int index);
    void emit_g5x();
    void emit_g92();
    void g92_family(int code, const Block &b);
    void g92_set(int code, const Block &b);
    int g10_system(const Block &b) const;
    void apply_tlo(const Pose &tlo);
    void convert_units(CanonUnits to);
    int find_tool_index(int toolno) const;
    void m2_reset(int code);
    void m2_stop_spindles();
    void check_closing_percent();
    void modal_save(bool autorestore);
    void modal_restore(const SavedModal &m);
    void modal_restore_block(const SavedModal &m, Block &b) const;
    void restore_modal_codes(const SavedModal &m, Block &b) const;
    void restore_coolant(const SavedModal &m, bool first);

    // REMAP= configuration (remap/remap_config.cc)
    void load_remaps(const IniFile &ini);
    std::string remap_parse_line(const std::string &line, RemapDef &def) const;
    std::string remap_parse_code(const std::string &word, RemapDef &def) const;
    std::string remap_parse_option(const std::string &key, const std::string &value, RemapDef &def) const;
    std::string remap_check_group(RemapDef &def) const;
    const RemapDef *letter_remap(char c) const;
    static int builtin_g_group(int g);
    static int builtin_m_group(int m);

    // running remapped codes (remap/remap_exec.cc, remap/remap_args.cc)
    static const ExecStep *exec_steps(size_t &count);
    const RemapDef *remap_due(const Block &b, const ExecStep &step) const;
    bool remap_active(const RemapDef *def) const;
    void check_remap_args(const Block &b);
    bool remap_uses_word(const Block &b, char c) const;
    void remap_words(const Block &b, const RemapDef &def, std::vector<double> &positional,
                     std::map<std::string, double> &named, bool check_state) const;
    void consume_remapped(Block &b, const RemapDef &def) const;
    InterpStatus start_remap(const Block &b, const RemapDef &def, size_t step);
    void push_remap_frame(RemapCall &rc, const std::vector<double> &positional,
                          const std::map<std::string, double> &named);
    InterpStatus remap_body();
    InterpStatus remap_after_body();
    InterpStatus remap_complete();
    InterpStatus remap_outcome(const PyOutcome &o, RemapPhase phase);
    InterpStatus resume_remap();
    bool remap_suspended() const;
    bool in_remap_frame() const;

    // embedded Python (python/py_interp.cc)
    void load_python_config(const IniFile &ini);
    PyHost *python(const char *why);
    void start_python();
    bool python_comment(const std::string &text);
    bool python_oword(Block &b);
    bool python_named(const std::string &name, double &v);
    static std::string semicolon_python(const std::string &raw);
    InterpStatus execute_nested(const std::string &text);
    InterpStatus run_frame_line();
    InterpStatus run_line_body(const std::string &raw);
    InterpStatus fail(const InterpError &e, const std::string &raw);

    // parameter file (varfile.cc) and predefined parameters (predef.cc)
    void read_var_file();
    std::string var_file_line(const char *line, int &last);
    void write_var_file();
    bool predefined(const std::string &name, double &v);
    static std::vector<std::string> predefined_names();
    bool hal_value(const std::string &name, double &v);
    bool predefined_position(const std::string &name, double &v) const;
    bool interp_value(const std::string &name, double &v) const;
    bool ini_value(const std::string &name, double &v);

    InterpState s_;
    Canon &real_out_;
    std::unique_ptr<cutcomp::Engine> comp_;
    std::string var_file_ = "/etc/emc2/sample-configs/sim/sim.var";
    std::set<int> in_var_file_;
    bool var_file_bad_ = false;      // the .var file was refused: never rewrite it
    std::vector<CallFrame> calls_;
    std::map<std::string, SubDef> subs_;
    std::map<std::string, std::pair<long long, std::shared_ptr<SourceFile>>> sub_files_;  // path -> (mtime+size, file)
    std::map<std::string, double> globals_;
    std::map<std::string, double> ini_cache_;
    std::string error_, error_line_;
    mutable std::vector<std::string> error_stack_;   // filled by INTERP_FRAME() while unwinding
    bool skipping_ = false;
    std::string skip_name_;
    std::vector<OKind> skip_kinds_;
    bool skip_past_ = false, skip_sub_ = false;
    int skip_start_ = 0;
    bool block_delete_ = false;
    bool task_ = false;
    bool start_in_machine_units_ = false;
    bool loop_main_m99_ = false;     // M99 in the main program restarts it (task)
    bool file_open_ = false;
    bool eof_error_ = false;
    double value_ = 0, value_returned_ = 0;
    long line_budget_ = -1;
    HalReader hal_reader_;
    UserMHandler user_m_;
    bool spline_continues_ = false;  // the last motion was a G5: the next may omit I J
    double spline_cp2_[2] = {};      // its second control point (absolute X Y)
    bool nurbs_open_ = false;        // inside a G5.2 ... G5.3 block
    unsigned nurbs_order_ = 0;
    std::vector<CanonNurbsPoint> nurbs_;
    long total_iterations_ = 0;    // loop passes since the program (or MDI command) started
    std::string ini_path_;
    std::map<int, RemapDef> g_remaps_, m_remaps_;
    std::map<char, RemapDef> letter_remaps_;   // T, S and F
    bool have_remaps_ = false;                 // any REMAP= line loaded (else blocks skip the remap checks)
    std::vector<RemapCall> remap_stack_;       // running remaps; _remap_level is its size
    const Block *current_block_ = nullptr;     // the block being executed (Python's blocks[0])
    PythonConfig py_config_;
    bool py_configured_ = false;               // [PYTHON] present or Python needed by a REMAP
    bool py_failed_ = false;                   // the plugin could not be started
    std::unique_ptr<PyHost> py_;
    std::string py_errormsg_;                  // set_errormsg() text for an INTERP_ERROR return
    std::set<std::string> py_named_;           // #<_name>s defined by module namedparams
    bool py_finish_request_ = false;           // Python set a queue-buster flag: end the block with execute-finish
    bool reading_profile_ = false;   // parsing a lathe-cycle profile: U and W are incremental X and Z

    friend struct InterpAccess;
};

#endif
