// tool_table.hh: LinuxCNC tool table files (canon.md sec. 3): loading, saving (temp file + rename) and lookups.
#ifndef TOOL_TABLE_HH
#define TOOL_TABLE_HH

#include <string>
#include <vector>

#include "canon.hh"
#include "tooldata.h"

// The table task owns. entries[0] is the spindle. A random changer keeps tool data index ==
// pocket number (P0 = spindle); a non-random one numbers the rows 1, 2, ... in file order and
// entries[0] is a copy of the loaded tool's row (toolno -1 / 0 when the spindle is empty).
class ToolTable {
public:
    explicit ToolTable(bool random = false) : random_(random) { clear(); }
    // Read path; false with "file:line: what" messages in *errors (good lines still load).
    bool load(const std::string &path, std::vector<std::string> *errors);
    // Write the table to path through a temporary file in the same folder and a rename.
    bool save(const std::string &path, std::string *error) const;
    void clear();
    bool random() const { return random_; }
    int size() const { return (int)rows_.size(); }
    tooldata_entry_t &at(int index) { return rows_[index]; }
    const tooldata_entry_t &at(int index) const { return rows_[index]; }
    const std::vector<tooldata_entry_t> &rows() const { return rows_; }
    // Index (> 0, or 0 on random changers) of tool toolno, -1 when absent. Tool 0 is a tool only on random changers.
    int find(int toolno) const;
    // Put entry at index, growing the table (new rows empty).
    void put(int index, const tooldata_entry_t &entry);
    // Append a row for a tool that is not in the table yet; its index.
    int append(const tooldata_entry_t &entry);
    // The table as the interpreter takes it.
    std::vector<CanonTool> canon_tools() const;

private:
    bool parse_line(const std::string &line, tooldata_entry_t &e, std::string *why) const;
    bool random_;
    std::vector<tooldata_entry_t> rows_;
};

#endif
