// block_steps.hh: one step of block execution (LinuxCNC's order of execution) and the remapped code it may run.
#ifndef OPENEMC_RS274NGC_BLOCK_STEPS_HH
#define OPENEMC_RS274NGC_BLOCK_STEPS_HH

class Interp;
struct Block;

// Which remapped code a step may hand over to its remap procedure.
enum RemapSlot { SLOT_NONE, SLOT_F, SLOT_S, SLOT_T, SLOT_M, SLOT_G };

// One step of block execution.
struct ExecStep {
    void (Interp::*run)(Block &b);  // the built-in behaviour
    RemapSlot slot;                 // remapped code this step may run instead
    int group;                      // modal group of that code (SLOT_M, SLOT_G)
};

// Makes a block the current one (Python's blocks[0]) for as long as it lives.
struct BlockScope {
    const Block *&slot;
    const Block *saved;
    BlockScope(const Block *&s, const Block *b) : slot(s), saved(s) { slot = b; }
    ~BlockScope() { slot = saved; }
    BlockScope(const BlockScope &) = delete;
    BlockScope &operator=(const BlockScope &) = delete;
};

#endif
