// io_control.hh: the former iocontrol inside task: HAL component iocontrol.0, E-stop chain, coolant, tool changer.
#ifndef IO_CONTROL_HH
#define IO_CONTROL_HH

#include <string>
#include <vector>

#include "emc_nml.hh"
#include "hal.h"
#include "tool_table.hh"

// iocontrol.0 pins (nml.md sec. 5 "HAL pins owned by task").
struct IoPins {
    hal_bit_t *user_enable_out, *user_request_enable, *emc_enable_in;
    hal_bit_t *coolant_flood, *coolant_mist;
    hal_bit_t *tool_prepare, *tool_prepared, *tool_change, *tool_changed;
    hal_s32_t *tool_prep_number, *tool_prep_pocket, *tool_prep_index, *tool_number, *tool_from_pocket;
};

class IoControl {
public:
    IoControl(const std::string &tool_table_path, bool random);
    // Create component iocontrol with its pins and make it ready; false with *error.
    bool create_hal(std::string *error);
    void destroy_hal();
    // Load the tool table file (start-up, EMC_TOOL_LOAD_TOOL_TABLE); errors as messages.
    bool load_tools(const std::string &path, std::vector<std::string> *errors);
    // Per cycle: E-stop input, handshakes; fills st.
    void update(EMC_IO_STAT &st);
    // E-stop chain: user-enable-out off (estop) or on with a request pulse (reset).
    void estop_on();
    void estop_reset();
    // Drop pending handshakes (abort); the spindle keeps its tool.
    void abort();
    void coolant(bool mist, bool on);
    // Tool commands. prepare: T word; load: M6; set_number: M61 (tool-data index).
    void prepare(int tool, int index);
    void load();
    void set_number(int index);
    // G10 L1/L10/L11 and command.tool_offset(): the row of index (or of toolno when index < 0).
    void set_offset(const EMC_TOOL_SET_OFFSET &m);
    bool done() const { return !preparing_ && !changing_; }
    bool changing() const { return changing_; }
    const ToolTable &table() const { return table_; }
    // Table changed since the last call (to publish it and resynch the interpreter).
    bool take_table_changed() { bool c = changed_; changed_ = false; return c; }
    // Save the table to its file; error message or "".
    std::string save();
    const std::string &table_path() const { return path_; }
    int tool_in_spindle() const { return tool_in_spindle_; }
    int prepped_index() const { return prepped_; }

private:
    void finish_change();
    bool prepared_is_loaded() const;
    int hal_id_ = -1;
    IoPins *pins_ = nullptr;
    ToolTable table_;
    std::string path_;
    bool mist_ = false, flood_ = false;
    bool request_pulse_ = false;
    bool preparing_ = false, changing_ = false;
    int prepped_ = -1;          // tool-data index of the prepared tool
    int reported_prepped_ = -1; // what status shows: set when the changer confirmed the prepare
    int prep_tool_ = 0;         // its number
    int tool_in_spindle_ = 0;
    int tool_from_pocket_ = 0;
    bool changed_ = true;
};

#endif
