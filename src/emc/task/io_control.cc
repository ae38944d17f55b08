// io_control.cc: E-stop, coolant and tool-changer handshakes on iocontrol.0, tool table bookkeeping.
#include "io_control.hh"

#include <cstring>

IoControl::IoControl(const std::string &tool_table_path, bool random)
    : table_(random), path_(tool_table_path)
{
}

bool IoControl::create_hal(std::string *error)
{
    hal_id_ = hal_init("iocontrol");
    if (hal_id_ < 0) {
        *error = "iocontrol: hal_init failed (" + std::to_string(hal_id_) + ")";
        return false;
    }
    pins_ = static_cast<IoPins *>(hal_malloc(sizeof(IoPins)));
    if (!pins_) { *error = "iocontrol: out of HAL memory"; return false; }
    struct BitPin { hal_bit_t **p; hal_pin_dir_t dir; const char *name; };
    const BitPin bits[] = {
        {&pins_->user_enable_out, HAL_OUT, "user-enable-out"},
        {&pins_->user_request_enable, HAL_OUT, "user-request-enable"},
        {&pins_->emc_enable_in, HAL_IN, "emc-enable-in"},
        {&pins_->coolant_flood, HAL_OUT, "coolant-flood"},
        {&pins_->coolant_mist, HAL_OUT, "coolant-mist"},
        {&pins_->tool_prepare, HAL_OUT, "tool-prepare"},
        {&pins_->tool_prepared, HAL_IN, "tool-prepared"},
        {&pins_->tool_change, HAL_OUT, "tool-change"},
        {&pins_->tool_changed, HAL_IN, "tool-changed"},
    };
    struct S32Pin { hal_s32_t **p; const char *name; };
    const S32Pin s32s[] = {
        {&pins_->tool_prep_number, "tool-prep-number"}, {&pins_->tool_prep_pocket, "tool-prep-pocket"},
        {&pins_->tool_prep_index, "tool-prep-index"}, {&pins_->tool_number, "tool-number"},
        {&pins_->tool_from_pocket, "tool-from-pocket"},
    };
    for (const BitPin &b : bits)
        if (hal_pin_bit_newf(b.dir, b.p, hal_id_, "iocontrol.0.%s", b.name) < 0) {
            *error = std::string("iocontrol: can't create pin iocontrol.0.") + b.name;
            return false;
        }
    for (const S32Pin &s : s32s)
        if (hal_pin_s32_newf(HAL_OUT, s.p, hal_id_, "iocontrol.0.%s", s.name) < 0) {
            *error = std::string("iocontrol: can't create pin iocontrol.0.") + s.name;
            return false;
        }
    *pins_->tool_number = tool_in_spindle_;
    return hal_ready(hal_id_) == 0 || (*error = "iocontrol: hal_ready failed", false);
}

void IoControl::destroy_hal()
{
    if (hal_id_ >= 0) hal_exit(hal_id_);
    hal_id_ = -1;
    pins_ = nullptr;
}

bool IoControl::load_tools(const std::string &path, std::vector<std::string> *errors)
{
    if (path.empty()) {
        table_.clear();
        changed_ = true;
        return true;
    }
    bool ok = table_.load(path, errors);
    if (table_.random()) {
        tool_in_spindle_ = table_.at(0).toolno;
    } else {
        int idx = table_.find(tool_in_spindle_);
        tooldata_entry_t e = idx > 0 ? table_.at(idx) : tooldata_empty_entry();
        if (idx <= 0) { e.toolno = tool_in_spindle_ > 0 ? tool_in_spindle_ : -1; }
        table_.put(0, e);
    }
    if (pins_) *pins_->tool_number = tool_in_spindle_;
    prepped_ = reported_prepped_ = -1;
    changed_ = true;
    return ok;
}

void IoControl::update(EMC_IO_STAT &st)
{
    if (pins_) {
        if (request_pulse_) request_pulse_ = false;
        else *pins_->user_request_enable = 0;
        *pins_->coolant_mist = mist_;
        *pins_->coolant_flood = flood_;
        if (preparing_ && *pins_->tool_prepared) {
            preparing_ = false;
            reported_prepped_ = prepped_;
            *pins_->tool_prepare = 0;
        }
        if (changing_ && *pins_->tool_changed) finish_change();
        st.aux.estop = !*pins_->emc_enable_in;
    }
    st.coolant.mist = mist_;
    st.coolant.flood = flood_;
    st.tool.pocketPrepped = reported_prepped_;
    st.tool.toolInSpindle = tool_in_spindle_;
    st.tool.toolFromPocket = tool_from_pocket_;
    st.tool.toolTableCurrent = table_.at(0);
    st.status = done() ? RCS_DONE : RCS_EXEC;
}

void IoControl::estop_on()
{
    if (pins_) *pins_->user_enable_out = 0;
    abort();
}

void IoControl::estop_reset()
{
    if (!pins_) return;
    *pins_->user_enable_out = 1;
    *pins_->user_request_enable = 1;
    request_pulse_ = true;
}

// Abort: drop a change or prepare in progress; the spindle keeps its tool.
void IoControl::abort()
{
    preparing_ = changing_ = false;
    if (!pins_) return;
    *pins_->tool_prepare = 0;
    *pins_->tool_change = 0;
}

void IoControl::coolant(bool mist, bool on)
{
    (mist ? mist_ : flood_) = on;
    if (pins_) *(mist ? pins_->coolant_mist : pins_->coolant_flood) = on;
}

// T word: raise tool-prepare with the tool's number, pocket and index until tool-prepared.
// The status keeps the previous prepared pocket until the changer answers. A random changer
// asked for the tool it already holds (index 0) has nothing to fetch: no handshake.
void IoControl::prepare(int tool, int index)
{
    if (!table_.random() && tool == 0) index = 0;
    prep_tool_ = tool;
    prepped_ = index;
    int pocket = index >= 0 && index < table_.size() ? table_.at(index).pocketno : 0;
    if (index == 0) pocket = 0;
    if (pins_) {
        *pins_->tool_prep_number = tool;
        *pins_->tool_prep_pocket = pocket;
        *pins_->tool_prep_index = index < 0 ? 0 : index;
    }
    if (!pins_ || (table_.random() && index == 0)) {
        reported_prepped_ = index;
        return;
    }
    // a non-random T0 (empty the spindle) names no pocket: known prepared at once, the
    // handshake still runs so the changer can put the tool away
    if (!table_.random() && index == 0) reported_prepped_ = 0;
    *pins_->tool_prepare = 1;
    preparing_ = true;
}

// True when the prepared tool is the one already in the spindle (M6 then changes nothing).
bool IoControl::prepared_is_loaded() const
{
    if (table_.random()) return prepped_ == 0;
    return prepped_ >= 0 && prep_tool_ == tool_in_spindle_;
}

// M6: raise tool-change until tool-changed; nothing to do when the tool is already loaded.
void IoControl::load()
{
    if (prepped_ < 0 || prepared_is_loaded()) return;
    changing_ = true;
    if (pins_) *pins_->tool_change = 1;
    else finish_change();
}

// The changer reported the change: update the spindle row (random: swap with the pocket).
void IoControl::finish_change()
{
    changing_ = false;
    int idx = prepped_;
    if (table_.random()) {
        if (idx >= 0 && idx < table_.size()) {
            tooldata_entry_t spindle = table_.at(0), pocket = table_.at(idx);
            spindle.pocketno = idx;
            pocket.pocketno = 0;
            table_.put(0, pocket);
            table_.put(idx, spindle);
        }
        tool_in_spindle_ = table_.at(0).toolno;
        // tool 0 (or an empty pocket) is "no tool": it came from no pocket
        tool_from_pocket_ = tool_in_spindle_ > 0 ? idx : 0;
    } else {
        tooldata_entry_t e = idx > 0 && idx < table_.size() ? table_.at(idx) : tooldata_empty_entry();
        if (idx <= 0) e.toolno = -1;
        table_.put(0, e);
        tool_in_spindle_ = idx > 0 ? e.toolno : 0;
        tool_from_pocket_ = idx > 0 ? e.pocketno : 0;
    }
    prepped_ = reported_prepped_ = -1;
    changed_ = true;
    if (!pins_) return;
    *pins_->tool_change = 0;
    *pins_->tool_number = tool_in_spindle_;
    *pins_->tool_from_pocket = tool_from_pocket_;
    *pins_->tool_prep_number = 0;
    *pins_->tool_prep_pocket = 0;
    *pins_->tool_prep_index = 0;
}

// M61: declare the tool at index (0 = none) loaded without a change.
void IoControl::set_number(int index)
{
    if (index < 0 || index >= table_.size()) return;
    if (table_.random()) {
        int tool = index == 0 ? 0 : table_.at(index).toolno;
        tooldata_entry_t e = table_.at(0);
        e.toolno = tool;
        table_.put(0, e);
        tool_in_spindle_ = tool > 0 ? tool : 0;
    } else {
        tooldata_entry_t e = index > 0 ? table_.at(index) : tooldata_empty_entry();
        if (index == 0) e.toolno = -1;
        table_.put(0, e);
        tool_in_spindle_ = index > 0 ? e.toolno : 0;
    }
    // nothing was fetched from a pocket: tool-from-pocket keeps telling the last change
    changed_ = true;
    if (pins_) *pins_->tool_number = tool_in_spindle_;
}

// New values for one tool. The row is found by number first: on a non-random changer row 0
// is only a copy of the loaded tool's row, and both are kept equal, so no row is ever lost.
void IoControl::set_offset(const EMC_TOOL_SET_OFFSET &m)
{
    int idx = table_.find(m.toolno);
    if (idx < 0 && m.pocket > 0 && m.pocket < table_.size() && table_.at(m.pocket).toolno == m.toolno) idx = m.pocket;
    tooldata_entry_t e = idx >= 0 ? table_.at(idx) : tooldata_empty_entry();
    if (idx < 0) {
        if (m.toolno <= 0) return;
        e.toolno = m.toolno;
        e.pocketno = table_.random() ? m.pocket : table_.size();
    }
    e.offset = m.offset;
    e.diameter = m.diameter;
    e.frontangle = m.frontangle;
    e.backangle = m.backangle;
    e.orientation = m.orientation;
    if (idx < 0) idx = table_.random() ? (m.pocket > 0 ? m.pocket : -1) : table_.append(e);
    if (idx < 0) return;
    table_.put(idx, e);
    if (!table_.random() && table_.at(0).toolno == m.toolno) table_.put(0, e);
    changed_ = true;
}

std::string IoControl::save()
{
    if (path_.empty()) return "";
    std::string err;
    return table_.save(path_, &err) ? "" : err;
}
