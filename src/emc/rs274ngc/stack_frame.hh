// stack_frame.hh: records the interpreter functions an error unwinds through (rs274 -s prints them).
#ifndef OPENEMC_RS274NGC_STACK_FRAME_HH
#define OPENEMC_RS274NGC_STACK_FRAME_HH

#include <exception>
#include <string>
#include <vector>

#include "interp_state.hh"

// Most frames one error records.
constexpr size_t STACK_FRAME_MAX = 64;

// Appends its function's signature to `stack` when an exception unwinds it (innermost first).
// An exception in flight while the frame is destroyed means unwinding, so there is no
// process-wide state. Only the destructor reads the counter: interpreter functions never run
// from a destructor during unwinding, so no frame starts with an exception already in flight,
// and the normal path costs one counter read per call.
class StackFrame {
public:
    // remember where to record
    StackFrame(std::vector<std::string> &stack, const char *signature)
        : stack_(stack), signature_(signature) {}
    // record the signature when an exception is unwinding through this frame
    ~StackFrame()
    {
        if (std::uncaught_exceptions() > 0 && stack_.size() < STACK_FRAME_MAX)
            stack_.emplace_back(signature_);
    }
    StackFrame(const StackFrame &) = delete;
    StackFrame &operator=(const StackFrame &) = delete;

private:
    std::vector<std::string> &stack_;
    const char *signature_;
};

// Declares the frame of the enclosing Interp member function.
#define INTERP_FRAME() StackFrame interp_frame_(error_stack_, __PRETTY_FUNCTION__)

#endif
