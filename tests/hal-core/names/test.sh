#!/bin/bash
# names: HAL refuses empty names, names with white space or control characters and names
# ending in '.', for components, pins, params, signals and aliases (Python API and halcmd).
realtime start 2> /dev/null || exit 1
trap 'realtime stop' EXIT
python3 - <<'PY' 2>&1
import hal

def attempt(what, fn, *args):
    """Print whether HAL accepted the call."""
    try:
        fn(*args)
        print("accepted", what, repr(args))
    except Exception as e:
        print("refused ", what, repr(args), type(e).__name__)

for name in ["", "a b", "tab\tname", "new\nline", "ends."]:
    attempt("component", hal.component, name)
c = hal.component("names")
for name in ["", "x y", "bell\a", "ok"]:
    attempt("pin", c.newpin, name, hal.HAL_BIT, hal.HAL_IN)
for name in ["", "p q", "okp"]:
    attempt("param", c.newparam, name, hal.HAL_FLOAT, hal.HAL_RW)
c.ready()
# new_sig reports failure by returning True, as LinuxCNC's does
for name in ["", "s t", "ok.s"]:
    print("new_sig", repr(name), "failed" if hal.new_sig(name, hal.HAL_BIT) else "created")
PY
halcmd newsig 'with"quote' bit 2>&1; echo "exit $?"
halcmd loadrt and2 count=1
halcmd alias pin and2.0.in0 'al ias' 2>&1; echo "exit $?"
halcmd alias pin and2.0.in0 'alias.' 2>&1; echo "exit $?"
halcmd alias pin and2.0.in0 alias.ok 2>&1; echo "exit $?"
halcmd list pin and2; halcmd list sig
