// tooltable.hh: loading tool table files into tool-data entries.
#ifndef OPENEMC_RS274NGC_TOOLTABLE_HH
#define OPENEMC_RS274NGC_TOOLTABLE_HH

#include <string>
#include <vector>

#include "canon.hh"

// Load path into tools (index 0 = spindle); false with error set when unreadable.
bool load_tool_table(const std::string &path, std::vector<CanonTool> &tools, std::string &error);

#endif
