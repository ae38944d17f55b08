// script_block.hh: parse a test-script line of letter words ("g81 x1 y2 z-1 r1") into a Block.
#ifndef OPENEMC_TESTS_SCRIPT_BLOCK_HH
#define OPENEMC_TESTS_SCRIPT_BLOCK_HH

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "emc/rs274ngc/block.hh"

// The words of one script line: G codes ×10 and M codes in order, other letters in the Block.
struct ScriptLine {
    Block block;
    std::vector<int> g;   // G codes ×10
    std::vector<int> m;   // M codes
};

// split "g81x1 y-2.5" into words; letters other than g/m go into the block
inline ScriptLine parse_script_line(const std::string &text)
{
    ScriptLine out;
    size_t i = 0;
    while (i < text.size()) {
        char c = (char)std::tolower((unsigned char)text[i]);
        if (!std::isalpha((unsigned char)c)) {
            i++;
            continue;
        }
        char *end = nullptr;
        double v = std::strtod(text.c_str() + i + 1, &end);
        i = (size_t)(end - text.c_str());
        if (c == 'g')
            out.g.push_back((int)std::lround(v * 10));
        else if (c == 'm')
            out.m.push_back((int)std::lround(v));
        else {
            out.block.has[c - 'a'] = true;
            out.block.val[c - 'a'] = v;
        }
    }
    return out;
}

#endif
