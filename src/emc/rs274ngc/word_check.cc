// word_check.cc: every letter word on a line needs a code that uses it (LinuxCNC's "A letter
// without a user"), one rule per letter.
#include "interp.hh"

namespace {

// The codes of a block that can use letter words (modal motion included).
struct WordUsers {
    int motion;         // explicit or modal group-1 code ×10
    int g0;             // group 0 code ×10 or -1
    int comp, tool_length, path, spindle_g;
    int io_m, spindle_m, override_m, user_m, tool_m;
    bool m98;
};

// true for G73, G74 and G81..G89
bool drill_cycle(int m) { return m == 730 || m == 740 || (m >= 810 && m <= 890); }
// true for G70, G71(.1 .2) and G72(.1 .2)
bool lathe_cycle(int m) { return m >= 700 && m <= 722; }
// true for G2 and G3
bool arc(int m) { return m == 20 || m == 30; }
// true for G5 and G5.1
bool cubic(int m) { return m == 50 || m == 51; }

bool uses_d(const WordUsers &u)
{
    return u.comp >= 410 || lathe_cycle(u.motion) || u.motion == 730 || u.motion == 830 ||
           u.spindle_g == 960 || u.motion == 760;
}

bool uses_e(const WordUsers &u)
{
    return u.motion == 760 || u.motion == 700 || u.io_m == 66 || u.io_m == 67 || u.io_m == 68;
}

bool uses_h(const WordUsers &u)
{
    return u.tool_length == 430 || u.tool_length == 432 || u.motion == 760;
}

bool uses_ij(const WordUsers &u)
{
    return arc(u.motion) || cubic(u.motion) || u.motion == 760 || u.motion == 870 ||
           u.g0 == 100 || u.motion == 331 || lathe_cycle(u.motion);
}

bool uses_k(const WordUsers &u)
{
    return arc(u.motion) || u.motion == 330 || u.motion == 331 || u.motion == 760 ||
           u.motion == 870;
}

bool uses_l(const WordUsers &u)
{
    return u.g0 == 100 || drill_cycle(u.motion) || u.motion == 760 || u.motion == 52 ||
           u.comp == 411 || u.comp == 421 || u.io_m == 66 || lathe_cycle(u.motion) || u.m98;
}

bool uses_p(const WordUsers &u)
{
    return arc(u.motion) || cubic(u.motion) || u.motion == 52 || u.g0 == 40 || u.g0 == 100 ||
           u.path == 640 || u.motion == 760 || drill_cycle(u.motion) || u.motion == 700 ||
           u.io_m != -1 || u.spindle_m == 19 || u.override_m >= 50 || u.user_m != -1 || u.m98;
}

bool uses_q(const WordUsers &u)
{
    return cubic(u.motion) || drill_cycle(u.motion) || u.motion == 760 || lathe_cycle(u.motion) ||
           u.path == 640 || u.g0 == 100 || u.io_m == 66 || u.io_m == 67 || u.io_m == 68 ||
           u.spindle_m == 19 || u.user_m != -1 || u.tool_m == 61;
}

bool uses_r(const WordUsers &u)
{
    return arc(u.motion) || drill_cycle(u.motion) || u.g0 == 100 || u.motion == 760 ||
           lathe_cycle(u.motion) || u.spindle_m == 19 || u.path == 640;
}

// One letter's rule and its message.
struct WordRule {
    char letter;
    bool (*used)(const WordUsers &);
    const char *message;
};

const WordRule WORD_RULES[] = {
    {'d', uses_d, "D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2 G73, G83 or G96 to use it"},
    {'e', uses_e, "E word with no G70, G76, M66, M67 or M68 to use it"},
    {'h', uses_h, "H word with no G43 or G76 to use it"},
    {'i', uses_ij, "I word with no G2, G3, G5, G5.1, G10, G33.1, G71, G72, G76 or G87 to use it"},
    {'j', uses_ij, "J word with no G2, G3, G5, G5.1, G10, G76 or G87 to use it"},
    {'k', uses_k, "K word with no G2, G3, G33, G33.1, G76 or G87 to use it"},
    {'l', uses_l, "L word with no G10, G76, cycle or M66 to use it"},
    {'p', uses_p, "P word with no G2, G3, G4, G5, G10, G64, G76, cycle, M19, M50-M53, M62-M68 or "
                  "user M code to use it"},
    {'q', uses_q, "Q word with no G5, G10, G64, G73, G76, G83, lathe cycle, M19, M61, M66-M68 or "
                  "user M code to use it"},
    {'r', uses_r, "R word with no g code that uses it"},
};

} // namespace

// Letters that need a code to use them (argspec words of remapped codes are used).
void Interp::check_words(Block &b)
{
    INTERP_FRAME();
    WordUsers u{b.g_modes[GG_MOTION] != -1 ? b.g_modes[GG_MOTION] : s_.motion_mode,
                b.g_modes[GG_NONMODAL], b.g_modes[GG_COMP], b.g_modes[GG_TOOL_LENGTH],
                b.g_modes[GG_PATH], b.g_modes[GG_SPINDLE], b.m_modes[MG_IO],
                b.m_modes[MG_SPINDLE], b.m_modes[MG_OVERRIDE], b.m_modes[MG_USER],
                b.m_modes[MG_TOOL], b.m98};
    for (const WordRule &r : WORD_RULES)
        if (b.word(r.letter) && !r.used(u) && !remap_uses_word(b, r.letter))
            throw InterpError(r.message);
    if (b.has_dollar && !uses_dollar(b, u.motion))
        throw InterpError("$ word with no M3, M4, M5, M19, M51, G33, G33.1, G74, G76, G84, G96, "
                          "G97 or S word to use it");
    if (b.word('r') && u.path == 640 && u.spindle_m == 19)
        throw InterpError("R word is ambiguous on a line with both G64 and M19 - use separate lines");
    if (u.g0 == 40 && arc(u.motion) && b.g_modes[GG_MOTION] != -1)
        throw InterpError("G4 not allowed with G2 or G3 because they both use P");
}

// True when a code of the block selects a spindle with '$'.
bool Interp::uses_dollar(const Block &b, int motion) const
{
    int sm = b.m_modes[MG_SPINDLE];
    return b.word('s') || sm == 3 || sm == 4 || sm == 5 || sm == 19 ||
           b.m_modes[MG_OVERRIDE] == 51 || motion == 330 || motion == 331 || motion == 740 ||
           motion == 760 || motion == 840 || b.g_modes[GG_SPINDLE] != -1;
}
