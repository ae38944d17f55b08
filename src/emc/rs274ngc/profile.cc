// profile.cc: ProfileSource for lathe cycles: the blocks a profile subroutine produces when it
// runs (its O-word flow and parameter assignments are executed, its moves only collected).
#include "interp.hh"

// Run subroutine `name` without arguments and return the evaluated blocks of its non-O-word
// lines in the order they ran (U and W are allowed there as incremental X and Z).
std::vector<Block> Interp::sub_blocks(const std::string &name)
{
    INTERP_FRAME();
    SubDef def;
    if (!lookup_sub(name, def))
        throw InterpError("Unable to find profile subroutine o" + name);
    size_t depth = calls_.size();
    std::string saved_line = s_.line_text;
    int saved_seq = s_.sequence_number;
    push_call(def, name, {}, false);
    std::vector<Block> blocks;
    try {
        while (calls_.size() > depth) profile_line(blocks, name);
    } catch (...) {
        while (calls_.size() > depth) pop_call();
        skipping_ = false;
        reading_profile_ = false;
        throw;
    }
    s_.line_text = saved_line;
    s_.sequence_number = saved_seq;
    return blocks;
}

// One line of a running profile subroutine: flow control runs, other lines are collected.
void Interp::profile_line(std::vector<Block> &blocks, const std::string &name)
{
    CallFrame &f = calls_.back();
    if (f.pos >= f.file->lines.size())
        throw InterpError("Profile subroutine o" + name + " has no endsub");
    s_.sequence_number = (int)f.pos + 1;
    const std::string &line = f.file->lines[f.pos++];
    s_.line_text = line;
    std::string label;
    OKind kind;
    if (skipping_ && (!peek_oword(line, label, kind) || !skip_match(label, kind))) return;
    Block b;
    reading_profile_ = true;
    parse_line(line, b);
    reading_profile_ = false;
    for (auto &a : b.num_assign) s_.params[a.first] = a.second;
    for (auto &a : b.named_assign) set_named(a.first, a.second);
    if (b.o_kind != O_NONE) execute_oword(b);
    else if (!b.o_fanuc) blocks.push_back(b);
}
