// remap_args.cc: which remapped code a block step runs, and the argspec words passed to its procedure.
#include <cctype>

#include "../interp.hh"

namespace {

const char AXIS_LETTERS[] = "xyzabcuvw";

// group-0 codes that take the block's axis words for themselves
bool nonmodal_takes_axes(int g)
{
    return g == 100 || g == 280 || g == 300 || g == 520 || g == 920;
}

// true when the block has axis (or polar) words
bool has_axis_words(const Block &b)
{
    for (const char *c = AXIS_LETTERS; *c; c++)
        if (b.word(*c)) return true;
    return b.has_polar_radius || b.has_polar_angle;
}

// the motion code a block hands to a remap: explicit, or the modal one continued by axis words
int block_motion_code(const Block &b, int modal)
{
    if (b.motion() != -1) return b.motion();
    int tl = b.g_modes[GG_TOOL_LENGTH];
    if (nonmodal_takes_axes(b.g_modes[GG_NONMODAL]) || tl == 431 || tl == 432) return -1;
    return has_axis_words(b) ? modal : -1;
}

} // namespace

// True while def's procedure is running (then its code means the built-in one, or is an error).
bool Interp::remap_active(const RemapDef *def) const
{
    for (const RemapCall &rc : remap_stack_)
        if (rc.def == def) return true;
    return false;
}

// The remap this step of b runs instead of its built-in behaviour, or nullptr.
const RemapDef *Interp::remap_due(const Block &b, const ExecStep &step) const
{
    const RemapDef *def = nullptr;
    if (step.slot == SLOT_NONE || !have_remaps_) return nullptr;
    if (step.slot == SLOT_F || step.slot == SLOT_S || step.slot == SLOT_T) {
        char c = step.slot == SLOT_F ? 'f' : step.slot == SLOT_S ? 's' : 't';
        def = b.word(c) ? letter_remap(c) : nullptr;
    } else if (step.slot == SLOT_M && b.m_modes[step.group] != -1) {
        auto it = m_remaps_.find(b.m_modes[step.group]);
        if (it != m_remaps_.end() && it->second.group == step.group) def = &it->second;
    } else if (step.slot == SLOT_G) {
        auto it = g_remaps_.find(block_motion_code(b, s_.motion_mode));
        if (it != g_remaps_.end()) def = &it->second;
    }
    if (!def || !remap_active(def)) return def;
    if (def->builtin) return nullptr;
    throw InterpError("Remapped code " + def->code + " used inside its own remap procedure");
}

// Collect def's argspec words from b: positional (with '@') or named; missing required words are an error,
// and with check_state the '^' (spindle turning) and '>' (feed set) conditions of the moment it runs.
void Interp::remap_words(const Block &b, const RemapDef &def, std::vector<double> &positional,
                         std::map<std::string, double> &named, bool check_state) const
{
    bool at = def.argspec.find('@') != std::string::npos;
    std::string missing;
    for (char c : def.argspec) {
        char lc = (char)tolower((unsigned char)c);
        if (c == '@') continue;
        if (c == '^' && check_state && s_.speed[0] <= 0)
            throw InterpError(def.code + ": spindle speed must be greater than 0");
        if (c == '>' && check_state && s_.feed_rate <= 0)
            throw InterpError(def.code + ": feed rate must be greater than 0");
        if (c == '^' || c == '>') continue;
        if (lc == 'n') {
            named["n"] = b.has_line_number ? b.line_number : (double)s_.sequence_number;
            continue;
        }
        if (!b.word(lc)) {
            if (isupper((unsigned char)c)) missing += c;
            continue;
        }
        if (at)
            positional.push_back(b.value(lc));
        named[std::string(1, lc)] = b.value(lc);
    }
    if (!missing.empty()) throw InterpError("user-defined " + def.code + ": missing: " + missing);
}

// Before anything on the line runs: every remapped code of b must have its required words.
void Interp::check_remap_args(const Block &b)
{
    INTERP_FRAME();
    if (!have_remaps_) return;
    size_t count;
    const ExecStep *steps = exec_steps(count);
    for (size_t i = 0; i < count; i++) {
        const RemapDef *def = remap_due(b, steps[i]);
        if (!def) continue;
        std::vector<double> positional;
        std::map<std::string, double> named;
        try {
            remap_words(b, *def, positional, named, false);
        } catch (const InterpErrorAt &) {
            throw;
        } catch (const InterpError &e) {
            throw InterpErrorAt(e.what(), "O <" + def->proc() + "> call ");
        }
    }
}

// True when word letter c ('a'..'z') is an argument of a remapped code of the block (so it is used).
bool Interp::remap_uses_word(const Block &b, char c) const
{
    if (!have_remaps_) return false;
    size_t count;
    const ExecStep *steps = exec_steps(count);
    for (size_t i = 0; i < count; i++) {
        const RemapDef *def = remap_due(b, steps[i]);
        if (!def) continue;
        for (char a : def->argspec)
            if (isalpha((unsigned char)a) && tolower((unsigned char)a) == c) return true;
    }
    return false;
}

// Remove the remapped code from the block so the step's built-in behaviour leaves it alone.
void Interp::consume_remapped(Block &b, const RemapDef &def) const
{
    if (def.number < 0) {
        b.has[tolower((unsigned char)def.letter) - 'a'] = false;
        return;
    }
    if (def.letter == 'M') {
        b.m_modes[def.group] = -1;
        b.m_count--;
        return;
    }
    b.g_modes[GG_MOTION] = -1;
    for (const char *c = AXIS_LETTERS; *c; c++) b.has[*c - 'a'] = false;
    b.has_polar_radius = b.has_polar_angle = false;
}
