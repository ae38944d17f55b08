component pushmsg "Print configured messages, with pin values in them, when trigger pins change";
modparam dummy msgs "Up to 64 entries level|name|text, comma-separated; level e, w, i or d (error, warning, info, debug)";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Each entry makes the bit inputs pushmsg.NAME.trigger, pushmsg.NAME.force and
pushmsg.NAME.edge. Up to two placeholders {t:ref} in the text make input pins
pushmsg.NAME.ref of type t (b bit, s s32, u u32, l s64, k u64, f float) whose values
replace them when printed; a backslash makes the next character plain (the backslash is
printed).

The function pushmsg prints an entry when trigger XOR edge rises while pushmsg.enable is
TRUE (the default), or when force rises. Entries that are too long (128 characters or
more), too short, have a bad level letter, miss a separator, or name pins badly fail the
load with a message naming the entry.""";
