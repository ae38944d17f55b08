component threadtest "Count how often a function runs";
pin out u32 count "Number of calls of increment since the last reset";
function increment "Add one to count";
function reset "Set count to zero";
license "GPL";
author "OpenEMC";
;;
/* Add one to count. */
FUNCTION(increment) { count = count + 1; }

/* Set count to zero. */
FUNCTION(reset) { count = 0; }
