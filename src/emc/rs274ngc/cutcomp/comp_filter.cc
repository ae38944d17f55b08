// comp_filter.cc: deferring canon calls behind held compensated moves.
#include "comp_filter.hh"

namespace cutcomp {

// queue the call while a move is held, else run it now
void CompFilter::later(std::function<void(Canon &)> call)
{
    if (queue_.holding())
        queue_.push_call(std::move(call));
    else
        call(out_);
}

}  // namespace cutcomp
