// interp_hooks.hh: entry points the cycles and cutter-comp engineers implement and the interpreter calls.
#ifndef OPENEMC_RS274NGC_INTERP_HOOKS_HH
#define OPENEMC_RS274NGC_INTERP_HOOKS_HH

#include <memory>
#include <string>
#include <vector>

#include "block.hh"
#include "canon.hh"
#include "interp_state.hh"

// Gives lathe cycles (G70-G72) the evaluated blocks of profile subroutine Q.
class ProfileSource {
public:
    virtual ~ProfileSource() = default;
    // blocks between "o<name> sub" and "o<name> endsub" (name as in the Q word, e.g. "100")
    virtual std::vector<Block> sub_blocks(const std::string &name) = 0;
};

namespace cycles {
// G73 G74 G81..G89: one canned-cycle block (motion code in s.motion_mode, words in b).
void execute(InterpState &s, const Block &b, Canon &canon) __attribute__((weak));
// G76 threading cycle for one block.
void execute_g76(InterpState &s, const Block &b, Canon &canon) __attribute__((weak));
// G70 G71 G71.1 G71.2 G72 G72.1 G72.2 lathe cycles.
void execute_lathe(InterpState &s, const Block &b, Canon &canon, ProfileSource &src)
    __attribute__((weak));
}

namespace cutcomp {
// Cutter radius compensation: a Canon filter in front of the real canon.
class Engine {
public:
    virtual ~Engine() = default;
    // the Canon the interpreter calls for everything while this engine exists
    virtual Canon &canon() = 0;
    // G41/G42/G41.1/G42.1 executed: s.comp_side, comp_radius, comp_orientation already set
    virtual void start(InterpState &s) = 0;
    // G40 executed: s.comp_side still holds the old side
    virtual void stop(InterpState &s) = 0;
    // emit every held move and queued call (M2, program end)
    virtual void flush() = 0;
    // drop everything held (interpreter reset / error)
    virtual void reset() = 0;
};
// create the engine for state s writing to out
std::unique_ptr<Engine> make_engine(InterpState &s, Canon &out) __attribute__((weak));
}

#endif
