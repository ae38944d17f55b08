component dbounce "Integrating debounce of a bit input";
pin in bit in;
pin out bit out "Changes after in has held its new value for delay cycles";
pin in u32 delay = 5 "Cycles of agreement needed";
variable unsigned counter;
function _;
license "GPL";
author "OpenEMC";
;;
if (in) {
    if (counter < delay) counter++;
    if (counter >= delay) out = 1;
} else {
    if (counter > 0) counter--;
    if (counter == 0) out = 0;
}
