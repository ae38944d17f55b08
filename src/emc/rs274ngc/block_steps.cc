// block_steps.cc: runs a block's items in the order of gcode.md §3; a remapped code's step calls its procedure.
#include "interp.hh"

// A step whose built-in behaviour needs nothing from the rest of the block.
template <void (Interp::*F)(Block &)>
StepResult Interp::step_plain(Block &b)
{
    (this->*F)(b);
    return STEP_CONTINUE;
}

// Step 2: the comment (and a ;py, statement).
StepResult Interp::step_comment(Block &b)
{
    if (b.has_comment) do_comment(b);
    if (!b.py_code.empty()) python_comment(b.py_code);
    return STEP_CONTINUE;
}

// M6 / M61: a queue buster.
StepResult Interp::step_tool_change(Block &b)
{
    return do_tool_change(b) ? STEP_FINISH : STEP_CONTINUE;
}

// Motion (probing is a queue buster).
StepResult Interp::step_motion(Block &b)
{
    return do_motion(b) ? STEP_FINISH : STEP_CONTINUE;
}

// M0 M1 M2 M30 M60 M99.
StepResult Interp::step_stop(Block &b)
{
    return do_stop(b) == INTERP_EXIT ? STEP_EXIT : STEP_CONTINUE;
}

// The steps in execution order, each with the remapped code it may run instead.
const StepDef *Interp::block_steps()
{
    static const StepDef steps[] = {
        {&Interp::step_comment, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_spindle_mode>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_feed_mode>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_feed_rate>, SLOT_F, 0},
        {&Interp::step_plain<&Interp::do_speed>, SLOT_S, 0},
        {&Interp::step_plain<&Interp::do_select_tool>, SLOT_T, 0},
        {&Interp::step_plain<&Interp::do_io>, SLOT_M, MG_IO},
        {&Interp::step_tool_change, SLOT_M, MG_TOOL},
        {&Interp::step_plain<&Interp::do_spindle>, SLOT_M, MG_SPINDLE},
        {&Interp::step_plain<&Interp::do_coolant>, SLOT_M, MG_COOLANT},
        {&Interp::step_plain<&Interp::do_overrides>, SLOT_M, MG_OVERRIDE},
        {&Interp::step_plain<&Interp::do_user_m>, SLOT_M, MG_USER},
        {&Interp::step_plain<&Interp::do_dwell>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_plane>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_units>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_lathe_mode>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_comp>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_tool_length>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_coord_system>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_path_control>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_distance>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_retract>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_nonmodal>, SLOT_NONE, 0},
        {&Interp::step_plain<&Interp::do_g92_family>, SLOT_NONE, 0},
        {&Interp::step_motion, SLOT_G, GG_MOTION},
        {&Interp::step_stop, SLOT_M, MG_STOP},
        {nullptr, SLOT_NONE, 0},
    };
    return steps;
}

// Run the steps of b from index first on; a remapped code suspends the block until its procedure returns.
InterpStatus Interp::run_steps(Block &b, int first, bool finish)
{
    INTERP_FRAME();
    BlockScope scope(current_block_, &b);
    const StepDef *steps = block_steps();
    for (int i = first; steps[i].run; i++) {
        const RemapDef *def = have_remaps_ && steps[i].slot != SLOT_NONE ? remap_due(b, steps[i]) : nullptr;
        if (def) return start_remap(b, *def, i, finish);
        StepResult r = (this->*steps[i].run)(b);
        if (r == STEP_EXIT) return INTERP_EXIT;
        if (r == STEP_FINISH) finish = true;
    }
    return finish ? INTERP_EXECUTE_FINISH : INTERP_OK;
}
