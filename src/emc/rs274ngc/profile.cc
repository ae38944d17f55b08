// profile.cc: ProfileSource for lathe cycles: the evaluated blocks of a subroutine body.
#include "interp.hh"

// Parse every line of subroutine `name` (between its sub and endsub lines) into blocks.
std::vector<Block> Interp::sub_blocks(const std::string &name)
{
    INTERP_FRAME();
    SubDef def;
    if (!lookup_sub(name, def))
        throw InterpError("Unable to find profile subroutine o" + name);
    std::vector<Block> blocks;
    std::string n;
    OKind k;
    for (size_t i = def.line + 1; i < def.file->lines.size(); i++) {
        const std::string &line = def.file->lines[i];
        if (peek_oword(line, n, k)) {
            if (n == name && (k == O_ENDSUB || k == O_RETURN)) return blocks;
            continue;
        }
        Block b;
        parse_line(line, b);
        blocks.push_back(b);
    }
    throw InterpError("Profile subroutine o" + name + " has no endsub");
}
