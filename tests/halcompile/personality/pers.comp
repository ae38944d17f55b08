component pers "Personality-dependent pins";
pin in s32 in-##[8 : personality & 0xf] "Inputs, count from the low nibble";
pin out s32 sum if personality & 0x10 "Sum of the inputs";
pin out s32 product if personality & 0x20 "Product of the inputs";
param r s32 pers "This instance's personality";
option default_personality 0x12;
function _;
license "GPL";
;;
int i, s = 0, p = 1;
pers = personality;
for (i = 0; i < (personality & 0xf); i++) {
    s += in(i);
    p *= in(i);
}
if (personality & 0x10) sum = s;
if (personality & 0x20) product = p;
