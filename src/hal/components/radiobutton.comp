component radiobutton "Momentary buttons select one of N channels (radio buttons)";
description "personality is the number of channels (at most 32; the default 0 makes none). The highest pressed button wins; channel 0 is selected at start.";
pin in bit sel-##[32 : personality] "Button of channel NN";
pin out bit out-##[32 : personality] "Channel NN is selected";
pin in float input-##[32 : personality] "Value of channel NN";
pin out s32 selected "Selected channel";
pin out float value "Value of the selected channel";
function _;
license "GPL";
author "OpenEMC";
;;
int s = selected;
(void)period;
for (int i = 0; i < personality && i < 32; i++)
    if (sel(i))
        selected = i;
for (int i = 0; i < personality && i < 32; i++) {
    out(i) = i == s;
    if (i == s)
        value = input(i);
}
