// task_interp.cc: the interpreter task owns: set-up, synch with the machine, active codes, user M codes, tools.
#include "task.hh"

#include <algorithm>
#include <cstdio>

#include "inifile.hh"

bool Task::init_interp(std::string *error)
{
    interp_ = std::make_unique<Interp>(*canon_);
    if (!interp_->load_ini(cfg_.ini_path)) {
        *error = cfg_.ini_path + ": interpreter can't read the INI file";
        return false;
    }
    IniFile ini(cfg_.ini_path);
    auto var = ini.Find("PARAMETER_FILE", "RS274NGC");
    interp_->set_var_file(var ? *var : "");
    interp_->set_task(true);
    interp_->set_start_in_machine_units(true);
    interp_->set_loop_on_main_m99(true);
    interp_->set_block_delete(block_delete_);
    interp_->set_tools(io_.table().canon_tools());
    interp_->set_user_m_handler([this](int m, double p, double q) { return user_m(m, p, q); });
    interp_->set_hal_reader([](const std::string &name, double &v) {
        hal_type_t type;
        hal_data_u *data;
        bool conn;
        if (hal_get_pin_value_by_name(name.c_str(), &type, &data, &conn) != 0) return false;
        switch (type) {
        case HAL_BIT: v = data->b; return true;
        case HAL_FLOAT: v = data->f; return true;
        case HAL_S32: v = data->s; return true;
        case HAL_U32: v = data->u; return true;
        default: return false;
        }
    });
    canon_->set_tagger([this](state_tag_t &t) { interp_tag(t); });
    try {
        interp_->init();
    } catch (const std::exception &e) {
        *error = std::string("interpreter init failed: ") + e.what();
        return false;
    }
    return true;
}

// Run [RS274NGC]RS274NGC_STARTUP_CODE: its settings take effect, its actions are dropped (machine in E-stop).
void Task::run_startup_code()
{
    if (cfg_.startup_code.empty()) return;
    list_.clear();
    size_t keep = 0;
    InterpStatus st = interp_->execute_line(cfg_.startup_code);
    for (int n = 0; st != INTERP_ERROR && interp_->state().call_level > 0 && n < 100000; n++)
        st = interp_->execute_next();
    if (st == INTERP_ERROR) operator_error(interp_->error_text());
    canon_->take_needs();
    drop_output_since(keep);
    // the settings it made (offsets, tool length offset, path control) take effect now
    while (!list_.empty()) issue(list_.pop());
    exec_state_ = EMC_TASK_EXEC_DONE;
}

// ON_ABORT_COMMAND: run the O-call after an abort; its output runs like MDI output.
void Task::run_abort_command()
{
    if (cfg_.on_abort_command.empty() || !interp_) return;
    InterpStatus st = interp_->execute_line(cfg_.on_abort_command);
    for (int n = 0; st != INTERP_ERROR && interp_->state().call_level > 0 && n < 100000; n++)
        st = interp_->execute_next();
    if (st == INTERP_ERROR) operator_error(interp_->error_text());
    canon_->take_needs();
    canon_->flush();
}

// Bring the interpreter up to date with the machine (after probes, M66, tool changes, aborts).
void Task::interp_synch()
{
    if (!interp_) return;
    EmcPose pos = mst_.carte_pos_cmd;
    canon_->set_position(pos);
    xl_.set_position(pos);
    InterpState &s = interp_->state();
    CanonPose p = canon_->to_program(pos);
    s.current = Pose{p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w};
    if (synch_needs_.probe) {
        CanonPose t = canon_->to_program(mst_.probed_pos);
        const double v[9] = {t.x, t.y, t.z, t.a, t.b, t.c, t.u, t.v, t.w};
        for (int i = 0; i < 9; i++) s.params[5061 + i] = v[i];
        s.params[5070] = mst_.probe_tripped;
    }
    if (synch_needs_.wait_input) {
        int i = synch_needs_.wait_index;
        if (st_.task.input_timeout) s.params[5399] = -1;
        else if (synch_needs_.wait_digital) s.params[5399] = i >= 0 && i < EMCMOT_MAX_DIO ? mst_.synch_di[i] : 0;
        else s.params[5399] = i >= 0 && i < EMCMOT_MAX_AIO ? mst_.analog_input[i] : 0;
    }
    synch_needs_ = CanonBlockNeeds();
    interp_->set_tools(io_.table().canon_tools());
    int idx = io_.table().find(io_.tool_in_spindle());
    s.current_pocket = io_.table().random() ? 0 : (idx > 0 ? idx : 0);
    s.selected_pocket = io_.prepped_index();
}

// The active G/M codes and settings (nml.md sec. 5 layout): the interpreter's own, as a snapshot
// between blocks (no group-0, stop or tool-change code of a block in progress) that keeps the
// exact cutter compensation mode (G41.1/G42.1), so a state tag restores it.
void Task::interp_codes(int32_t *g, int32_t *m, double *v) const
{
    int gi[STATE_TAG_GCODES], mi[STATE_TAG_MCODES];
    interp_->active_g_codes(gi);
    interp_->active_m_codes(mi);
    interp_->active_settings(v);
    const InterpState &s = interp_->state();
    gi[2] = -1;
    gi[4] = s.comp_code;
    gi[16] = s.params[5210] == 1.0 ? 923 : -1;
    mi[1] = -1;
    mi[3] = -1;
    std::copy(gi, gi + STATE_TAG_GCODES, g);
    std::copy(mi, mi + STATE_TAG_MCODES, m);
}

void Task::interp_tag(state_tag_t &t) const
{
    t.flags = STATE_TAG_VALID;
    t.line_number = interp_->state().sequence_number;
    interp_codes(t.gcodes, t.mcodes, t.settings);
}

// M100-M199: queue the user's program with P and Q; false when there is none.
bool Task::user_m(int m, double p, double q)
{
    std::string path = interp_->find_user_m(m);
    if (path.empty()) return false;
    canon_->flush();
    EMC_SYSTEM_CMD c;
    char text[LINELEN];
    snprintf(text, sizeof text, "%s %f %f", path.c_str(), p, q);
    emc_set_text(c.string, text);
    list_.append(c, interp_->state().sequence_number);
    return true;
}

int Task::tool_index(int toolno)
{
    if (toolno == 0 && !io_.table().random()) return 0;
    return io_.table().find(toolno);
}

// Publish the table for UIs and keep the file current.
void Task::publish_tools()
{
    if (!io_.take_table_changed()) return;
    const auto &rows = io_.table().rows();
    if (tooldata_) tooldata_publish(tooldata_, rows.data(), (int)rows.size());
    if (interp_) interp_->set_tools(io_.table().canon_tools());
}

void Task::tool_load_table(const std::string &file)
{
    std::vector<std::string> errors;
    io_.load_tools(file.empty() ? io_.table_path() : file, &errors);
    for (const std::string &e : errors) operator_error(e);
    publish_tools();
}

void Task::tool_set_offset(const EMC_TOOL_SET_OFFSET &m)
{
    io_.set_offset(m);
    std::string err = io_.save();
    if (!err.empty()) operator_error(err);
    publish_tools();
}

void Task::tool_set_number(int index)
{
    io_.set_number(index);
    std::string err = io_.save();
    if (!err.empty()) operator_error(err);
    publish_tools();
}

void Task::coolant(bool mist, bool on) { io_.coolant(mist, on); }

// S while the spindle turns: a new speed; while stopped only remembered by the interpreter.
void Task::spindle_speed(const EMC_SPINDLE_SPEED &m)
{
    int s = m.spindle >= 0 && m.spindle < EMCMOT_MAX_SPINDLES ? m.spindle : 0;
    if (!mst_.spindle[s].state) return;
    emcmot_command_t c = MotionTranslator::make(EMCMOT_SPINDLE_ON);
    c.spindle = s;
    c.speed = m.speed;
    c.css_factor = m.factor;
    c.css_xoffset = m.xoffset;
    send(c);
}

// After an abort, the interpreter's modal state goes back to what the executing segment was
// programmed with (its state tag), not what readahead had reached (LinuxCNC's state restore).
void Task::restore_tag(const state_tag_t &t)
{
    if (!(t.flags & STATE_TAG_VALID) || !interp_) return;
    InterpState &s = interp_->state();
    const int32_t *g = t.gcodes;
    s.motion_mode = g[1];
    s.plane = g[3] == 190 ? CANON_PLANE_YZ : g[3] == 180 ? CANON_PLANE_XZ : g[3] == 171 ? CANON_PLANE_UV
            : g[3] == 191 ? CANON_PLANE_VW : g[3] == 181 ? CANON_PLANE_UW : CANON_PLANE_XY;
    s.distance_incremental = g[6] == 910;
    s.feed_mode = g[7] == 930 ? FEED_INVERSE_TIME : g[7] == 950 ? FEED_UNITS_PER_REV : FEED_UNITS_PER_MINUTE;
    s.retract = g[10] == 980 ? RETRACT_OLD_Z : RETRACT_R_PLANE;
    s.control_mode = g[11] == 611 ? CANON_EXACT_STOP : g[11] == 610 ? CANON_EXACT_PATH : CANON_CONTINUOUS;
    s.ijk_absolute = g[14] == 901;
    s.lathe_diameter = g[15] == 70;
    s.feed_rate = t.settings[1];
    s.speed[0] = t.settings[2];
    s.tolerance = t.settings[3];
    s.naivecam_tolerance = t.settings[4];
    restore_origin(g[8]);
    canon_->select_plane(s.plane);
    canon_->set_motion_control_mode(s.control_mode, s.tolerance);
    canon_->set_naivecam_tolerance(s.naivecam_tolerance);
    canon_->set_feed_rate(s.feed_rate);
}

// The coordinate system of a state tag (G54 = 540 ... G59.3 = 593) made active again.
void Task::restore_origin(int code)
{
    static const int codes[] = {540, 550, 560, 570, 580, 590, 591, 592, 593};
    int index = 0;
    for (int i = 0; i < 9; i++)
        if (codes[i] == code) index = i + 1;
    InterpState &s = interp_->state();
    if (index == 0 || index == s.origin_index) return;
    s.origin_index = index;
    s.params[5220] = index;
    CanonPose p;
    double *f[9] = {&p.x, &p.y, &p.z, &p.a, &p.b, &p.c, &p.u, &p.v, &p.w};
    for (int i = 0; i < 9; i++) {
        bool linear = i < 3 || i > 5;
        double stored = s.params[5201 + 20 * index + i];
        s.origin_offset[i] = linear ? s.user_to_program(stored) : stored;
        *f[i] = s.origin_offset[i];
    }
    s.rotation_xy = s.params[5210 + 20 * index];
    canon_->set_g5x_offset(index, p);
    canon_->set_xy_rotation(s.rotation_xy);
}
