// remap_exec.cc: runs a remapped code: prolog, NGC or Python body, epilog, then the rest of its block.
#include "../interp.hh"

namespace {

// Remaps may nest this deep (LinuxCNC's limit).
constexpr size_t MAX_REMAP_LEVELS = 10;

} // namespace

// Start def's procedure for the code in b found at block step `step`; errors name the generated call line.
InterpStatus Interp::start_remap(const Block &b, const RemapDef &def, size_t step)
{
    INTERP_FRAME();
    std::string call_line = "O <" + def.proc() + "> call ";
    if (remap_stack_.size() >= MAX_REMAP_LEVELS)
        throw InterpErrorAt("Remapped codes nested more than " + std::to_string(MAX_REMAP_LEVELS) +
                            " levels deep (" + def.code + ")", call_line);
    RemapCall rc;
    rc.def = &def;
    rc.block = b;
    rc.resume_step = step;
    rc.call_line = call_line;
    std::vector<double> positional;
    try {
        if (def.needs_python()) python(("REMAP=" + def.code).c_str());
        remap_words(b, def, positional, rc.words, true);
    } catch (const InterpErrorAt &) {
        throw;
    } catch (const InterpError &e) {
        throw InterpErrorAt(e.what(), call_line);
    }
    remap_stack_.push_back(std::move(rc));
    push_remap_frame(remap_stack_.back(), positional, remap_stack_.back().words);
    RemapCall &top = remap_stack_.back();
    if (def.prolog.empty()) return remap_body();
    top.phase = REMAP_PROLOG;
    return remap_outcome(py_->call_remap(def.prolog, top.words), REMAP_PROLOG);
}

// Enter the procedure's call level (its arguments set) before the prolog runs; the NGC file is found after it.
void Interp::push_remap_frame(RemapCall &rc, const std::vector<double> &positional,
                              const std::map<std::string, double> &named)
{
    INTERP_FRAME();
    const RemapDef &def = *rc.def;
    bool at = def.argspec.find('@') != std::string::npos;
    push_call(SubDef{}, def.proc(), positional, false);
    calls_.back().python = def.ngc.empty();
    if (!at)
        for (const auto &kv : named) calls_.back().locals[kv.first] = kv.second;
    rc.frame = calls_.size() - 1;
}

// After the prolog: run the Python body, or let the NGC procedure's lines follow.
InterpStatus Interp::remap_body()
{
    INTERP_FRAME();
    RemapCall &rc = remap_stack_.back();
    if (!rc.def->python.empty()) {
        rc.phase = REMAP_BODY_PY;
        return remap_outcome(py_->call_remap(rc.def->python, rc.words), REMAP_BODY_PY);
    }
    SubDef sub;
    if (!lookup_sub(rc.def->ngc, sub))
        throw InterpErrorAt("Remap procedure " + rc.def->ngc + " for " + rc.def->code + " not found",
                            rc.call_line);
    CallFrame &f = calls_[rc.frame];
    f.file = sub.file;
    f.pos = sub.line + 1;
    f.sub_line = sub.line;
    rc.phase = REMAP_BODY_NGC;
    return INTERP_OK;
}

// The body is done (endsub/return of the NGC procedure, or the Python body returned): run the epilog.
InterpStatus Interp::remap_after_body()
{
    INTERP_FRAME();
    RemapCall &rc = remap_stack_.back();
    if (rc.def->epilog.empty()) return remap_complete();
    rc.phase = REMAP_EPILOG;
    python(("REMAP=" + rc.def->code).c_str());
    return remap_outcome(py_->call_remap(rc.def->epilog, rc.words), REMAP_EPILOG);
}

// Leave the procedure's call level and run the rest of the block that held the remapped code; a remapped
// G code stays the motion mode (axis words alone run it again).
InterpStatus Interp::remap_complete()
{
    INTERP_FRAME();
    RemapCall rc = std::move(remap_stack_.back());
    remap_stack_.pop_back();
    while (calls_.size() > rc.frame) pop_call();
    if (py_finish_request_) rc.block.execute_finish = true;
    py_finish_request_ = false;
    if (rc.def->letter == 'G') s_.motion_mode = rc.def->number;
    consume_remapped(rc.block, *rc.def);
    return execute_steps(rc.block, rc.resume_step);
}

// Act on what a prolog, Python body or epilog returned.
InterpStatus Interp::remap_outcome(const PyOutcome &o, RemapPhase phase)
{
    INTERP_FRAME();
    RemapCall &rc = remap_stack_.back();
    if (o.kind == PyOutcome::ERROR) {
        bool own_line = phase != REMAP_EPILOG || rc.def->ngc.empty();
        if (own_line) throw InterpErrorAt(o.error, rc.call_line);
        throw InterpError(o.error);
    }
    if (o.kind == PyOutcome::SUSPEND) {
        rc.generator = o.generator;
        return INTERP_EXECUTE_FINISH;
    }
    rc.generator.reset();
    if (phase == REMAP_PROLOG) return remap_body();
    if (phase == REMAP_BODY_PY) return remap_after_body();
    return remap_complete();
}

// True when a prolog, body or epilog waits (after yield INTERP_EXECUTE_FINISH) to be resumed.
bool Interp::remap_suspended() const
{
    return !remap_stack_.empty() && remap_stack_.back().generator;
}

// Resume the suspended Python function of the innermost remap.
InterpStatus Interp::resume_remap()
{
    INTERP_FRAME();
    RemapCall &rc = remap_stack_.back();
    PyGenerator gen = rc.generator;
    return remap_outcome(py_->resume(gen), rc.phase);
}

// True when the current call level is the NGC body of the innermost remap.
bool Interp::in_remap_frame() const
{
    return !remap_stack_.empty() && remap_stack_.back().phase == REMAP_BODY_NGC &&
           remap_stack_.back().frame == calls_.size() - 1;
}
