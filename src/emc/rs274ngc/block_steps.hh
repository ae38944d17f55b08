// block_steps.hh: the execution order of a block's items (gcode.md §3) as a table, with the remap slot of each step.
#ifndef OPENEMC_RS274NGC_BLOCK_STEPS_HH
#define OPENEMC_RS274NGC_BLOCK_STEPS_HH

class Interp;
struct Block;

// What one step asks of the rest of the block.
enum StepResult { STEP_CONTINUE, STEP_FINISH, STEP_EXIT };

// Which remapped code a step may hand over to its remap procedure.
enum RemapSlot { SLOT_NONE, SLOT_F, SLOT_S, SLOT_T, SLOT_M, SLOT_G };

// One step of block execution.
struct StepDef {
    StepResult (Interp::*run)(Block &b);  // the built-in behaviour
    RemapSlot slot;                       // remapped code this step may run instead
    int group;                            // modal group of that code (SLOT_M, SLOT_G)
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
